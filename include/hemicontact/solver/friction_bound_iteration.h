#pragma once

#include <hemicontact/input/parameters.h>
#include <hemicontact/solver/step_statistics.h>

#include <functional>

namespace hemicontact
{
  /**
   * The fixed point of doc/theory.md, sections 9.8 and 9.9: @p update_bounds
   * evaluates the bounds at the step's current solution and returns their
   * relative change, @p solve solves the step again with them frozen; until
   * the change is below 'friction bound tolerance'. The iterations and the
   * extra Newton and Krylov iterations are added to @p stats. A bound that
   * has not settled within 'friction bound iterations', or whose change
   * grows three times in a row, fails the step (SolverFailure).
   */
  void
  iterate_friction_bound(const std::function<double()>         &update_bounds,
                         const std::function<StepStatistics()> &solve,
                         const NonlinearSolverParameters       &settings,
                         StepStatistics                        &stats);
} // namespace hemicontact
