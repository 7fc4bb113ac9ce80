#pragma once

#include <hemicontact/model/step_scheme.h>

#include <vector>

namespace hemicontact
{
  /**
   * One mode of the linear part of a step with the explicit memory rule
   * (doc/theory.md 11.13): the Rayleigh quotients of rho M (@p mass), A
   * (@p viscosity) and B (@p elasticity) at the mode, and the memory
   * kernel as exponentials r_l e^{-t/tau_l} of the same quotient (the
   * kernel's tensor R_l, or b_l at the contact). A term with tau_l = inf
   * is a constant kernel.
   */
  struct MemoryMode
  {
    double              mass       = 0;
    double              viscosity  = 0;
    double              elasticity = 0;
    std::vector<double> amplitudes;
    std::vector<double> relaxation_times;
  };

  /**
   * The spectral radius of the rule's one-step map of @p mode for steps
   * of length @p k in the class and rule of @p scheme (doc/theory.md
   * 11.13), on the state (h_1, ..., h_L) in the static class and
   * (w_{n-1}, u, h_1, ..., h_L) in the velocity classes,
   * h_l = sum_{j<n} k e^{-(t_n - t_j)/tau_l} u_j. With @p with_memory
   * false, the same map without the memory terms.
   */
  double
  memory_rule_growth(const MemoryMode &mode,
                     const double      k,
                     const StepScheme &scheme,
                     const bool        with_memory = true);

  /**
   * The growth rate s >= 0 of @p mode in the model itself (doc/theory.md
   * 11.13): the largest real part of the eigenvalues of the mode's
   * equations m w' + a w + b u + sum_l r_l h_l = 0, u' = w,
   * h_l' = u - h_l/tau_l (without inertia a u' + ..., in the static
   * class b u + ...), 0 if the model does not grow. A kernel whose
   * long-term modulus is negative makes it positive.
   */
  double
  model_growth_rate(const MemoryMode &mode, const StepScheme &scheme);

  /**
   * The largest growth per step of length @p k that the rule may have for
   * a mode whose model grows at @p model_rate: e^{2 s k} (1 at s = 0, up
   * to round-off), the model's own e^{s k} with as much again for the
   * rule's first-order error.
   */
  double
  allowed_memory_growth(const double model_rate, const double k);

  /**
   * The largest step length at most @p k at which memory_rule_growth()
   * is at most allowed_memory_growth() (by bisection, to 1e-3 relative);
   * @p k itself if it is stable.
   */
  double
  largest_stable_memory_step(const MemoryMode &mode,
                             const double      k,
                             const StepScheme &scheme);

  /**
   * The exponential r e^{-t/tau} through the values @p at_k and @p at_2k
   * of a kernel at t = k and 2k, as a one-term mode's amplitude and
   * relaxation time: the kernel an expression kernel is checked as
   * (exact for a one-term Prony series written as an expression). A
   * kernel that does not decrease in size from k to 2k, or changes sign,
   * is checked as the constant @p at_k (tau = inf).
   */
  std::pair<double, double>
  exponential_through(const double at_k, const double at_2k, const double k);
} // namespace hemicontact
