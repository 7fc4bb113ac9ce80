#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/problem/problem_state.h>

#include <utility>

namespace hemicontact
{
  /**
   * @name The state against the wall of the normal law (doc/theory.md 10.2;
   * wall_admissibility.cc)
   */
  /** @{ */
  /**
   * Throw InputError if the initial state starts beyond the wall, or if the
   * left-point rule carries it beyond in the first step.
   */
  template <int dim>
  void
  require_admissible_initial_state(const ProblemState<dim> &state);

  /**
   * Move the contact nodes of @p displacement (the state's u_n) that a
   * transfer carried beyond the wall g + omega back onto it; returns the
   * number of nodes moved and the largest move.
   */
  template <int dim>
  std::pair<unsigned int, double>
  move_state_onto_wall(const ProblemState<dim>       &state,
                       TrilinosWrappers::MPI::Vector &displacement);
  /** @} */
} // namespace hemicontact
