// The data derived from a manufactured solution by automatic
// differentiation, against a solution whose data are known in closed form:
//   u = (x^2 y t^3, sin(x) cos(y) t^2),
// so w, dw/dt, grad u, grad w and Div sigma are written out by hand below.
// Checks f0, f2 = sigma nu and the three cases of f3 (w_nu > 0: damped
// response; w_nu < 0: none; w_nu = 0: the given multiplier), to 1e-12.
#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/friction/tresca.h>
#include <hemicontact/laws/normal/exponential_law.h>
#include <hemicontact/verification/manufactured_solution.h>

#include <cmath>
#include <iostream>

using namespace hemicontact;

int
main()
{
  const double     rho = 1.3, mv = 0.7, lv = 0.4, me = 2.1, le = 1.7;
  ParameterHandler prm;
  Parameters       p = read_parameters_from_string(
    prm,
    "subsection material\n  set density = 1.3\n"
          "  subsection viscosity\n    set mu = 0.7\n    set lambda = 0.4\n  end\n"
          "  subsection elasticity\n    set mu = 2.1\n    set lambda = 1.7\n  end\n"
          "end\n"
          "subsection data\n  set constants = F=0.8\n  set friction bound = F\nend\n"
          "subsection manufactured solution\n  set enabled = true\n"
          "  set exact displacement = x^2*y*t^3; sin(x)*cos(y)*t^2\n"
          "  set normal multiplier = 0.25 + 0*x\n"
          "  set tangential multiplier = 0.3; 0.1\nend\n");
  const ExponentialLaw          law(1., 0.5, 2.);
  const TrescaLaw               tresca;
  const ManufacturedSolution<2> m(p, law, tresca);

  double err_f0 = 0, err_f2 = 0, err_u = 0;
  for (const double t : {0.3, 0.9})
    for (const Point<2> &x :
         {Point<2>(0.2, 0.7), Point<2>(0.9, 0.1), Point<2>(-0.5, 1.3)})
      {
        const double X = x[0], Y = x[1], sx = std::sin(X), cx = std::cos(X),
                     sy = std::sin(Y), cy = std::cos(Y);
        // by hand
        const Tensor<1, 2> u({X * X * Y * t * t * t, sx * cy * t * t});
        const Tensor<1, 2> w({3 * X * X * Y * t * t, 2 * sx * cy * t});
        const Tensor<1, 2> w_dot({6 * X * X * Y * t, 2 * sx * cy});
        Tensor<2, 2>       gu, gw;
        gu[0][0] = 2 * X * Y * t * t * t;
        gu[0][1] = X * X * t * t * t;
        gu[1][0] = cx * cy * t * t;
        gu[1][1] = -sx * sy * t * t;
        gw[0][0] = 6 * X * Y * t * t;
        gw[0][1] = 3 * X * X * t * t;
        gw[1][0] = 2 * cx * cy * t;
        gw[1][1] = -2 * sx * sy * t;
        // mu lap v + (mu + lambda) grad div v
        const Tensor<1, 2> lap_u({2 * Y * t * t * t, -2 * sx * cy * t * t});
        const Tensor<1, 2> grad_div_u({2 * Y * t * t * t - cx * sy * t * t,
                                       2 * X * t * t * t - sx * cy * t * t});
        const Tensor<1, 2> lap_w({6 * Y * t * t, -4 * sx * cy * t});
        const Tensor<1, 2> grad_div_w(
          {6 * Y * t * t - 2 * cx * sy * t, 6 * X * t * t - 2 * sx * cy * t});
        const Tensor<1, 2> div_sigma = mv * lap_w + (mv + lv) * grad_div_w +
                                       me * lap_u + (me + le) * grad_div_u;
        const Tensor<1, 2> f0 = rho * w_dot - div_sigma;

        const auto eps = [](const Tensor<2, 2> &g) {
          return 0.5 * (g + transpose(g));
        };
        const Tensor<2, 2> I     = unit_symmetric_tensor<2>();
        const Tensor<2, 2> sigma = 2 * mv * eps(gw) + lv * trace(gw) * I +
                                   2 * me * eps(gu) + le * trace(gu) * I;
        const Tensor<1, 2> n({0.6, -0.8});

        const auto v = m.evaluate(x, t);
        err_u        = std::max({err_u,
                                 (v.u - u).norm(),
                                 (v.w - w).norm(),
                                 (v.grad_u - gu).norm(),
                                 (v.grad_w - gw).norm()});
        err_f0 =
          std::max(err_f0, (m.body_force(x, t) - f0).norm() / (1 + f0.norm()));
        err_f2 = std::max(err_f2,
                          (m.surface_traction(x, n, t) - sigma * n).norm() /
                            (1 + (sigma * n).norm()));
      }
  std::cout << "u, w, grad u, grad w exact: " << (err_u < 1e-12 ? "yes" : "no")
            << "\nbody force f0 = rho dw/dt - Div sigma exact: "
            << (err_f0 < 1e-12 ? "yes" : "no")
            << "\nsurface traction sigma nu exact: "
            << (err_f2 < 1e-12 ? "yes" : "no") << "\n";

  // contact traction: sigma nu + xi_nu nu + xi_tau, three normal cases
  const double t              = 0.5;
  const auto   f3_minus_sigma = [&](const Point<2> &x, const Tensor<1, 2> &n) {
    return m.contact_traction(x, n, t) - m.surface_traction(x, n, t);
  };
  {
    // w = (3 x^2 y t^2, 2 sin x cos y t); at (0.5, 0.4) with n = (0, 1):
    // w_nu = w_y > 0 -> damped: xi_nu = (a-b) exp(-beta w_nu) + b;
    // w_tau = w_x e_x != 0 -> xi_tau = F_b sign(w_x) e_x
    const Point<2>     x(0.5, 0.4);
    const Tensor<1, 2> n({0., 1.});
    const double       wy = 2 * std::sin(0.5) * std::cos(0.4) * t;
    const Tensor<1, 2> expected({0.8, 0.5 * std::exp(-2 * wy) + 0.5});
    std::cout << "f3 with w_nu > 0 (damped) and w_tau != 0 (slip): "
              << ((f3_minus_sigma(x, n) - expected).norm() < 1e-12 ? "yes" :
                                                                     "no")
              << "\n";
    // n = (0, -1): w_nu < 0 -> separating, xi_nu = 0; slip as before
    const Tensor<1, 2> expected2({0.8, 0.});
    std::cout << "f3 with w_nu < 0 (separating): "
              << ((f3_minus_sigma(x, -n) - expected2).norm() < 1e-12 ? "yes" :
                                                                       "no")
              << "\n";
  }
  {
    // at x = 0: w = 0 -> the given multipliers: xi_nu = 0.25, xi_tau = the
    // tangential part of (0.3, 0.1)
    const Point<2>     x(0., 0.4);
    const Tensor<1, 2> n({0., 1.});
    const Tensor<1, 2> expected({0.3, 0.25});
    std::cout << "f3 with w = 0 (given multipliers): "
              << ((f3_minus_sigma(x, n) - expected).norm() < 1e-12 ? "yes" :
                                                                     "no")
              << "\n";
  }
}
