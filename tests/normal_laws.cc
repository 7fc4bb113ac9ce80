// Unit test of every normal law: j, the subdifferential and its split
// a + p(r), p' against a difference quotient of p, P against a quadrature
// of p, and alpha against the steepest descent of the response, at and
// around every kink (r = 0 and the breakpoints). Also checks the relaxed
// monotonicity inequality on a grid.
#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/normal/exponential_law.h>
#include <hemicontact/laws/normal/linear_damping_law.h>
#include <hemicontact/laws/normal/no_normal_resistance.h>
#include <hemicontact/laws/normal/piecewise_linear_law.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <vector>

using namespace hemicontact;

namespace
{
  void
  check_law(const NormalLaw &law, const std::vector<double> &kinks)
  {
    std::cout << "law '" << law.name() << "': a = " << law.jump()
              << ", alpha = " << law.relaxed_monotonicity_constant() << "\n";

    std::vector<double> points = {-0.5, -1e-3, 0., 1e-3, 0.5, 2.};
    for (const double r : kinks)
      for (const double d : {-1e-3, 0., 1e-3})
        points.push_back(r + d);

    bool derivative_ok = true, primitive_ok = true, split_ok = true;
    for (const double r : points)
      {
        // p' against a one-sided difference quotient (away from kinks)
        const double h         = 1e-7;
        const double fd        = (law.remainder(r + h) - law.remainder(r)) / h;
        bool         near_kink = std::abs(r) < 2 * h;
        for (const double k : kinks)
          near_kink |= std::abs(r - k) < 2 * h;
        if (!near_kink && std::abs(fd - law.remainder_derivative(r)) >
                            1e-5 * (1 + std::abs(fd)))
          derivative_ok = false;

        // P against the trapezoidal rule on a fine grid
        const unsigned int n        = 200000;
        double             integral = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            const double s0 = r * i / n, s1 = r * (i + 1) / n;
            integral +=
              0.5 * (law.remainder(s0) + law.remainder(s1)) * (s1 - s0);
          }
        if (std::abs(integral - law.remainder_primitive(r)) > 1e-8)
          primitive_ok = false;

        // subdifferential = [0,a] at 0, {0} below, {a + p} above
        const auto sd = law.subdifferential(r);
        if (r < 0 && (sd.first != 0 || sd.second != 0))
          split_ok = false;
        if (r == 0 && (sd.first != 0 || sd.second != law.jump()))
          split_ok = false;
        if (r > 0 && std::abs(sd.first - law.jump() - law.remainder(r)) > 1e-15)
          split_ok = false;
        if (std::abs(law.potential(r) - (law.jump() * std::max(r, 0.) +
                                         law.remainder_primitive(r))) > 1e-15)
          split_ok = false;
      }

    // relaxed monotonicity: (xi1 - xi2)(r1 - r2) >= -alpha (r1 - r2)^2,
    // and alpha is attained (sharp) up to the grid
    const double alpha       = law.relaxed_monotonicity_constant();
    bool         monotone_ok = true;
    double       worst       = 0;
    for (double r1 = -0.2; r1 <= 1.5; r1 += 0.0125)
      for (double r2 = r1 + 0.0125; r2 <= 1.5; r2 += 0.0125)
        {
          const auto s1 = law.subdifferential(r1), s2 = law.subdifferential(r2);
          for (const double xi1 : {s1.first, s1.second})
            for (const double xi2 : {s2.first, s2.second})
              {
                const double q =
                  (xi1 - xi2) * (r1 - r2) / ((r1 - r2) * (r1 - r2));
                worst = std::min(worst, q);
                if (q < -alpha - 1e-9)
                  monotone_ok = false;
              }
        }
    const bool sharp = alpha == 0 ? worst >= -1e-12 : -worst > 0.5 * alpha;

    std::cout << std::setprecision(6);
    for (const double r : {-0.1, 0., 0.05, 0.1, 0.3, 1.})
      std::cout << "  r = " << r << ": j = " << law.potential(r) << ", dj = ["
                << law.subdifferential(r).first << ", "
                << law.subdifferential(r).second << "]"
                << ", p' = " << law.remainder_derivative(r) << "\n";
    std::cout
      << "  p' matches difference quotients: " << (derivative_ok ? "yes" : "no")
      << "\n  P matches the integral of p: " << (primitive_ok ? "yes" : "no")
      << "\n  subdifferential = d(a r+) + p: " << (split_ok ? "yes" : "no")
      << "\n  relaxed monotone with alpha: " << (monotone_ok ? "yes" : "no")
      << "\n  alpha is sharp: " << (sharp ? "yes" : "no") << "\n";
  }

  void
  expect_input_error(const std::string &what, const std::function<void()> &f)
  {
    try
      {
        f();
        std::cout << what << ": accepted (WRONG)\n";
      }
    catch (const InputError &e)
      {
        std::cout << what << ": rejected\n";
      }
  }
} // namespace

int
main()
{
  check_law(ExponentialLaw(1., 0.4, 3.), {});
  check_law(ExponentialLaw(1., 1., 3.), {});
  check_law(PiecewiseLinearLaw({{0, 1}, {0.05, 1.5}, {0.2, 0.4}, {0.5, 0.4}}),
            {0.05, 0.2, 0.5});
  check_law(LinearDampingLaw(2.), {});
  check_law(NoNormalResistance(), {});

  expect_input_error("exponential with a < b",
                     [] { ExponentialLaw(0.5, 1., 1.); });
  expect_input_error("exponential with b < 0",
                     [] { ExponentialLaw(1., -1., 1.); });
  expect_input_error("exponential with beta < 0",
                     [] { ExponentialLaw(1., 0.5, -1.); });
  expect_input_error("piecewise linear not starting at 0", [] {
    PiecewiseLinearLaw({{0.1, 1}});
  });
  expect_input_error("piecewise linear with decreasing r", [] {
    PiecewiseLinearLaw({{0, 1}, {0.2, 1}, {0.1, 1}});
  });
  expect_input_error("piecewise linear with negative response", [] {
    PiecewiseLinearLaw({{0, 1}, {0.2, -1}});
  });
  expect_input_error("linear damping with negative coefficient",
                     [] { LinearDampingLaw(-1.); });
}
