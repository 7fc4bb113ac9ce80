// The data derived from a manufactured solution with long memory
// (doc/theory.md, section 11.11) against closed forms: the static class,
//   u = (x^2 y t^3, sin(x) cos(y) t^2),
// and a one-term Prony kernel R(t) eps = exp(-t/tau) (2 mu_m eps + lambda_m
// tr(eps) I). The memory integral M(t) = int_0^t R(t - s) eps(u(s)) ds of a
// field s^p E is E' I_p(t), E' = 2 mu_m E + lambda_m tr(E) I, with
//   I_0 = tau (1 - exp(-t/tau)),  I_p = tau (t^p - p I_{p-1}),
// so f0 = -Div(B eps(u) + M), f2 = (B eps(u) + M) nu and f3 - f2 (the
// contact law's part, which the memory does not change) are written out
// by hand below and checked to 1e-12.
#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/friction/tresca.h>
#include <hemicontact/laws/normal/exponential_law.h>
#include <hemicontact/verification/manufactured_solution.h>

#include <cmath>
#include <iostream>

using namespace hemicontact;

namespace
{
  /** int_0^t exp(-(t - s)/tau) s^p ds. */
  double
  memory_weight(const unsigned int p, const double t, const double tau)
  {
    return p == 0 ? tau * (1 - std::exp(-t / tau)) :
                    tau * (std::pow(t, p) - p * memory_weight(p - 1, t, tau));
  }
} // namespace

int
main()
{
  const double     me = 2.1, le = 1.7, mm = 0.6, lm = 0.9, tau = 0.5;
  ParameterHandler prm;
  Parameters       p = read_parameters_from_string(
    prm,
    "subsection problem\n  set class = static\nend\n"
          "subsection material\n"
          "  subsection elasticity\n    set mu = 2.1\n    set lambda = 1.7\n  end\n"
          "end\n"
          "subsection relaxation\n  set kernel = prony\n"
          "  set mu amplitudes = 0.6\n  set lambda amplitudes = 0.9\n"
          "  set relaxation times = 0.5\nend\n"
          "subsection data\n  set constants = F=0.8\n  set friction bound = F\nend\n"
          "subsection manufactured solution\n  set enabled = true\n"
          "  set exact displacement = x^2*y*t^3; sin(x)*cos(y)*t^2\n"
          "  set normal multiplier = 0.25 + 0*x\n"
          "  set tangential multiplier = 0.3; 0.1\nend\n");
  const ExponentialLaw          law(1., 0.5, 2.);
  const TrescaLaw               tresca;
  const ManufacturedSolution<2> m(p, law, tresca);
  // the same solution without memory: f3 - f2 must not change
  ParameterHandler prm_elastic;
  Parameters       p_elastic = read_parameters_from_string(
    prm_elastic,
    "subsection problem\n  set class = static\nend\n"
          "subsection material\n"
          "  subsection elasticity\n    set mu = 2.1\n    set lambda = 1.7\n  end\n"
          "end\n"
          "subsection data\n  set constants = F=0.8\n  set friction bound = F\nend\n"
          "subsection manufactured solution\n  set enabled = true\n"
          "  set exact displacement = x^2*y*t^3; sin(x)*cos(y)*t^2\n"
          "  set normal multiplier = 0.25 + 0*x\n"
          "  set tangential multiplier = 0.3; 0.1\nend\n");
  const ManufacturedSolution<2> m_elastic(p_elastic, law, tresca);

  const Tensor<2, 2> I   = unit_symmetric_tensor<2>();
  const auto         eps = [](const Tensor<2, 2> &g) {
    return 0.5 * (g + transpose(g));
  };
  double err_f0 = 0, err_f2 = 0, err_f3 = 0, memory_share = 0;
  for (const double t : {0.3, 0.9, 1.7})
    for (const Point<2> &x :
         {Point<2>(0.2, 0.7), Point<2>(0.9, 0.1), Point<2>(-0.5, 1.3)})
      {
        const double X = x[0], Y = x[1], sx = std::sin(X), cx = std::cos(X),
                     sy = std::sin(Y), cy = std::cos(Y);
        // grad u = t^3 G3 + t^2 G2
        Tensor<2, 2> G3, G2;
        G3[0][0] = 2 * X * Y;
        G3[0][1] = X * X;
        G2[1][0] = cx * cy;
        G2[1][1] = -sx * sy;
        // lap and grad div of the two parts
        const Tensor<1, 2> lap3({2 * Y, 0}), lap2({0, -2 * sx * cy});
        const Tensor<1, 2> grad_div3({2 * Y, 2 * X}),
          grad_div2({-cx * sy, -sx * cy});
        const auto isotropic_divergence = [](const Tensor<1, 2> &lap,
                                             const Tensor<1, 2> &grad_div,
                                             const double        mu,
                                             const double        lambda) {
          return mu * lap + (mu + lambda) * grad_div;
        };
        const auto isotropic_stress =
          [&](const Tensor<2, 2> &g, const double mu, const double lambda) {
            return Tensor<2, 2>(2 * mu * eps(g) + lambda * trace(g) * I);
          };
        const double t3 = t * t * t, t2 = t * t;
        const double I3          = memory_weight(3, t, tau),
                     I2          = memory_weight(2, t, tau);
        const Tensor<2, 2> sigma = isotropic_stress(t3 * G3 + t2 * G2, me, le) +
                                   isotropic_stress(I3 * G3 + I2 * G2, mm, lm);
        const Tensor<1, 2> div_sigma =
          isotropic_divergence(t3 * lap3 + t2 * lap2,
                               t3 * grad_div3 + t2 * grad_div2,
                               me,
                               le) +
          isotropic_divergence(I3 * lap3 + I2 * lap2,
                               I3 * grad_div3 + I2 * grad_div2,
                               mm,
                               lm);
        const Tensor<1, 2> f0 = -div_sigma;
        const Tensor<1, 2> n({0.6, -0.8});
        err_f0 =
          std::max(err_f0, (m.body_force(x, t) - f0).norm() / (1 + f0.norm()));
        err_f2 = std::max(err_f2,
                          (m.surface_traction(x, n, t) - sigma * n).norm() /
                            (1 + (sigma * n).norm()));
        err_f3 = std::max(err_f3,
                          ((m.contact_traction(x, n, t) -
                            m.surface_traction(x, n, t)) -
                           (m_elastic.contact_traction(x, n, t) -
                            m_elastic.surface_traction(x, n, t)))
                            .norm());
        memory_share =
          std::max(memory_share,
                   (m.body_force(x, t) - m_elastic.body_force(x, t)).norm() /
                     f0.norm());
      }
  std::cout << "the memory changes f0 (by more than 1%): "
            << (memory_share > 0.01 ? "yes" : "no")
            << "\nbody force f0 = -Div(B eps(u) + M) exact: "
            << (err_f0 < 1e-12 ? "yes" : "no")
            << "\nsurface traction (B eps(u) + M) nu exact: "
            << (err_f2 < 1e-12 ? "yes" : "no")
            << "\nf3 - f2 the same as without memory: "
            << (err_f3 < 1e-12 ? "yes" : "no") << "\n";
}
