// Unit test of the node-wise pieces for laws with breakpoints and a wall
// (doc/theory.md section 10): the hold points of a node, the branch and held
// value along the path q = s + c w_nu, the complementarity function (zero
// exactly at consistent states), the wall's reaction, the linearised force
// of a free segment, and the laws' pieces: staircase, remainder continuity
// at an upward jump, P' = p, the subdifferential at a kink, alpha = inf
// for a downward jump, and the refusals of badly ordered breakpoints and a
// negative penetration limit.
#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/friction/tresca.h>
#include <hemicontact/laws/normal/finite_penetration_law.h>
#include <hemicontact/laws/normal/piecewise_linear_law.h>
#include <hemicontact/laws/normal/signorini_law.h>
#include <hemicontact/model/contact_node.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>

using namespace hemicontact;

namespace
{
  const char *
  name(const NormalBranch b)
  {
    switch (b)
      {
        case NormalBranch::separating:
          return "separating";
        case NormalBranch::stick:
          return "stick";
        case NormalBranch::damped:
          return "damped";
        case NormalBranch::breakpoint:
          return "breakpoint";
        default:
          return "wall";
      }
  }

  ContactNode<2>
  make_node(const double upper_limit)
  {
    ContactNode<2> node;
    node.normal[0]   = 0.6;
    node.normal[1]   = -0.8;
    node.mass        = 0.5;
    node.c           = 10;
    node.upper_limit = upper_limit;
    return node;
  }

  /** Branch, held value and C_nu at (s, w_nu). */
  void
  print_state(const ContactNode<2> &node,
              const NormalLaw      &law,
              const double          s,
              const double          w)
  {
    NodeState<2> m;
    m.s                           = s;
    m.w_normal                    = w;
    const nodal::NormalHold hold  = nodal::normal_hold(node, m, law);
    const double            c_val = nodal::normal_complementarity(node, m, law);
    std::cout << "  s = " << s << ", w_nu = " << w << ": " << name(hold.branch)
              << " (held " << hold.value
              << "), C_nu = " << (std::abs(c_val) < 1e-14 ? 0. : c_val) << "\n";
  }

  template <class F>
  void
  expect_input_error(const std::string &what, F f)
  {
    try
      {
        f();
        std::cout << what << ": accepted (WRONG)\n";
      }
    catch (const InputError &e)
      {
        std::cout << what << ": refused\n";
      }
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(6);
  // jump a = 0.5 at 0, rise to 1 at r = 0.1, jump up to 2 there, flat, jump
  // down to 0.5 at r = 0.2
  const PiecewiseLinearLaw law(
    {{0, 0.5}, {0.1, 1}, {0.1, 2}, {0.2, 2}, {0.2, 0.5}});
  std::cout << "kinks:";
  for (const NormalLaw::Kink &k : law.kinks())
    std::cout << " (" << k.position << ", " << k.jump << ")";
  std::cout << "\nalpha = " << law.relaxed_monotonicity_constant() << "\n";
  std::cout << "staircase / remainder / subgradient:\n";
  for (const double r : {-0.1, 0., 0.05, 0.099, 0.1, 0.15, 0.2, 0.3})
    std::cout << "  r = " << r << ": " << law.staircase(r) << " / "
              << law.remainder(r) << " / " << law.subgradient(r) << "\n";
  const auto sd = law.subdifferential(0.1);
  std::cout << "subdifferential at 0.1: [" << sd.first << ", " << sd.second
            << "]\n";
  // P' = p + staircase, and j continuous (finite differences)
  double worst = 0;
  for (double r = 0.003; r < 0.3; r += 0.0071)
    {
      const double h  = 1e-7;
      const double fd = (law.potential(r + h) - law.potential(r - h)) / (2 * h);
      worst           = std::max(worst, std::abs(fd - law.subgradient(r)));
    }
  std::cout << "j' = response (finite differences away from kinks): "
            << (worst < 1e-6 ? "yes" : "NO") << "\n";
  std::cout << "j continuous at the jumps: "
            << (std::abs(law.potential(0.1 + 1e-12) - law.potential(0.1)) <
                      1e-10 &&
                    std::abs(law.potential(0.2 + 1e-12) - law.potential(0.2)) <
                      1e-10 ?
                  "yes" :
                  "NO")
            << "\n";

  // a node without wall: hold points at 0 and 0.1
  {
    const ContactNode<2> node =
      make_node(std::numeric_limits<double>::infinity());
    std::cout << "hold points without wall:";
    for (const nodal::HoldPoint &p : nodal::hold_points(node, law))
      std::cout << " [" << p.position << ": " << p.lower << ", " << p.upper
                << ", " << name(p.branch) << "]";
    std::cout << "\nconsistent states (C_nu = 0) and inconsistent ones:\n";
    print_state(node, law, 0., -0.01); // separating
    print_state(node, law, 0.3, 0.);   // stick, s in [0, 0.5]
    print_state(node, law, 0.5, 0.05); // free between 0 and 0.1
    print_state(node, law, 1.1, 0.1);  // at the breakpoint, s in [0.5, 1.5]
    print_state(node, law, 1.5, 0.15); // free beyond 0.1
    print_state(node, law, 0.5, 0.2);  // q = 2.5: at the breakpoint, C != 0
    print_state(node, law, 0.2, 0.1);  // q = 1.2: free below 0.1, C != 0
  }

  // a node with a wall at 0.15: hold points at 0, 0.1 and the wall
  {
    ContactNode<2> node = make_node(0.15);
    std::cout << "hold points with the wall at 0.15:";
    for (const nodal::HoldPoint &p : nodal::hold_points(node, law))
      std::cout << " [" << p.position << ": " << p.lower << ", " << p.upper
                << ", " << name(p.branch) << "]";
    std::cout << "\n";
    print_state(node, law, 1.5, 0.12); // free between 0.1 and the wall
    print_state(node, law, 4., 0.15);  // at the wall, s >= 1.5
    print_state(node, law, 1.5, 0.3);  // beyond the wall: held there
    node.normal_branch = NormalBranch::wall;
    // -sigma_nu = staircase 1.5 + p(0.15) + reaction 2
    std::cout << "wall reaction: "
              << nodal::wall_reaction(node, 1.5 + law.remainder(0.15) + 2, law)
              << "\n";
    // the force of a free segment: the staircase's value plus p
    node.normal_branch = NormalBranch::damped;
    NodeState<2> m;
    m.s        = 1.5;
    m.w_normal = 0.12;
    const NodeLinearization<2> lin =
      nodal::linearize(node, m, law, TrescaLaw());
    std::cout << "free-segment force . nu / m: "
              << lin.force * node.normal / node.mass << " (response "
              << law.subgradient(0.12) << ")\n";
  }

  // walls at or below zero (velocity classes: u_nu at or beyond g)
  for (const double limit : {0., -0.05})
    {
      const ContactNode<2> node = make_node(limit);
      const SignoriniLaw   signorini(0.);
      std::cout << "Signorini, upper limit " << limit << ":";
      for (const nodal::HoldPoint &p : nodal::hold_points(node, signorini))
        std::cout << " [" << p.position << ": " << p.lower << ", " << p.upper
                  << ", " << name(p.branch) << "]";
      std::cout << "\n";
      print_state(node, signorini, 0., limit - 0.01);
      print_state(node, signorini, 3., limit);
    }

  // the laws with a wall
  {
    const FinitePenetrationLaw compliance(10., 0.1);
    std::cout << "finite penetration: g = " << compliance.penetration_limit()
              << ", p(0.05) = " << compliance.subgradient(0.05)
              << ", j(0.05) = " << compliance.potential(0.05) << "\n";
  }
  expect_input_error("breakpoints out of order", [] {
    PiecewiseLinearLaw({{0, 1}, {0.2, 1}, {0.1, 1}});
  });
  expect_input_error("three breakpoints at one r", [] {
    PiecewiseLinearLaw({{0, 1}, {0.1, 1}, {0.1, 2}, {0.1, 0}});
  });
  expect_input_error("two breakpoints at r = 0", [] {
    PiecewiseLinearLaw({{0, 1}, {0, 2}});
  });
  expect_input_error("negative penetration limit", [] { SignoriniLaw(-0.1); });
  expect_input_error("negative penetration limit (compliance)",
                     [] { FinitePenetrationLaw(1., -1e-3); });
}
