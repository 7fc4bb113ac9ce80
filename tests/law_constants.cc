// Every registered law's declared constants against its own functions.
// For each normal and friction law of the registries (with its default
// parameters, and a few further sets for the laws with breakpoints), the
// remainder and its derivative are sampled on a fine grid and the law's
// declarations are checked against what the samples show
// (include/hemicontact/laws/normal_law.h, doc/theory.md sections 7 and 10):
// - p' (r') brackets the difference quotient of p (r) on every grid cell
//   where p is continuous, and P (R) is the integral of p (r);
// - p = 0 (and p' = P = 0) for r <= 0, p(0+) = 0 (the jump a is all of
//   the response's jump at 0), a >= 0;
// - p has no upward jump (an upward jump of the response is a kink, listed
//   by kinks(), with the remainder continuous there), the kinks are at
//   increasing r > 0 with jumps J > 0;
// - alpha is the steepest descent of p (infinite exactly when p jumps
//   down), the largest remainder slope its steepest rise (0 if none);
// - the wall is the law's 'penetration limit' entry, +inf without one.
// A law registered later is checked by the same loop with its defaults.
#include <deal.II/base/parameter_handler.h>

#include <hemicontact/laws/friction_law.h>
#include <hemicontact/laws/normal_law.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

using namespace hemicontact;

namespace
{
  const char *
  yes(const bool b)
  {
    return b ? "yes" : "no";
  }

  /** Whether @p value agrees with @p expected: both infinite, or close. */
  bool
  close(const double value, const double expected, const double relative)
  {
    if (std::isinf(expected) || std::isinf(value))
      return value == expected;
    return std::abs(value - expected) <= relative * (1 + std::abs(expected));
  }

  /**
   * What the samples of a remainder f (with derivative df and primitive F)
   * on the grid r_k = k h, k = k0..k1, show: its steepest rise and descent
   * on the cells where it is continuous, its jumps, and whether df and F
   * agree with it.
   */
  struct Sampled
  {
    double                                 steepest_rise    = 0;
    double                                 steepest_descent = 0;
    std::vector<std::pair<double, double>> jumps; // (position, size)
    bool                                   derivative_ok = true;
    bool                                   primitive_ok  = true;
    double worst_derivative_r = std::numeric_limits<double>::quiet_NaN();
  };

  template <class F, class DF, class PF>
  Sampled
  sample(const F &f, const DF &df, const PF &primitive, const double end)
  {
    Sampled      result;
    const double h  = 1e-5;
    const long   k0 = -20000, k1 = std::lround(end / h);
    double       integral = 0; // trapezoidal rule from r = 0
    for (long k = k0; k < k1; ++k)
      {
        const double r0 = k * h, r1 = (k + 1) * h;
        // the derivative just inside the cell: one-sided at its ends
        const double f0 = f(r0), f1 = f(r1);
        const double d0 = df(r0 + 1e-3 * h), d1 = df(r1 - 1e-3 * h);
        const double quotient = (f1 - f0) / h;
        // a jump: more change over the cell than the derivative allows
        const double slope_scale = std::max(std::abs(d0), std::abs(d1));
        if (std::abs(f1 - f0) > 2 * h * slope_scale + 1e-9 * (1 + slope_scale))
          {
            result.jumps.emplace_back(r1, f1 - f0);
            if (r0 >= 0)
              integral = primitive(r1); // restart the quadrature after it
            continue;
          }
        // the difference quotient lies between the derivatives at the
        // ends (up to the curvature within the cell)
        const double tolerance = 1e-6 * (1 + std::abs(quotient));
        if (quotient < std::min(d0, d1) - tolerance ||
            quotient > std::max(d0, d1) + tolerance)
          {
            if (result.derivative_ok)
              result.worst_derivative_r = r0;
            result.derivative_ok = false;
          }
        result.steepest_rise    = std::max(result.steepest_rise, quotient);
        result.steepest_descent = std::max(result.steepest_descent, -quotient);
        result.steepest_rise    = std::max({result.steepest_rise, d0, d1});
        result.steepest_descent = std::max({result.steepest_descent, -d0, -d1});
        if (r0 >= 0)
          {
            integral += 0.5 * (f0 + f1) * h;
            if (std::abs(integral - primitive(r1)) >
                1e-6 * (1 + std::abs(integral)))
              result.primitive_ok = false;
          }
      }
    return result;
  }

  /** The law of @p name of @p kind with the parameters @p settings. */
  void
  parameters(ParameterHandler  &prm,
             const std::string &kind,
             const std::string &name,
             const std::string &settings)
  {
    declare_normal_law_parameters(prm);
    declare_friction_law_parameters(prm);
    prm.parse_input_from_string("subsection " + kind + "\n  set law = " + name +
                                "\n" + settings + "end\n");
  }

  /** The law's 'penetration limit' entry, +inf if it declares none. */
  double
  declared_wall(ParameterHandler &prm, const std::string &name)
  {
    prm.enter_subsection("normal law");
    double g = std::numeric_limits<double>::infinity();
    try
      {
        prm.enter_subsection(name);
        try
          {
            g = prm.get_double("penetration limit");
          }
        catch (...)
          {}
        prm.leave_subsection();
      }
    catch (...)
      {}
    prm.leave_subsection();
    return g;
  }

  void
  check_normal_law(const std::string &name, const std::string &settings)
  {
    ParameterHandler prm;
    parameters(prm, "normal law", name, settings);
    const std::unique_ptr<NormalLaw> law = create_normal_law(prm);
    const double                     a   = law->jump();
    const double alpha                   = law->relaxed_monotonicity_constant();
    const double slope                   = law->largest_remainder_slope();
    const double g                       = law->penetration_limit();
    const std::vector<NormalLaw::Kink> &kinks = law->kinks();

    std::cout << "normal law '" << name << "'"
              << (settings.empty() ? " (defaults)" : "") << ": a = " << a
              << ", alpha = " << alpha
              << ", largest remainder slope = " << slope
              << ", kinks = " << kinks.size() << ", wall = " << g << "\n";

    // the grid reaches beyond every kink and the wall
    double end = 3;
    for (const NormalLaw::Kink &kink : kinks)
      end = std::max(end, 2 * kink.position);
    if (std::isfinite(g))
      end = std::max(end, 2 * g);
    const Sampled s =
      sample([&](const double r) { return law->remainder(r); },
             [&](const double r) { return law->remainder_derivative(r); },
             [&](const double r) { return law->remainder_primitive(r); },
             end);

    bool zero_below = true;
    for (const double r : {-1., -0.1, -1e-9, 0.})
      zero_below &= law->remainder(r) == 0 &&
                    law->remainder_primitive(r) == 0 &&
                    (r == 0 || law->remainder_derivative(r) == 0);

    bool   upward_jump = false, downward_jump = false;
    double first_upward = 0;
    for (const auto &jump : s.jumps)
      if (jump.second > 0)
        {
          if (!upward_jump)
            first_upward = jump.first;
          upward_jump = true;
        }
      else
        downward_jump = true;

    bool kinks_ok = true;
    for (unsigned int j = 0; j < kinks.size(); ++j)
      kinks_ok &= kinks[j].position > 0 && kinks[j].jump > 0 &&
                  (j == 0 || kinks[j].position > kinks[j - 1].position) &&
                  // the response jumps up by J at r_j: p is continuous there
                  std::abs(law->subgradient(kinks[j].position) -
                           law->subgradient(kinks[j].position - 1e-9) -
                           kinks[j].jump) < 1e-6 * (1 + kinks[j].jump);

    const double expected_alpha = downward_jump ?
                                    std::numeric_limits<double>::infinity() :
                                    s.steepest_descent;
    std::cout << "  a >= 0: " << yes(a >= 0 && std::isfinite(a))
              << ", p = p' = P = 0 for r <= 0: " << yes(zero_below) << "\n"
              << "  p' matches difference quotients of p: "
              << yes(s.derivative_ok);
    if (!s.derivative_ok)
      std::cout << " (first at r = " << s.worst_derivative_r << ")";
    std::cout << "\n  P is the integral of p: " << yes(s.primitive_ok) << "\n"
              << "  no upward jump of p (jumps of the response are a or "
                 "kinks): "
              << yes(!upward_jump);
    if (upward_jump)
      std::cout << " (at r = " << first_upward << ")";
    std::cout << "\n  kinks at increasing r > 0, J > 0, the response's jumps: "
              << yes(kinks_ok) << "\n"
              << "  alpha = steepest descent of p (" << expected_alpha << "): "
              << yes(close(alpha, expected_alpha, 1e-3) &&
                     alpha >= expected_alpha * (1 - 1e-9))
              << "\n"
              << "  largest remainder slope = steepest rise of p ("
              << s.steepest_rise << "): "
              << yes(close(slope, s.steepest_rise, 1e-3) &&
                     slope >= s.steepest_rise * (1 - 1e-9))
              << "\n"
              << "  wall = the law's 'penetration limit' ("
              << declared_wall(prm, name)
              << "): " << yes(g == declared_wall(prm, name) && g >= 0) << "\n";
  }

  void
  check_friction_law(const std::string &name,
                     const std::string &settings,
                     const double       bound)
  {
    ParameterHandler prm;
    parameters(prm, "friction law", name, settings);
    const std::unique_ptr<FrictionLaw> law = create_friction_law(prm);
    const double alpha = law->relaxed_monotonicity_constant(bound);
    std::cout << "friction law '" << name << "'"
              << (settings.empty() ? " (defaults)" : "") << ", F_b = " << bound
              << ": alpha_tau = " << alpha << "\n";

    // the remainder of the slip speed, extended by 0 to s < 0
    const Sampled s = sample(
      [&](const double v) { return v > 0 ? law->remainder(bound, v) : 0.; },
      [&](const double v) {
        return v > 0 ? law->remainder_derivative(bound, v) : 0.;
      },
      [&](const double v) {
        return v > 0 ? law->remainder_primitive(bound, v) : 0.;
      },
      3.);
    bool force_ok = law->remainder(bound, 0.) == 0;
    for (double v = 0; v < 3; v += 1e-3)
      force_ok &= law->response(bound, v) >= 0;
    std::cout << "  r(0) = 0 and F >= 0: " << yes(force_ok) << "\n"
              << "  r' matches difference quotients of r: "
              << yes(s.derivative_ok) << "\n"
              << "  R is the integral of r: " << yes(s.primitive_ok) << "\n"
              << "  r is continuous: " << yes(s.jumps.empty()) << "\n"
              << "  alpha_tau = steepest descent of r (" << s.steepest_descent
              << "): "
              << yes(close(alpha, s.steepest_descent, 1e-3) &&
                     alpha >= s.steepest_descent * (1 - 1e-9))
              << "\n";
  }
} // namespace

int
main()
{
  // every registered law with its defaults
  for (const NormalLawEntry &entry : normal_law_registry())
    check_normal_law(entry.name, "");
  for (const FrictionLawEntry &entry : friction_law_registry())
    for (const double bound : {1., 0.35})
      check_friction_law(entry.name, "", bound);

  // further parameters: an upward jump (a kink), a downward jump, Example
  // B's penalty, a wall away from its default, a nonmonotone friction law
  check_normal_law("piecewise linear",
                   "  subsection piecewise linear\n"
                   "    set subgradient breakpoints = 0:0.5, 0.1:1, 0.1:1.5, "
                   "0.3:0.5, 0.6:2\n  end\n");
  check_normal_law("piecewise linear",
                   "  subsection piecewise linear\n"
                   "    set subgradient breakpoints = 0:0, 0.1:2, 0.1:0\n"
                   "  end\n");
  check_normal_law("penalised softening compliance",
                   "  subsection penalised softening compliance\n"
                   "    set penalty = 1024\n  end\n");
  check_normal_law("exponential",
                   "  subsection exponential\n    set a = 2\n    set b = 2\n"
                   "  end\n");
  check_normal_law("normal compliance with finite penetration",
                   "  subsection normal compliance with finite penetration\n"
                   "    set stiffness = 3\n    set penetration limit = 0.37\n"
                   "  end\n");
  check_normal_law("signorini",
                   "  subsection signorini\n    set penetration limit = 0.25\n"
                   "  end\n");
  check_friction_law("piecewise linear",
                     "  subsection piecewise linear\n"
                     "    set response breakpoints = 0:1, 0.1:1.4, 0.3:0.2\n"
                     "  end\n",
                     0.8);
  check_friction_law("rational weakening",
                     "  subsection rational weakening\n"
                     "    set characteristic slip = 0.2\n  end\n",
                     0.6);
}
