// Unit test of the stability limit of the left-point rule
// (include/hemicontact/model/time_step_stability.h): for single modes (m, a, b)
// the spectral radius of the step's amplification matrix is at most 1 just
// below the limit and above 1 just above it; for a viscosity proportional
// to the elasticity the mesh-independent limit is 2 mu_v / mu.
#include <hemicontact/model/time_step_stability.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <iostream>

using namespace hemicontact;

namespace
{
  /**
   * Spectral radius of (w_{n-1}, u_n) -> (w_n, u_{n+1}) for
   * m (w_n - w_{n-1})/k + a w_n + b u_n = 0, u_{n+1} = u_n + k w_n.
   */
  double
  spectral_radius(const double m,
                  const double a,
                  const double b,
                  const double k)
  {
    const double c = m / k + a;
    // [[m/(k c), -b/c], [m/c, 1 - k b/c]]
    const double m11 = m / (k * c), m12 = -b / c, m21 = m / c,
                 m22                 = 1 - k * b / c;
    const double               trace = m11 + m22;
    const double               det   = m11 * m22 - m12 * m21;
    const std::complex<double> root =
      std::sqrt(std::complex<double>(trace * trace / 4 - det));
    return std::max(std::abs(trace / 2 + root), std::abs(trace / 2 - root));
  }
} // namespace

int
main()
{
  const double modes[][3] = {{1, 1, 100},
                             {1e-3, 1, 100},
                             {0, 1, 100},
                             {1, 0.01, 1},
                             {5, 2, 1e4},
                             {1e-6, 0.3, 7}};
  bool         all_ok     = true;
  for (const auto &mode : modes)
    {
      const double m = mode[0], a = mode[1], b = mode[2];
      const double k     = stable_time_step_of_mode(m, a, b);
      const double below = spectral_radius(m, a, b, 0.999 * k);
      const double above = spectral_radius(m, a, b, 1.001 * k);
      const bool   ok    = below <= 1 + 1e-12 && above > 1;
      all_ok             = all_ok && ok;
      std::cout << "m = " << m << ", a = " << a << ", b = " << b
                << ": k* = " << k << (ok ? " separates" : " does NOT separate")
                << " bounded from growing powers\n";
    }
  // without mass the limit is 2a/b
  std::cout << "no mass: k* b / (2 a) = "
            << stable_time_step_of_mode(0, 3, 12) * 12 / (2 * 3) << "\n";
  // A = 0.01 B: every mode has a/b = 0.01, so k* >= 0.02 on any mesh
  std::cout << "proportional viscosity, 2D: "
            << mesh_independent_stable_time_step(2, 0.4, 0.6, 40, 60) << "\n"
            << "proportional viscosity, 3D: "
            << mesh_independent_stable_time_step(3, 0.4, 0.6, 40, 60) << "\n";
  // the default example: mu_v = lambda_v = 1, E = 100, nu = 0.3
  const double mu = 100 / (2 * 1.3), lambda = 100 * 0.3 / (1.3 * 0.4);
  std::cout << "default example, 2D: "
            << mesh_independent_stable_time_step(2, 1, 1, mu, lambda) << "\n";
  // the staggered thermal coupling, implicit rule (doc/theory.md 13.2): a
  // uniform dilation e I in d dimensions with theta maps (e, theta) to
  // e_n = e + k edot, theta_n = theta - k c_e d edot/c_theta, edot =
  // (c_e theta - d kappa_B e)/(d (kappa_A + k kappa_B)); its eigenvalues
  // are 1 and (kappa_A - k c)/(kappa_A + k kappa_B), -1 at the limit
  for (const unsigned int d : {2u, 3u})
    {
      const double mu_v = 1, lambda_v = 1, mu_e = 1, lambda_e = 1;
      const double c_e = 10, c_theta = 1;
      const double kappa_a = 2 * mu_v / d + lambda_v;
      const double kappa_b = 2 * mu_e / d + lambda_e;
      const double limit   = coupling_stable_time_step(
        d, mu_v, lambda_v, mu_e, lambda_e, c_e * c_e / c_theta);
      const auto second_eigenvalue = [&](const double k) {
        const double D  = d * (kappa_a + k * kappa_b);
        const double a0 = -(d * kappa_b) / D, a1 = c_e / D;
        const double t00 = 1 + k * a0, t01 = k * a1;
        const double t10 = -k * c_e * d / c_theta * a0;
        const double t11 = 1 - k * c_e * d / c_theta * a1;
        // the smaller (real) eigenvalue of the 2 x 2 map
        const double half_trace = (t00 + t11) / 2;
        const double det        = t00 * t11 - t01 * t10;
        return half_trace -
               std::sqrt(std::max(half_trace * half_trace - det, 0.));
      };
      const bool ok = std::abs(second_eigenvalue(limit) + 1) < 1e-12 &&
                      second_eigenvalue(0.99 * limit) > -1 &&
                      second_eigenvalue(1.01 * limit) < -1;
      all_ok = all_ok && ok;
      std::cout << "staggered thermal coupling, " << d << "D: k* = " << limit
                << (ok ? ", the dilation's eigenvalue -1 there" :
                         ", NOT the dilation's limit")
                << "\n";
    }
  std::cout << (all_ok ? "all limits separate" : "FAILED") << std::endl;
  return all_ok ? 0 : 1;
}
