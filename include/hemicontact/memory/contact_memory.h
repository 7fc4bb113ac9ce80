#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/memory/normal_memory_kernel.h>
#include <hemicontact/model/contact_node.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The history of the memory term of the normal response (doc/theory.md,
   * section 11.9), a part of MemoryHistory: at each contact node x_i
   *
   *   N_{n,i} = sum_{j<n} k_j b(t_n - t_j) (u_nu,j(x_i))_+,
   *
   * the known pressure that -sigma_nu gains in the step on
   * [t_{n-1}, t_n]: the step's right-hand side loses m_i N_i nu_i.
   *
   * A node's history value is held at the degree of freedom of its first
   * component in vectors of the displacement's layout, so that checkpoints
   * save it as they save the displacement. A Prony series keeps one such
   * vector per term, h_n = e^{-k_n/tau} (h_{n-1} + k_n (u_nu,n-1)_+); an
   * expression kernel keeps every past (u_nu,j)_+ with t_j and k_j.
   *
   * With measure_slip(), also the slip s_tau accumulated up to the state
   * before the step (section 11.10), a variable of the friction bound: in
   * the static class S_n = sum_{j=1}^{n-1} |u_tau,j - u_tau,j-1|, in the
   * velocity classes S_n = sum_{j=1}^{n-1} k_j |w_tau,j|.
   *
   * With a wear coefficient k_w > 0, also the wear depth (section 11.12)
   * up to the state before the step: omega_n = k_w sum_{j=1}^{n-1} p_j
   * |u_tau,j - u_tau,j-1 - k_j v*_tau| in the static class, k_w
   * sum_{j=1}^{n-1} k_j p_j |w_tau,j - v*_tau| in the velocity classes,
   * p_j = (-sigma_nu)_+ the contact pressure of state j.
   */
  template <int dim>
  class ContactMemory
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /**
     * The kernel of @p parameters ('data/constants' @p constants) and the
     * wear of @p wear.
     */
    ContactMemory(const NormalMemoryParameters &parameters,
                  const WearParameters         &wear,
                  const std::string            &constants,
                  MPI_Comm                      comm);

    /** Whether the normal response, the slip or the wear has a history. */
    bool
    active() const
    {
      return normal_active() || slip_measured || wear_active();
    }

    /** Whether the foundation wears ('wear/wear coefficient' > 0). */
    bool
    wear_active() const
    {
      return wear_coefficient > 0;
    }

    /**
     * The slip and the wear are of the displacement (@p of_displacement,
     * the static class) or of the velocity. Before reinit().
     */
    void
    set_static_class(const bool of_displacement)
    {
      slip_from_displacement = of_displacement;
    }

    /** Whether 'normal memory/kernel' is not none. */
    bool
    normal_active() const
    {
      return kernel.type() != RelaxationKernelType::none;
    }

    /**
     * Accumulate the slip: of the displacement (@p of_displacement, the
     * static class) or of the velocity. Before reinit().
     */
    void
    measure_slip(const bool of_displacement)
    {
      slip_measured = true;
      set_static_class(of_displacement);
    }

    /** Whether the slip is accumulated. */
    bool
    slip_active() const
    {
      return slip_measured;
    }

    /**
     * The accumulated slip s_tau of each owned contact node at its first
     * degree of freedom, up to the state before the step (zero elsewhere).
     */
    const VectorType &
    slip() const
    {
      return accumulated_slip;
    }

    /**
     * The wear depth omega of each owned contact node at its first degree
     * of freedom, up to the state before the step (zero elsewhere).
     */
    const VectorType &
    wear() const
    {
      return wear_depth;
    }

    const NormalMemoryKernel &
    get_kernel() const
    {
      return kernel;
    }

    /** The owned nodes of @p nodes and an empty history. */
    void
    reinit(const std::vector<ContactNode<dim>> &nodes, const IndexSet &owned);

    /** Forget every past state. */
    void
    clear();

    /**
     * N of the step on [@p start, @p start + @p k] from the history and
     * @p u_start, the displacement at @p start, the state the step adds.
     */
    void
    prepare_step(const double start, const double k, const VectorType &u_start);

    /**
     * The step prepared last converged with the unknown @p unknown (u_n in
     * the static class, w_n otherwise) and the nodal traction -sigma nu
     * @p traction: its state joins the history, its slip the accumulated
     * slip and its wear the wear depth.
     */
    void
    commit_step(const VectorType *unknown, const VectorType *traction);

    /** @p functional += m_i N_i nu_i at the owned contact nodes. */
    void
    add_functional(VectorType &functional) const;

    /**
     * N_i nu_i at the owned contact nodes' degrees of freedom, zero
     * elsewhere: the part of the nodal traction -sigma nu that the memory
     * adds, of the step prepared last (zero before the first step).
     */
    const VectorType &
    pressure() const
    {
      return memory_pressure;
    }

    /** @name Checkpoints, as MemoryHistory's */
    /** @{ */
    std::vector<double>
    saved_values() const;
    std::vector<const VectorType *>
    saved_fields() const;
    std::vector<VectorType *>
    restore(const std::vector<double> &values);
    /** @} */

    /** Bytes held by the vectors. */
    std::size_t
    memory_consumption() const;

  private:
    /** What the memory needs of a contact node. */
    struct Node
    {
      std::array<types::global_dof_index, dim> dofs;
      Tensor<1, dim>                           normal;
      double                                   mass;
    };

    NormalMemoryKernel kernel;
    MPI_Comm           comm;
    IndexSet           owned_dofs;
    std::vector<Node>  nodes;

    /** Prony: h_{n-1} of each term, and h_n of the step prepared. */
    std::vector<VectorType> terms;
    std::vector<VectorType> trial_terms;

    /** Expression: t_j, k_j and (u_nu,j)_+ of every state j < n - 1 ... */
    std::vector<double>     past_times;
    std::vector<double>     past_steps;
    std::vector<VectorType> past_states;
    /** ... and the state the step prepared adds. */
    double     pending_time = 0;
    double     pending_step = 0;
    VectorType pending_state;

    /** N_i nu_i of the step prepared last. */
    VectorType memory_pressure;
    bool       prepared = false;

    /** The accumulated slip, and u at the start of the static step. */
    bool       slip_measured          = false;
    bool       slip_from_displacement = false;
    VectorType accumulated_slip;
    VectorType slip_start;

    /** k_w, v*, and the wear depth omega. */
    double         wear_coefficient = 0;
    Tensor<1, dim> foundation_velocity;
    VectorType     wear_depth;
  };
} // namespace hemicontact
