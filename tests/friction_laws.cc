// Unit test of every friction law (doc/theory.md section 7): r(0) = 0,
// r' against a difference quotient of r and R against a quadrature of r at
// and around every kink, F = F_b + r >= 0, alpha_tau >= -r' and sharp, the
// vector relaxed monotonicity of dphi(v) = d(F_b|v|) + r(|v|) v/|v| on a
// grid in 2D, the input checks, and the laws built through the registry
// from a parameter file. Then node-level checks of the friction disk with
// a remainder in 3D: the multipliers take the remainder off, the
// complementarity vanishes at the law's contact force, the slip
// linearisation equals the Jacobian of that force, and the nodal energy's
// gradient is that force.
#include <deal.II/base/symmetric_tensor.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/friction/piecewise_linear_friction.h>
#include <hemicontact/laws/friction/rational_weakening.h>
#include <hemicontact/laws/friction/slip_rate_weakening.h>
#include <hemicontact/laws/friction/tresca.h>
#include <hemicontact/laws/friction_law.h>
#include <hemicontact/laws/normal/no_normal_resistance.h>
#include <hemicontact/model/contact_node.h>

#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <vector>

using namespace hemicontact;

namespace
{
  const char *
  yes(const bool b)
  {
    return b ? "yes" : "no";
  }

  void
  check_law(const FrictionLaw         &law,
            const double               bound,
            const std::vector<double> &kinks)
  {
    const double alpha = law.relaxed_monotonicity_constant(bound);
    std::cout << "law '" << law.name() << "', F_b = " << bound
              << ": alpha_tau = " << alpha << "\n";

    std::vector<double> points = {0., 1e-3, 0.02, 0.3, 3.};
    for (const double s : kinks)
      for (const double d : {-1e-3, 0., 1e-3})
        if (s + d >= 0)
          points.push_back(s + d);
    for (const double s : {0., 0.05, 0.2, 1.})
      std::cout << "  s = " << s << ": F = " << law.response(bound, s)
                << ", r = " << law.remainder(bound, s)
                << ", r' = " << law.remainder_derivative(bound, s)
                << ", phi = " << law.potential(bound, s) << "\n";

    bool derivative_ok = true, primitive_ok = true, force_ok = true;
    for (const double s : points)
      {
        const double h = 1e-7;
        const double fd =
          (law.remainder(bound, s + h) - law.remainder(bound, s)) / h;
        bool near_kink = false;
        for (const double k : kinks)
          near_kink |= std::abs(s - k) < 2 * h;
        if (!near_kink && std::abs(fd - law.remainder_derivative(bound, s)) >
                            1e-5 * (1 + std::abs(fd)))
          derivative_ok = false;

        const unsigned int n        = 100000;
        double             integral = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            const double s0 = s * i / n, s1 = s * (i + 1) / n;
            integral += 0.5 *
                        (law.remainder(bound, s0) + law.remainder(bound, s1)) *
                        (s1 - s0);
          }
        if (std::abs(integral - law.remainder_primitive(bound, s)) > 1e-8)
          primitive_ok = false;
        if (law.response(bound, s) < 0 ||
            std::abs(law.potential(bound, s) -
                     (bound * s + law.remainder_primitive(bound, s))) > 1e-14)
          force_ok = false;
      }
    std::cout << "  r(0) = 0: " << yes(law.remainder(bound, 0.) == 0.) << "\n"
              << "  r' matches difference quotients: " << yes(derivative_ok)
              << "\n"
              << "  R matches the integral of r: " << yes(primitive_ok) << "\n"
              << "  F >= 0 and phi = F_b s + R: " << yes(force_ok) << "\n";

    // alpha_tau >= -r' everywhere, and attained (sharp) up to the grid
    double steepest = 0;
    for (double s = 0; s <= 4; s += 1e-3)
      steepest = std::max(steepest, -law.remainder_derivative(bound, s));
    std::cout << "  alpha_tau >= -r': " << yes(alpha >= steepest - 1e-12)
              << ", sharp: " << yes(alpha <= steepest + 1e-9) << "\n";

    // vector relaxed monotonicity in 2D: (xi1 - xi2).(v1 - v2) >=
    // -alpha |v1 - v2|^2 with xi in dphi(v); at v = 0 the extreme points of
    // the disk of radius F_b
    bool       monotone_ok = true;
    const auto xi          = [&](const Tensor<1, 2> &v) {
      std::vector<Tensor<1, 2>> result;
      const double              s = v.norm();
      if (s == 0)
        for (double q = 0; q < 6.28; q += 0.7854)
          result.push_back(bound * Tensor<1, 2>({std::cos(q), std::sin(q)}));
      else
        result.push_back(law.response(bound, s) / s * v);
      return result;
    };
    std::vector<Tensor<1, 2>> grid;
    for (double s : {0., 0.01, 0.03, 0.07, 0.15, 0.4, 1.2})
      for (double q = 0; q < 6.28; q += 0.5236)
        grid.push_back(s * Tensor<1, 2>({std::cos(q), std::sin(q)}));
    for (const auto &v1 : grid)
      for (const auto &v2 : grid)
        if ((v1 - v2).norm() > 0)
          for (const auto &x1 : xi(v1))
            for (const auto &x2 : xi(v2))
              {
                const double d2 = (v1 - v2).norm_square();
                const double q  = (x1 - x2) * (v1 - v2) / d2;
                if (q < -alpha - 1e-9)
                  monotone_ok = false;
              }
    std::cout << "  relaxed monotone with alpha_tau (2D grid): "
              << yes(monotone_ok) << "\n";
  }

  void
  expect_input_error(const std::function<void()> &f)
  {
    try
      {
        f();
        std::cout << "  NOT rejected\n";
      }
    catch (const InputError &e)
      {
        std::cout << "  rejected: " << e.what() << "\n";
      }
  }

  /** The law's nodal contact force m (F(|w_t|) w_t/|w_t|) in 3D. */
  Tensor<1, 3>
  friction_force(const ContactNode<3> &node,
                 const FrictionLaw    &law,
                 const Tensor<1, 3>   &w)
  {
    const Tensor<1, 3> wt = w - (w * node.normal) * node.normal;
    return node.mass * law.response(node.friction_bound, wt.norm()) /
           wt.norm() * wt;
  }

  void
  check_node(const FrictionLaw &law)
  {
    std::cout << "node with law '" << law.name() << "' (3D, oblique normal)\n";
    ContactNode<3> node;
    node.normal = Tensor<1, 3>({0.3, -0.2, 0.9});
    node.normal /= node.normal.norm();
    node.mass           = 0.7;
    node.friction_bound = 0.8;
    node.c              = 5.;
    const NoNormalResistance none;

    // a slipping velocity with no normal part and the exact contact force
    const auto         t     = nodal::tangent_basis(node.normal);
    Tensor<1, 3>       w     = 0.12 * t[0] - 0.05 * t[1];
    const Tensor<1, 3> force = friction_force(node, law, w);
    const NodeState<3> m     = nodal::state(node, w, force, none, law);
    const Tensor<1, 3> e     = m.w_tangential / m.w_tangential.norm();
    std::cout << "  multiplier of the convex part = F_b e: "
              << yes((m.lambda - node.friction_bound * e).norm() < 1e-14)
              << "\n"
              << "  tangential complementarity vanishes: "
              << yes(nodal::tangential_complementarity(node, m).norm() < 1e-14)
              << ", branch slip: "
              << yes(nodal::tangential_branch(node, m) ==
                     TangentialBranch::slip)
              << "\n";

    // the slip linearisation at the solution: the force itself, and the
    // Jacobian of the force in the tangent plane
    node.tangential_branch               = TangentialBranch::slip;
    node.normal_branch                   = NormalBranch::separating;
    const NodeLinearization<3> lin       = nodal::linearize(node, m, none, law);
    Tensor<2, 3>               projector = unit_symmetric_tensor<3>();
    projector -= outer_product(node.normal, node.normal);
    Tensor<2, 3> jacobian;
    for (unsigned int j = 0; j < 3; ++j)
      {
        Tensor<1, 3> dw;
        dw[j]                     = 1e-6;
        const Tensor<1, 3> column = (friction_force(node, law, w + dw) -
                                     friction_force(node, law, w - dw)) /
                                    2e-6;
        for (unsigned int i = 0; i < 3; ++i)
          jacobian[i][j] = column[i];
      }
    const double block_error =
      (projector * lin.matrix * projector - projector * jacobian * projector)
        .norm() /
      jacobian.norm();
    std::cout << "  linearised force at the solution = the force: "
              << yes((lin.force - force).norm() < 1e-12 * force.norm()) << "\n"
              << "  slip matrix = Jacobian of the force: "
              << yes(block_error < 1e-7) << "\n";

    // the nodal energy's gradient is the force
    Tensor<1, 3> gradient;
    for (unsigned int j = 0; j < 3; ++j)
      {
        Tensor<1, 3> dw;
        dw[j]       = 1e-6;
        gradient[j] = (nodal::energy(node, w + dw, none, law) -
                       nodal::energy(node, w - dw, none, law)) /
                      2e-6;
      }
    std::cout << "  gradient of the nodal energy = the force: "
              << yes((gradient - force).norm() < 1e-7 * force.norm()) << "\n";

    // the work rate booked in the energy balance is xi . w = m F(s) s
    const auto work = nodal::contact_work(node, w, 0., none, law);
    std::cout << "  friction work = m F(s) s: "
              << yes(std::abs(work.second - force * w) < 1e-14) << "\n";
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(6);
  check_law(TrescaLaw(), 0.6, {});
  check_law(SlipRateWeakeningLaw(0.6, 0.3, 0.1), 0.6, {});
  check_law(SlipRateWeakeningLaw(0.5, 0.5, 0.2), 0.9, {});
  // weakening, then strengthening, then constant
  check_law(PiecewiseLinearFrictionLaw({{0.05, 0.6}, {0.5, 0.8}}),
            0.7,
            {0., 0.05, 0.5});
  check_law(PiecewiseLinearFrictionLaw({{0, 1}, {0.1, 1.4}, {0.3, 0.2}}),
            1.,
            {0., 0.1, 0.3});
  check_law(RationalWeakeningLaw(0.5), 0.8, {});

  std::cout << "input checks\n";
  expect_input_error([] { SlipRateWeakeningLaw(0.6, 0.8, 0.1); });
  expect_input_error([] { SlipRateWeakeningLaw(0.6, 0., 0.1); });
  expect_input_error([] { SlipRateWeakeningLaw(0.6, 0.3, 0.); });
  expect_input_error([] { SlipRateWeakeningLaw(-1, -2, 0.1); });
  expect_input_error([] { PiecewiseLinearFrictionLaw({}); });
  expect_input_error([] { PiecewiseLinearFrictionLaw({{0, 0.9}, {1, 1}}); });
  expect_input_error([] { PiecewiseLinearFrictionLaw({{0.2, 1}, {0.1, 1}}); });
  expect_input_error([] { PiecewiseLinearFrictionLaw({{0.2, -0.1}}); });
  expect_input_error([] { RationalWeakeningLaw(0.); });

  std::cout << "registry\n";
  for (const FrictionLawEntry &e : friction_law_registry())
    std::cout << "  '" << e.name << "'\n";
  {
    ParameterHandler prm;
    declare_friction_law_parameters(prm);
    prm.parse_input_from_string(
      "subsection friction law\n  set law = slip rate weakening\n"
      "  subsection slip rate weakening\n    set static coefficient = 0.5\n"
      "    set dynamic coefficient = 0.25\n"
      "    set characteristic slip speed = 0.2\n  end\nend\n");
    const std::unique_ptr<FrictionLaw> law = create_friction_law(prm);
    std::cout << "  from a parameter file: '" << law->name()
              << "', alpha_tau(F_b = 1) = "
              << law->relaxed_monotonicity_constant(1.) << "\n";
  }
  {
    ParameterHandler prm;
    declare_friction_law_parameters(prm);
    prm.parse_input_from_string(
      "subsection friction law\n  set law = piecewise linear\n"
      "  subsection piecewise linear\n"
      "    set response breakpoints = 0.1:0.5, 0.2:0.5\n  end\nend\n");
    const std::unique_ptr<FrictionLaw> law = create_friction_law(prm);
    std::cout << "  from a parameter file: '" << law->name()
              << "', F(0.05) at F_b = 2: " << law->response(2., 0.05) << "\n";
  }

  check_node(TrescaLaw());
  check_node(SlipRateWeakeningLaw(0.6, 0.3, 0.1));
  check_node(PiecewiseLinearFrictionLaw({{0.05, 0.6}, {0.5, 0.8}}));
  check_node(RationalWeakeningLaw(0.5));
  return 0;
}
