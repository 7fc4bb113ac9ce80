#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/memory/convolution_history.h>
#include <hemicontact/memory/normal_memory_kernel.h>
#include <hemicontact/memory/slip_accumulator.h>
#include <hemicontact/model/contact_node.h>

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
   * save it as they save the displacement: a ConvolutionHistory of the
   * states (u_nu,j)_+, updated at those degrees of freedom only.
   *
   * With measure_slip(), also the slip s_tau accumulated up to the state
   * before the step (section 11.10), a variable of the friction bound; with
   * a wear coefficient k_w > 0, also the wear depth (section 11.12) up to
   * the state before the step: each a SlipAccumulator.
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
      return normal_active() || slip_active() || wear_active();
    }

    /** Whether the foundation wears ('wear/wear coefficient' > 0). */
    bool
    wear_active() const
    {
      return wear_sum.active();
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
      return history.active();
    }

    /**
     * Accumulate the slip: of the displacement (@p of_displacement, the
     * static class) or of the velocity. Before reinit().
     */
    void
    measure_slip(const bool of_displacement)
    {
      slip_sum = SlipAccumulator<dim>(1., Tensor<1, dim>(), false, comm);
      set_static_class(of_displacement);
    }

    /** Whether the slip is accumulated. */
    bool
    slip_active() const
    {
      return slip_sum.active();
    }

    /**
     * The accumulated slip s_tau of each owned contact node at its first
     * degree of freedom, up to the state before the step (zero elsewhere).
     */
    const VectorType &
    slip() const
    {
      return slip_sum.value();
    }

    /**
     * The wear depth omega of each owned contact node at its first degree
     * of freedom, up to the state before the step (zero elsewhere).
     */
    const VectorType &
    wear() const
    {
      return wear_sum.value();
    }

    const NormalMemoryKernel &
    get_kernel() const
    {
      return history.get_kernel();
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
    using Node = MemoryNode<dim>;

    MPI_Comm          comm;
    IndexSet          owned_dofs;
    std::vector<Node> nodes;

    /** The history of the (u_nu,j)_+. */
    ConvolutionHistory<NormalMemoryKernel> history;

    /** N_i nu_i of the step prepared last, and its length. */
    VectorType memory_pressure;
    double     pending_step = 0;
    bool       prepared     = false;

    /** The accumulated slip (none before measure_slip()) and the wear. */
    SlipAccumulator<dim> slip_sum;
    SlipAccumulator<dim> wear_sum;
    /** Whether in the static class, and u at the start of its step. */
    bool       slip_from_displacement = false;
    VectorType slip_start;
  };
} // namespace hemicontact
