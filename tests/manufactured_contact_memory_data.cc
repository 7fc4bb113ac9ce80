// The contact data derived from a manufactured solution with memory in the
// contact (doc/theory.md, section 11.11) against closed forms: the static
// class, u = (x^2 t^2, -(1/2 + x) t), the normal nu = -e_y, a one-term
// Prony kernel b(t) = B exp(-t/tau) in the normal response and the bound
// F_b = (0.4 + 0.6 exp(-s_tau/L)) (0.2 + 0.1 p_nu) with Tresca's law.
// Then u_nu = (1/2 + x) t and u_tau = x^2 t^2 e_x, so
//   N(t) = B (1/2 + x)_+ tau (t - tau (1 - exp(-t/tau))),
//   S(t) = int_0^t |du_tau/ds| ds = x^2 t^2,
// f3 - f2 = (xi_nu + N) nu + F_b u_tau/|u_tau| with xi_nu the law's
// subgradient at u_nu and F_b at p_nu = xi_nu + N and s_tau = S(t); all
// checked to 1e-12, and N = 0 where u_nu < 0.
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
  const double     B = 3.0, tau = 0.4, L = 0.05;
  ParameterHandler prm;
  Parameters       p = read_parameters_from_string(
    prm,
    "subsection problem\n  set class = static\nend\n"
          "subsection normal memory\n  set kernel = prony\n"
          "  set amplitudes = 3\n  set relaxation times = 0.4\nend\n"
          "subsection data\n  set constants = L=0.05\n"
          "  set friction bound = (0.4 + 0.6*exp(-s_tau/L))*(0.2 + 0.1*p_nu)\n"
          "end\n"
          "subsection manufactured solution\n  set enabled = true\n"
          "  set exact displacement = x^2*t^2; -(0.5 + x)*t\n"
          "  set normal multiplier = 0.25\n"
          "  set tangential multiplier = 0.01; 0\nend\n");
  const ExponentialLaw          law(1., 0.5, 2.);
  const TrescaLaw               tresca;
  const ManufacturedSolution<2> m(p, law, tresca);

  const Tensor<1, 2> nu({0., -1.});
  double             err_n = 0, err_s = 0, err_f3 = 0, largest_n = 0;
  for (const double t : {0.3, 0.9, 1.7})
    for (const Point<2> &x : {Point<2>(0.3, 0.2),
                              Point<2>(0.8, 0.0),
                              Point<2>(-0.9, 0.5),
                              Point<2>(-0.6, 0.1)})
      {
        const double u_nu = (0.5 + x[0]) * t, u_tau = x[0] * x[0] * t * t;
        const double N = B * std::max(0.5 + x[0], 0.) * tau *
                         (t - tau * (1 - std::exp(-t / tau)));
        const double S    = u_tau;
        const double xi_n = law.subgradient(u_nu);
        const double bound =
          (0.4 + 0.6 * std::exp(-S / L)) * (0.2 + 0.1 * (xi_n + N));
        const Tensor<1, 2> f3_minus_f2 =
          (xi_n + N) * nu +
          tresca.response(bound, u_tau) * Tensor<1, 2>({1., 0.});

        largest_n = std::max(largest_n, N);
        err_n =
          std::max(err_n, std::abs(m.normal_memory_pressure(x, nu, t) - N));
        err_s  = std::max(err_s, std::abs(m.accumulated_slip(x, nu, t) - S));
        err_f3 = std::max(err_f3,
                          (m.contact_traction(x, nu, t) -
                           m.surface_traction(x, nu, t) - f3_minus_f2)
                            .norm());
      }
  std::cout
    << "N(t) = int b(t - s) (u_nu)_+ ds, closed form (largest N > 0.5): "
    << (err_n < 1e-12 && largest_n > 0.5 ? "yes" : "no")
    << "\nS(t) = int |du_tau/ds| ds, closed form: "
    << (err_s < 1e-12 ? "yes" : "no")
    << "\nf3 - f2 = (xi_nu + N) nu + F_b(p_nu = xi_nu + N, s_tau = S) "
       "u_tau/|u_tau|: "
    << (err_f3 < 1e-12 ? "yes" : "no") << "\n";
  if (err_n >= 1e-12 || err_s >= 1e-12 || err_f3 >= 1e-12)
    std::cout << "errors: N " << err_n << ", S " << err_s << ", f3 " << err_f3
              << "\n";
}
