#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace hemicontact
{
  /**
   * The stability limit of the left-point rule (doc/theory.md, section
   * "Stability of the left-point rule"). For one mode with mass m, viscosity
   * a and elasticity b (Rayleigh quotients of M, A, B) the scheme
   *
   *   m (w_n - w_{n-1})/k + a w_n + b u_n = 0,   u_{n+1} = u_n + k w_n
   *
   * has bounded powers iff k^2 b - 2 k a - 4 m <= 0, i.e.
   * k <= (a + sqrt(a^2 + 4 b m)) / b. For all modes at once: the largest
   * eigenvalue of B against A + 2M/k is at most 2/k.
   */
  inline double
  stable_time_step_of_mode(const double mass,
                           const double viscosity,
                           const double elasticity)
  {
    if (!(elasticity > 0))
      return std::numeric_limits<double>::infinity();
    return (viscosity + std::sqrt(viscosity * viscosity +
                                  4 * elasticity * std::max(mass, 0.))) /
           elasticity;
  }

  /**
   * A time step below which the left-point rule is stable on every mesh:
   * 2 / max(B eps : eps / A eps : eps) for isotropic A (mu_v, lambda_v) and
   * B (mu, lambda) in dimension @p dim. Both share the eigenspaces of
   * symmetric tensors (deviatoric: 2 mu; volumetric: 2 mu + dim lambda),
   * so the ratio is the larger of the two eigenvalue ratios. Infinite if B
   * vanishes.
   */
  inline double
  mesh_independent_stable_time_step(const unsigned int dim,
                                    const double       mu_v,
                                    const double       lambda_v,
                                    const double       mu,
                                    const double       lambda)
  {
    const double deviatoric = mu / mu_v;
    const double volumetric =
      (2 * mu + dim * lambda) / (2 * mu_v + dim * lambda_v);
    const double ratio = std::max(deviatoric, volumetric);
    return ratio > 0 ? 2 / ratio : std::numeric_limits<double>::infinity();
  }
} // namespace hemicontact
