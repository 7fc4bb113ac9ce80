#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/problem/problem_state.h>
#include <hemicontact/solver/linear_solver.h>
#include <hemicontact/solver/step_preconditioner.h>

namespace hemicontact
{
  /**
   * @name 'adaptivity/state transfer = projection' (state_projection.cc)
   */
  /** @{ */
  /**
   * Attach to the cells flagged for coarsening in @p state's mesh the
   * functionals rho M w and B u_next of their parents; returns the handle
   * for project_transferred_state(). Before the mesh changes.
   */
  template <int dim>
  unsigned int
  attach_coarsened_functionals(const ProblemState<dim>             &state,
                               const TrilinosWrappers::MPI::Vector &w,
                               const TrilinosWrappers::MPI::Vector &u_next);

  /**
   * On the new mesh of @p state: @p w and @p u_next (the interpolated
   * fields, before their hanging-node values are distributed) replaced by
   * the solutions of M w = (rho M w)_old and B u_next = (B u_next)_old,
   * with the functionals of @p handle on coarsened cells.
   */
  template <int dim>
  void
  project_transferred_state(const ProblemState<dim>       &state,
                            LinearSolver                  &linear_solver,
                            StepPreconditioner<dim>       &preconditioner,
                            const unsigned int             handle,
                            TrilinosWrappers::MPI::Vector &w,
                            TrilinosWrappers::MPI::Vector &u_next);
  /** @} */
} // namespace hemicontact
