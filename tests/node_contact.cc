// Unit test of the node-wise pieces of the active-set method: branch
// decisions and complementarity functions at and around the kinks
// (s + c w_nu = 0 and = a, |lambda + c w_tau| = F_b), the Tresca projection
// onto the friction disk, the elimination of constrained directions, the
// tangent basis, the slip linearisation against a difference quotient, and
// the gradual normal branch changes (separating <-> damped via stick).
#include <deal.II/base/symmetric_tensor.h>

#include <hemicontact/laws/friction/tresca.h>
#include <hemicontact/laws/friction_disk.h>
#include <hemicontact/laws/normal/exponential_law.h>
#include <hemicontact/laws/normal/linear_damping_law.h>
#include <hemicontact/model/contact_node.h>

#include <cmath>
#include <iomanip>
#include <iostream>

using namespace hemicontact;

namespace
{
  const char *
  name(const NormalBranch b)
  {
    return b == NormalBranch::separating ? "separating" :
           b == NormalBranch::stick      ? "stick" :
                                           "damped";
  }
  const char *
  name(const TangentialBranch b)
  {
    return b == TangentialBranch::stick ? "stick" : "slip";
  }

  /** min of v.Mv over a grid of directions on the unit sphere */
  double
  min_quadratic_form(const Tensor<2, 3> &m)
  {
    double result = 1e300;
    for (double theta = 0; theta < M_PI; theta += M_PI / 40)
      for (double phi = 0; phi < 2 * M_PI; phi += M_PI / 40)
        {
          const Tensor<1, 3> v({std::sin(theta) * std::cos(phi),
                                std::sin(theta) * std::sin(phi),
                                std::cos(theta)});
          result = std::min(result, v * (m * v));
        }
    return result;
  }

  template <int dim>
  ContactNode<dim>
  make_node()
  {
    ContactNode<dim> node;
    node.normal          = Tensor<1, dim>();
    node.normal[dim - 1] = -1; // bottom face
    if (dim == 2)
      { // a tilted normal exercises the general case
        node.normal[0] = 0.6;
        node.normal[1] = -0.8;
      }
    node.mass           = 0.5;
    node.friction_bound = 0.3;
    node.c              = 10;
    return node;
  }
} // namespace

int
main()
{
  std::cout << std::setprecision(6);
  const ExponentialLaw law(1., 0.4, 3.); // a = 1
  ContactNode<2>       node = make_node<2>();

  // normal branches around q = s + c w_nu = 0 and q = a
  std::cout << "normal branches (a = 1, c = 10):\n";
  for (const double s : {-0.2, 0., 0.5, 1., 1.2})
    for (const double wn : {-0.01, 0., 0.01})
      {
        NodeState<2> m;
        m.s        = s;
        m.w_normal = wn;
        std::cout << "  s = " << s << ", w_nu = " << wn << ": "
                  << name(nodal::normal_branch(node, m, law))
                  << ", C_nu = " << nodal::normal_complementarity(node, m, law)
                  << "\n";
      }

  // a Newton iteration's normal branch: separating <-> damped passes through
  // stick for a law with a jump, not for one without
  {
    const LinearDampingLaw no_jump(2.);
    const NormalBranch     all[] = {NormalBranch::separating,
                                    NormalBranch::stick,
                                    NormalBranch::damped};
    std::cout
      << "gradual normal branches (current -> predicted: a = 1 / a = 0):\n";
    for (const NormalBranch current : all)
      for (const NormalBranch predicted : all)
        std::cout << "  " << name(current) << " -> " << name(predicted) << ": "
                  << name(nodal::gradual_normal_branch(current, predicted, law))
                  << " / "
                  << name(nodal::gradual_normal_branch(current,
                                                       predicted,
                                                       no_jump))
                  << "\n";
  }

  // tangential branches around |lambda + c w_tau| = F_b = 0.3
  std::cout << "tangential branches (F_b = 0.3, c = 10):\n";
  const Tensor<1, 2> tau({0.8, 0.6}); // orthogonal to the tilted normal
  for (const double l : {0., 0.29, 0.3, 0.31})
    for (const double wt : {0., 0.001})
      {
        NodeState<2> m;
        m.lambda              = l * tau;
        m.w_tangential        = wt * tau;
        const Tensor<1, 2> ct = nodal::tangential_complementarity(node, m);
        std::cout << "  |lambda| = " << l << ", |w_tau| = " << wt << ": "
                  << name(nodal::tangential_branch(node, m))
                  << ", |C_tau| = " << std::abs(ct * tau) << "\n";
      }

  // the split of velocity and force into normal and tangential parts
  {
    const Tensor<1, 2> w({0.3, 0.1}), force({0.2, -0.5});
    const NodeState<2> m = nodal::state(node, w, force, law, TrescaLaw());
    const double       recombined =
      (node.mass *
         ((m.s + law.remainder(m.w_normal)) * node.normal + m.lambda) -
       force)
        .norm();
    std::cout
      << "split of force and velocity consistent: "
      << (recombined < 1e-14 &&
              std::abs((m.w_normal * node.normal + m.w_tangential - w).norm()) <
                1e-14 &&
              std::abs(m.lambda * node.normal) < 1e-14 ?
            "yes" :
            "no")
      << "\n";
  }

  // Tresca projection in 3D
  {
    const Tensor<1, 3> inside({0.1, 0.1, 0}), outside({0.3, 0.4, 0});
    std::cout << "projection keeps points of the disk: "
              << ((FrictionDisk::project(inside, 0.3) - inside).norm() == 0 ?
                    "yes" :
                    "no")
              << "\nprojection of (0.3, 0.4) onto radius 0.3: "
              << FrictionDisk::project(outside, 0.3) << "\n";
  }

  // the free projector: every projected velocity satisfies the constraints
  for (const auto &branches :
       {std::make_pair(NormalBranch::stick, TangentialBranch::slip),
        std::make_pair(NormalBranch::separating, TangentialBranch::stick),
        std::make_pair(NormalBranch::stick, TangentialBranch::stick)})
    {
      ContactNode<3> n3             = make_node<3>();
      n3.normal                     = Tensor<1, 3>({0.36, 0.48, -0.8});
      n3.normal_branch              = branches.first;
      n3.tangential_branch          = branches.second;
      const auto         directions = nodal::constrained_directions(n3);
      const Tensor<2, 3> pi         = nodal::free_projector(n3);
      const Tensor<1, 3> w          = pi * Tensor<1, 3>({0.7, -1.3, 0.4});
      // a projector: Pi Pi = Pi
      double violation = (pi * pi - pi).norm();
      for (const auto &d : directions)
        violation = std::max(violation, std::abs(d * w));
      std::cout << "3D " << name(branches.first) << "/" << name(branches.second)
                << ": " << directions.size() << " constraints, satisfied: "
                << (violation < 1e-14 ? "yes" : "no") << "\n";
    }

  // tangent basis is orthonormal and orthogonal to the normal
  {
    const Tensor<1, 3> nu({0.36, 0.48, -0.8});
    const auto         t = nodal::tangent_basis(nu);
    const double err = std::abs(t[0] * t[0] - 1) + std::abs(t[1] * t[1] - 1) +
                       std::abs(t[0] * t[1]) + std::abs(t[0] * nu) +
                       std::abs(t[1] * nu);
    std::cout << "3D tangent basis orthonormal: "
              << (err < 1e-14 ? "yes" : "no") << "\n";
  }

  // slip linearisation in 3D at a consistent slip state (lambda = F_b t,
  // w_tau = |w_tau| t): the force is m F_b t and the matrix is the Hessian
  // m F_b/|w_tau| (I - nu nu - t t) of m F_b |w_tau| (difference quotient
  // of its gradient m F_b w/|w|); symmetric positive semidefinite
  {
    ContactNode<3> n3    = make_node<3>();
    n3.tangential_branch = TangentialBranch::slip;
    const Tensor<1, 3> t({0.8, 0.6, 0});
    NodeState<3>       m;
    m.lambda                       = n3.friction_bound * t;
    m.w_tangential                 = 0.05 * t;
    const NodeLinearization<3> lin = nodal::linearize(n3, m, law, TrescaLaw());
    const auto                 gradient = [&](const Tensor<1, 3> &wt) {
      return n3.mass * n3.friction_bound * wt / wt.norm();
    };
    double fd_error = 0, asym = 0;
    for (unsigned int j = 0; j < 2; ++j) // tangential directions
      {
        Tensor<1, 3> dw;
        dw[j] = 1e-7;
        const Tensor<1, 3> diff =
          (gradient(m.w_tangential + dw) - gradient(m.w_tangential - dw)) /
          2e-7;
        for (unsigned int i = 0; i < 3; ++i)
          fd_error = std::max(fd_error, std::abs(diff[i] - lin.matrix[i][j]));
      }
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = 0; j < 3; ++j)
        asym = std::max(asym, std::abs(lin.matrix[i][j] - lin.matrix[j][i]));
    // the linearised force at the current iterate is m F_b t
    const Tensor<1, 3> force = lin.force - lin.matrix * m.w_tangential;
    std::cout << "3D slip force at the iterate = " << force
              << "\n3D slip tangent is the Hessian of F_b |w_tau|: "
              << (fd_error < 1e-6 ? "yes" : "no")
              << ", symmetric: " << (asym < 1e-14 ? "yes" : "no")
              << ", positive semidefinite: "
              << (min_quadratic_form(lin.matrix) > -1e-14 ? "yes" : "no")
              << "\n";
  }

  // damped linearisation: force m (a + p(w)) nu, matrix m p'(w) nu nu
  {
    ContactNode<2> n2 = make_node<2>();
    n2.normal_branch  = NormalBranch::damped;
    NodeState<2> m;
    m.w_normal                     = 0.1;
    const NodeLinearization<2> lin = nodal::linearize(n2, m, law, TrescaLaw());
    const double expect = n2.mass * (law.jump() + law.remainder(0.1));
    std::cout << "damped force along the normal: "
              << (std::abs(lin.force * n2.normal - expect) < 1e-14 ? "yes" :
                                                                     "no")
              << ", matrix = m p' nu nu: "
              << (std::abs(n2.normal * (lin.matrix * n2.normal) -
                           n2.mass * law.remainder_derivative(0.1)) < 1e-14 ?
                    "yes" :
                    "no")
              << "\n";
  }
}
