#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/memory/contact_memory.h>
#include <hemicontact/memory/convolution_history.h>
#include <hemicontact/memory/relaxation_kernel.h>
#include <hemicontact/model/contact_node.h>

#include <cstddef>
#include <string>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The history of the memory term of the stress (doc/theory.md, section
   * 11), its only owner: the step on [t_{n-1}, t_n] gets the functional
   * m_n(v) = (M_n, eps(v)) of
   *
   *   M_n = sum_{j<n} k_j R(t_n - t_j) eps(u_j),   k_j = t_{j+1} - t_j,
   *
   * u_j the displacement the scheme holds at t_j, and subtracts it from its
   * right-hand side; the step matrix, the Newton method and the laws do
   * not see it. Since R is isotropic and constant in space,
   * m_n = A_mu S_mu + A_lambda S_lambda with the matrices of
   * a_mu(u, v) = 2 (eps(u), eps(v)) and a_lambda(u, v) = (div u, div v) and
   * the nodal vectors S_mu = sum_j k_j mu_R(t_n - t_j) u_j, S_lambda the
   * same with lambda_R.
   *
   * The sums are those of a ConvolutionHistory of the states u_j.
   * prepare_step() forms m_n without changing the history, commit_step()
   * adds the step to it after the step converged: a failed step (and its
   * halves) needs no undo.
   *
   * It also owns the memory of the contact conditions, a ContactMemory
   * (section 11.9): the memory pressure N_i of each contact node, whose
   * nodal forces m_i N_i nu_i join m_n, and which add_pressure() adds to
   * the nodal contact traction of a solve.
   */
  template <int dim>
  class MemoryHistory
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /** The kernel of @p parameters ('data/constants' @p constants). */
    MemoryHistory(const RelaxationParameters &parameters,
                  const std::string          &constants,
                  MPI_Comm                    comm);

    /**
     * ... and the memory of the normal response of @p normal and the wear
     * of @p wear.
     */
    MemoryHistory(const RelaxationParameters   &parameters,
                  const NormalMemoryParameters &normal,
                  const WearParameters         &wear,
                  const std::string            &constants,
                  MPI_Comm                      comm);

    /** Whether the stress or the contact conditions have memory. */
    bool
    active() const
    {
      return stress_active() || contact.active();
    }

    /** Whether the stress has a memory term ('relaxation/kernel' not none). */
    bool
    stress_active() const
    {
      return history.active();
    }

    /** The memory of the contact conditions. */
    const ContactMemory<dim> &
    contact_memory() const
    {
      return contact;
    }

    /**
     * @p traction += N_i nu_i at the owned contact nodes: the nodal
     * traction -(K w - b)_i / m_i of a solve, the laws' part, made the
     * traction -sigma nu (section 11.9).
     */
    void
    add_pressure(VectorType &traction) const
    {
      if (contact.normal_active())
        traction += contact.pressure();
    }

    /** @p traction -= N_i nu_i: the laws' part of a traction -sigma nu. */
    void
    subtract_pressure(VectorType &traction) const
    {
      if (contact.normal_active())
        traction -= contact.pressure();
    }

    const RelaxationKernel &
    get_kernel() const
    {
      return history.get_kernel();
    }

    /**
     * The matrices A_mu and A_lambda on the mesh of @p dof_handler,
     * condensed with @p constraints as the step matrix is, the contact
     * nodes @p contact_nodes, and an empty history. Nothing without memory.
     */
    void
    reinit(const DoFHandler<dim>               &dof_handler,
           const Mapping<dim>                  &mapping,
           const Quadrature<dim>               &quadrature,
           const AffineConstraints<double>     &constraints,
           const IndexSet                      &owned,
           const IndexSet                      &relevant,
           const std::vector<ContactNode<dim>> &contact_nodes = {});

    /** Forget every past state (a run starting at t = 0). */
    void
    clear();

    /**
     * The memory functional m of the step on [@p start, @p start + @p k]
     * from the history and @p u_start, the displacement at @p start, the
     * state the step adds to the history once it converged.
     */
    void
    prepare_step(const double start, const double k, const VectorType &u_start);

    /** @p rhs -= m of the step prepared last. */
    void
    subtract_from(VectorType &rhs) const
    {
      rhs -= functional;
    }

    /**
     * m = A_mu S_mu + A_lambda S_lambda + sum_i m_i N_i nu_i of the step
     * prepared last.
     */
    const VectorType &
    step_functional() const
    {
      return functional;
    }

    /**
     * The step prepared last converged: its state joins the history, and
     * with an accumulated slip that of @p unknown (u_n in the static class,
     * w_n otherwise), with wear that of @p unknown under the nodal traction
     * -sigma nu @p traction.
     */
    void
    commit_step(const VectorType *unknown  = nullptr,
                const VectorType *traction = nullptr);

    /**
     * Accumulate the slip of the contact nodes for the friction bound
     * (section 11.10): of the displacement (@p of_displacement, the static
     * class) or of the velocity. Before reinit().
     */
    void
    measure_slip(const bool of_displacement)
    {
      contact.measure_slip(of_displacement);
    }

    /**
     * The wear (section 11.12) is of the displacement (@p of_displacement,
     * the static class) or of the velocity. Before reinit().
     */
    void
    set_static_class(const bool of_displacement)
    {
      contact.set_static_class(of_displacement);
    }

    /**
     * The cell averages of the memory stress M_n = 2 eps(S_mu) +
     * div(S_lambda) I of the step prepared last (zero before the first
     * step), the components xx, xy, (xz,) yy, ... as the field output
     * names them; owned cells only.
     */
    std::vector<Vector<float>>
    cell_stress(const DoFHandler<dim> &dof_handler,
                const Mapping<dim>    &mapping,
                const Quadrature<dim> &quadrature) const;

    /** @name Checkpoints */
    /** @{ */
    /** The numbers of the history: its size and, for an expression, t_j, k_j.
     */
    std::vector<double>
    saved_values() const;
    /** The vectors of the history: one per Prony term or per past state. */
    std::vector<const VectorType *>
    saved_fields() const;
    /**
     * A history of the size @p values record (from saved_values()), with
     * its t_j and k_j; the vectors to read its fields into.
     */
    std::vector<VectorType *>
    restore(const std::vector<double> &values);
    /** @} */

    /** Bytes held: the two matrices and the vectors. */
    std::size_t
    memory_consumption() const;

  private:
    ConvolutionHistory<RelaxationKernel> history;
    ContactMemory<dim>                   contact;
    MPI_Comm                             comm;
    IndexSet                             owned_dofs;
    IndexSet                             relevant_dofs;

    /** A_mu and A_lambda. */
    TrilinosWrappers::SparseMatrix shear_matrix;
    TrilinosWrappers::SparseMatrix volumetric_matrix;

    /** S_mu, S_lambda and m of the step prepared last. */
    VectorType shear_sum;
    VectorType volumetric_sum;
    VectorType functional;
    bool       prepared = false;
  };
} // namespace hemicontact
