// Unit test of the normal law 'penalised softening compliance' (Example B,
// doc/examples.md section 9): p, P and p' at sample points against the
// closed forms of j' and j, continuity of p and P at r = b, P' = p and
// p' against central difference quotients, alpha against the steepest
// descent of p on a grid, and the rejected parameters.
#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/normal/penalised_softening_compliance.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>

using namespace hemicontact;

namespace
{
  void
  check(const double a, const double b, const double penalty)
  {
    const PenalisedSofteningCompliance law(a, b, penalty);
    std::cout << std::setprecision(8) << "a = " << a << ", b = " << b
              << ", penalty = " << penalty << ": jump = " << law.jump()
              << ", alpha = " << law.relaxed_monotonicity_constant() << "\n";
    for (const double r : {-0.1, 0., 0.05, b, 0.5, 2.})
      std::cout << "  r = " << r << ": p = " << law.remainder(r)
                << ", P = " << law.remainder_primitive(r)
                << ", p' = " << law.remainder_derivative(r) << "\n";

    // closed forms of j' and j (penalty times) at the sample points
    const auto dj = [&](const double r) {
      return r <= 0 ? 0. :
             r < b  ? (a + std::exp(-b)) * r / b :
                      a + std::exp(-r);
    };
    const auto j = [&](const double r) {
      return r <= 0 ?
               0. :
             r < b ?
               (a + std::exp(-b)) * r * r / (2 * b) :
               a * r - std::exp(-r) + 0.5 * ((b + 2) * std::exp(-b) - a * b);
    };
    bool closed_ok = true;
    for (const double r : {-0.1, 0., 0.3 * b, b, 2 * b, 1., 5.})
      closed_ok &= std::abs(law.remainder(r) - penalty * dj(r)) <=
                     1e-14 * penalty * (1 + std::abs(dj(r))) &&
                   std::abs(law.remainder_primitive(r) - penalty * j(r)) <=
                     1e-14 * penalty * (1 + std::abs(j(r)));

    // continuity at b (one-sided limits) and the peak a + e^{-b}
    const double e      = 1e-12;
    const double jump_p = std::abs(law.remainder(b - e) - law.remainder(b));
    const double jump_P =
      std::abs(law.remainder_primitive(b - e) - law.remainder_primitive(b));
    const bool continuous =
      jump_p < 1e-9 * penalty && jump_P < 1e-9 * penalty &&
      std::abs(law.remainder(b) - penalty * (a + std::exp(-b))) <
        1e-14 * penalty;

    // P' = p and p' against central differences, away from r = 0 and r = b
    bool primitive_ok = true, derivative_ok = true;
    for (double r = 0.0137; r < 3; r += 0.0731)
      {
        if (std::abs(r - b) < 1e-3)
          continue;
        const double h = 1e-6;
        const double dP =
          (law.remainder_primitive(r + h) - law.remainder_primitive(r - h)) /
          (2 * h);
        const double dp =
          (law.remainder(r + h) - law.remainder(r - h)) / (2 * h);
        primitive_ok &= std::abs(dP - law.remainder(r)) <=
                        1e-6 * (1 + std::abs(law.remainder(r)));
        derivative_ok &= std::abs(dp - law.remainder_derivative(r)) <=
                         1e-5 * (1 + std::abs(law.remainder_derivative(r)));
      }

    // alpha = the steepest descent of p (attained just beyond b)
    double steepest = 0;
    for (double r = -0.2; r < 3; r += 1e-4)
      steepest = std::max(steepest,
                          -(law.remainder(r + 1e-4) - law.remainder(r)) / 1e-4);
    const double alpha = law.relaxed_monotonicity_constant();
    const bool   alpha_ok =
      steepest <= alpha * (1 + 1e-9) && steepest >= alpha * (1 - 1e-3);

    std::cout << "  p and P are penalty j' and penalty j: "
              << (closed_ok ? "yes" : "no")
              << "\n  continuous at b with the peak a + e^{-b}: "
              << (continuous ? "yes" : "no")
              << "\n  P' = p (differences): " << (primitive_ok ? "yes" : "no")
              << "\n  p' matches differences: "
              << (derivative_ok ? "yes" : "no")
              << "\n  alpha is the steepest descent of p: "
              << (alpha_ok ? "yes" : "no") << "\n";
  }

  void
  expect_input_error(const std::string &what, const std::function<void()> &f)
  {
    try
      {
        f();
        std::cout << what << ": accepted (WRONG)\n";
      }
    catch (const InputError &)
      {
        std::cout << what << ": rejected\n";
      }
  }
} // namespace

int
main()
{
  check(0.1, 0.1, 1.);
  check(0.1, 0.1, 1024.);
  check(0., 0.3, 3.);

  expect_input_error("a < 0",
                     [] { PenalisedSofteningCompliance(-0.1, 0.1, 1.); });
  expect_input_error("b = 0",
                     [] { PenalisedSofteningCompliance(0.1, 0., 1.); });
  expect_input_error("penalty < 0",
                     [] { PenalisedSofteningCompliance(0.1, 0.1, -1.); });
  expect_input_error("penalty infinite",
                     [] { PenalisedSofteningCompliance(0.1, 0.1, INFINITY); });
}
