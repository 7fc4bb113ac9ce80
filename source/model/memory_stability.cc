#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <hemicontact/model/memory_stability.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <utility>

namespace hemicontact
{
  using namespace dealii;

  namespace
  {
    /** The spectral radius of a square matrix (LAPACK's eigenvalues). */
    double
    spectral_radius(const FullMatrix<double> &matrix)
    {
      LAPACKFullMatrix<double> t(matrix.m(), matrix.n());
      t = matrix;
      t.compute_eigenvalues();
      double radius = 0;
      for (unsigned int i = 0; i < matrix.m(); ++i)
        radius = std::max(radius, std::abs(t.eigenvalue(i)));
      return radius;
    }

    /** e^{-k/tau}, 1 for a constant term. */
    double
    decay(const double k, const double tau)
    {
      return std::isfinite(tau) ? std::exp(-k / tau) : 1.;
    }

    /** A growth this far above 1 is round-off of the eigenvalues. */
    constexpr double growth_tolerance = 1e-10;

    /** The largest real part of the eigenvalues of a square matrix. */
    double
    largest_real_part(const FullMatrix<double> &matrix)
    {
      LAPACKFullMatrix<double> t(matrix.m(), matrix.n());
      t = matrix;
      t.compute_eigenvalues();
      double largest = -std::numeric_limits<double>::infinity();
      for (unsigned int i = 0; i < matrix.m(); ++i)
        largest = std::max(largest, t.eigenvalue(i).real());
      return largest;
    }
  } // namespace

  double
  model_growth_rate(const MemoryMode &mode, const StepScheme &scheme)
  {
    const unsigned int n_terms = mode.amplitudes.size();
    if (n_terms == 0)
      return 0;
    // h_l(t) = int_0^t e^{-(t-s)/tau_l} u(s) ds: h_l' = u - h_l/tau_l
    const auto inverse = [&](const unsigned int l) {
      return std::isfinite(mode.relaxation_times[l]) ?
               1. / mode.relaxation_times[l] :
               0.;
    };
    const double       m = scheme.has_inertia() ? mode.mass : 0.;
    FullMatrix<double> t;
    if (scheme.is_static() || (m <= 0 && !(mode.viscosity > 0)))
      {
        // b u = -sum_l r_l h_l: the state (h_1, ..., h_L)
        if (!(mode.elasticity > 0))
          return 0;
        t.reinit(n_terms, n_terms);
        for (unsigned int l = 0; l < n_terms; ++l)
          for (unsigned int j = 0; j < n_terms; ++j)
            t(l, j) = -mode.amplitudes[j] / mode.elasticity -
                      (l == j ? inverse(l) : 0.);
      }
    else if (m <= 0)
      {
        // a u' = -b u - sum_l r_l h_l: the state (u, h_1, ..., h_L)
        t.reinit(1 + n_terms, 1 + n_terms);
        t(0, 0) = -mode.elasticity / mode.viscosity;
        for (unsigned int l = 0; l < n_terms; ++l)
          {
            t(0, 1 + l)     = -mode.amplitudes[l] / mode.viscosity;
            t(1 + l, 0)     = 1;
            t(1 + l, 1 + l) = -inverse(l);
          }
      }
    else
      {
        // m w' = -a w - b u - sum_l r_l h_l, u' = w: (w, u, h_1, ..., h_L)
        t.reinit(2 + n_terms, 2 + n_terms);
        t(0, 0) = -mode.viscosity / m;
        t(0, 1) = -mode.elasticity / m;
        t(1, 0) = 1;
        for (unsigned int l = 0; l < n_terms; ++l)
          {
            t(0, 2 + l)     = -mode.amplitudes[l] / m;
            t(2 + l, 1)     = 1;
            t(2 + l, 2 + l) = -inverse(l);
          }
      }
    return std::max(largest_real_part(t), 0.);
  }

  double
  allowed_memory_growth(const double model_rate, const double k)
  {
    return std::exp(2 * model_rate * k) * (1 + growth_tolerance);
  }

  double
  memory_rule_growth(const MemoryMode &mode,
                     const double      k,
                     const StepScheme &scheme,
                     const bool        with_memory)
  {
    const unsigned int n_terms = with_memory ? mode.amplitudes.size() : 0;
    if (scheme.is_static())
      {
        // B u_n = f - sum_l r_l h_l,  h_l' = q_l (h_l + k u_n)
        if (n_terms == 0)
          return 0;
        FullMatrix<double> t(n_terms, n_terms);
        for (unsigned int l = 0; l < n_terms; ++l)
          {
            const double q = decay(k, mode.relaxation_times[l]);
            for (unsigned int j = 0; j < n_terms; ++j)
              t(l, j) = q * ((l == j ? 1. : 0.) -
                             k * mode.amplitudes[j] / mode.elasticity);
          }
        return spectral_radius(t);
      }
    // the state (w_{n-1}, u, h): u = u_n (left point, held before the
    // step) or u_{n-1} (implicit); the step solves
    //   (m/k + a [+ k b]) w_n = m/k w_{n-1} - b u - sum_l r_l h_l
    const bool   implicit = scheme.time_scheme() == TimeScheme::implicit;
    const double m        = scheme.has_inertia() ? mode.mass : 0.;
    const double diagonal =
      m / k + mode.viscosity + (implicit ? k * mode.elasticity : 0.);
    const unsigned int n = 2 + n_terms;
    FullMatrix<double> t(n, n);
    // w_n as a row over the state
    std::vector<double> w(n, 0.);
    w[0] = m / k / diagonal;
    w[1] = -mode.elasticity / diagonal;
    for (unsigned int l = 0; l < n_terms; ++l)
      w[2 + l] = -mode.amplitudes[l] / diagonal;
    for (unsigned int j = 0; j < n; ++j)
      {
        t(0, j) = w[j];
        // u_{n+1} = u_n + k w_n, or u_n = u_{n-1} + k w_n
        t(1, j) = (j == 1 ? 1. : 0.) + k * w[j];
      }
    for (unsigned int l = 0; l < n_terms; ++l)
      {
        // h_l' = q_l (h_l + k u), u the displacement the next term adds:
        // u_n (left point: the state's u), u_n = u_{n-1} + k w_n (implicit)
        const double q = decay(k, mode.relaxation_times[l]);
        for (unsigned int j = 0; j < n; ++j)
          t(2 + l, j) = q * ((j == 2 + l ? 1. : 0.) +
                             k * (implicit ? t(1, j) : (j == 1 ? 1. : 0.)));
      }
    return spectral_radius(t);
  }

  double
  largest_stable_memory_step(const MemoryMode &mode,
                             const double      k,
                             const StepScheme &scheme)
  {
    const double rate   = model_growth_rate(mode, scheme);
    const auto   stable = [&](const double s) {
      return memory_rule_growth(mode, s, scheme) <=
             allowed_memory_growth(rate, s);
    };
    if (stable(k))
      return k;
    double unstable = k, low = k / 2;
    while (!stable(low) && low > 1e-12 * k)
      {
        unstable = low;
        low /= 2;
      }
    while (unstable - low > 1e-3 * low)
      {
        const double middle               = (low + unstable) / 2;
        (stable(middle) ? low : unstable) = middle;
      }
    return low;
  }

  std::pair<double, double>
  exponential_through(const double at_k, const double at_2k, const double k)
  {
    const double q = at_2k / at_k;
    if (!(q > 0) || !(q < 1))
      return {at_k, std::numeric_limits<double>::infinity()};
    // r e^{-k/tau} = at_k, r e^{-2k/tau} = at_2k
    return {at_k / q, -k / std::log(q)};
  }
} // namespace hemicontact
