#pragma once

#include <deal.II/base/timer.h>

#include <hemicontact/problem/problem_state.h>
#include <hemicontact/solver/step_preconditioner.h>

namespace hemicontact
{
  /**
   * The time-step limits of the state's mesh and time step k: that of the
   * left-point rule (doc/theory.md 9.6; stability.cc), that of the memory
   * rule (doc/theory.md 11.13; memory_stability_check.cc) and that of the
   * staggered thermal coupling (doc/theory.md 13.2;
   * coupling_stability_check.cc). Above a limit:
   * InputError, or with 'time/allow unstable time step' a warning. Returns
   * whether k is above the memory rule's limit. The AMGs of the estimates
   * come from @p preconditioner; the time goes to @p timer's "stability
   * check".
   */
  template <int dim>
  bool
  check_time_step_limits(const ProblemState<dim> &state,
                         StepPreconditioner<dim> &preconditioner,
                         TimerOutput             &timer);

  /**
   * The memory rule's part of check_time_step_limits(): whether k is above
   * its limit (memory_stability_check.cc).
   */
  template <int dim>
  bool
  check_memory_stability(const ProblemState<dim> &state,
                         StepPreconditioner<dim> &preconditioner,
                         TimerOutput             &timer);

  /**
   * The limit of a staggered coupling (the temperature's,
   * CoupledFields::staggered_coupling()) with the implicit rule
   * (coupling_stability_check.cc); with the left-point rule it is part of
   * that rule's check.
   */
  template <int dim>
  void
  check_coupling_stability(const ProblemState<dim> &state, TimerOutput &timer);
} // namespace hemicontact
