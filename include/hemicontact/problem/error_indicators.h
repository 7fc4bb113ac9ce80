#pragma once

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/problem/contact_problem.h>

namespace hemicontact
{
  /**
   * The cell-wise refinement indicator of @p problem's current state, by
   * 'adaptivity/indicator': Kelly, Kelly with the jumps of the contact
   * traction, the residual estimate or the estimate in the energy norm
   * (adaptivity.cc).
   */
  template <int dim>
  Vector<float>
  refinement_indicators(const ContactProblem<dim> &problem);

  /**
   * The 'residual' indicator: the cells' parts of
   * ContactProblem::error_estimate() with the contact term weighted by
   * 'adaptivity/contact weight' (residual_indicator.cc).
   */
  template <int dim>
  Vector<float>
  residual_indicators(const ContactProblem<dim> &problem);

  /**
   * The time part of the error estimate (doc/theory.md 12.4): the energy
   * norm of w_n - @p w_before (time_indicator.cc).
   */
  template <int dim>
  double
  time_indicator(const ProblemState<dim>             &state,
                 const TrilinosWrappers::MPI::Vector &w_before);
} // namespace hemicontact
