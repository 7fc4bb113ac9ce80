#pragma once

#include <functional>

namespace hemicontact
{
  /**
   * The damping factor of a Newton step by backtracking on the step energy:
   * theta = 1, 1/2, 1/4, ... down to @p min_step_length, given
   * @p energy_change(theta) = J(w + theta d) - J(w).
   *
   * The full step is taken if the energy grows by no more than round-off
   * (1e-12 @p scale, @p scale the size of the energy terms); a shorter step
   * only if the energy really decreases. If none does, d is not a descent
   * direction (the linearisation at a kink of the contact potential): the
   * full active-set step is taken, as the semismooth method would. Accepting
   * a shorter step on the round-off bound instead lets such a direction
   * creep: at 3D r4, k = 0.0025 Newton once moved by theta = 1/512 for 50
   * iterations without converging.
   *
   * Returns theta; @p n_reductions counts the halvings tried.
   */
  double
  backtracking_step_length(const std::function<double(double)> &energy_change,
                           double                               scale,
                           double                               min_step_length,
                           unsigned int                        &n_reductions);
} // namespace hemicontact
