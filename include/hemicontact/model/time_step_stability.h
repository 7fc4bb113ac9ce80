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

  /**
   * A time step below which the staggered thermal coupling (doc/theory.md
   * 13.2) with the implicit rule is stable on every mesh. The mechanical
   * step sees theta_{n-1}, the heat step w_n: testing both with the step's
   * unknowns leaves k (c_e (theta_{n-1} - theta_n), div w_n), at most
   * 1/2 int c_theta (theta_n - theta_{n-1})^2 (the heat step's numerical
   * dissipation) plus k^2/2 int c (div w_n)^2, c = c_e^2/c_theta
   * (@p coupling_ratio, its largest value). The viscous k a_A(w_n, w_n)
   * and the elastic k^2/2 a_B(w_n, w_n) cover that, pointwise for every
   * eps, if k (c (tr eps)^2 - B eps : eps) <= 2 A eps : eps. Only the
   * volumetric part sees c; with the bulk moduli kappa = 2 mu/d + lambda
   * of A (@p mu_v, @p lambda_v) and B (@p mu, @p lambda):
   * k <= 2 kappa_A / (c - kappa_B), sharp for a uniform dilation.
   * Infinite when c <= kappa_B. (With the left-point rule B's term adds to
   * c instead: mesh_independent_stable_time_step() with lambda + c.)
   */
  inline double
  coupling_stable_time_step(const unsigned int dim,
                            const double       mu_v,
                            const double       lambda_v,
                            const double       mu,
                            const double       lambda,
                            const double       coupling_ratio)
  {
    const double kappa_v = 2 * mu_v / dim + lambda_v;
    const double kappa   = 2 * mu / dim + lambda;
    const double excess  = coupling_ratio - kappa;
    return excess > 0 ? 2 * kappa_v / excess :
                        std::numeric_limits<double>::infinity();
  }
} // namespace hemicontact
