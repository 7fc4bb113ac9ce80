// One time step with the slip-rate weakening friction law whose exact
// discrete answer is known in closed form (as in one_step_exact.cc): a
// block clamped on top, in contact at the bottom, loaded so that the exact
// velocity w = V (1 - y/H) e lies in the finite element space. The bottom
// slips at speed V, where the law's friction force is
//   F(V) = F_b (mu_d + (mu_s - mu_d) exp(-V/v0)) / mu_s,
// so the contact traction f3 that makes w exact carries F(V), not F_b. With
// a bound from the normal state the block starts pressed into the
// foundation, u0 = -d (1 - y) e_y (so u_nu = d at the bottom), and the bound
// is F_b = Fb + cp u_nu; the constant elastic prestress of u0 enters the
// side tractions and f3. A stick case checks that the static bound holds
// where the block does not move. 2D and 3D (slip in an oblique direction,
// on the friction disk), hexahedra and simplices.
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/contact_problem.h>

#include <cmath>
#include <sstream>

#include "one_step_block.h"
#include "tests.h"

using namespace hemicontact;

namespace
{
  const double rho = 2, mu_v = 1.5, lambda_v = 0.7, mu_e = 10, lambda_e = 5,
               k = 0.1, V = 0.3, Fb = 0.4, a = 1, H = 1, mu_s = 0.6, mu_d = 0.3,
               v0 = 0.5, cp = 3, d = 0.02;

  /** The law's friction force at slip speed V for the bound @p bound. */
  double
  friction_force(const double bound)
  {
    return bound * (mu_d + (mu_s - mu_d) * std::exp(-V / v0)) / mu_s;
  }

  std::string cell_type = "hypercube";

  std::string
  parameter_file(const unsigned int dim,
                 const std::string &f0,
                 const std::string &f2,
                 const std::string &f3,
                 const std::string &u0,
                 const std::string &bound)
  {
    std::ostringstream p;
    p << one_step_block(dim,
                        cell_type,
                        {rho, mu_v, lambda_v, mu_e, lambda_e},
                        k)
      << "subsection data\n"
      << "  set constants = V=" << num(V) << ", rho=" << rho << ", k=" << k
      << ", mv=" << mu_v << ", le=" << lambda_e << ", me=" << mu_e
      << ", Fb=" << Fb << ", a=" << a << ", H=" << H << ", cp=" << cp
      << ", d=" << d << "\n"
      << "  set body force = " << f0 << "\n"
      << "  set surface traction = " << f2 << "\n"
      << "  set contact traction = " << f3 << "\n"
      << "  set initial displacement = " << u0 << "\n"
      << "  set friction bound = " << bound << "\nend\n"
      << "subsection normal law\n  set law = exponential\n"
      << "  subsection exponential\n    set a = " << a
      << "\n    set b = 0.4\n    set beta = 3\n  end\nend\n"
      << "subsection friction law\n  set law = slip rate weakening\n"
      << "  subsection slip rate weakening\n    set static coefficient = "
      << mu_s << "\n    set dynamic coefficient = " << mu_d
      << "\n    set characteristic slip speed = " << v0 << "\n  end\nend\n"
      << "subsection nonlinear solver\n  set tolerance = 1e-12\nend\n"
      << "subsection linear solver\n  set relative tolerance = 1e-13\nend\n"
      << "subsection output\n  set terminal = quiet\nend\n";
    return p.str();
  }

  template <int dim>
  void
  check(const std::string &name,
        const std::string &f0,
        const std::string &f2,
        const std::string &f3,
        const std::string &u0,
        const std::string &bound,
        const std::string &exact_w)
  {
    const OneStepResult result =
      one_step<dim>(parameter_file(dim, f0, f2, f3, u0, bound), exact_w, V);
    const StepStatistics &stats = result.stats;
    const double          error = result.error;

    out() << cell_type << " " << name
          << ": relative max error < 1e-9: " << (error < 1e-9 ? "yes" : "no")
          << "; convex: " << (result.convexity_bound > 1 ? "yes" : "no")
          << "; contact nodes sep/stick/damped " << stats.n_separating << "/"
          << stats.n_normal_stick << "/" << stats.n_damped << ", stick/slip "
          << stats.n_stick << "/" << stats.n_slip << std::endl;
    if (error >= 1e-9)
      out() << "  error = " << error << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  for (const std::string type : {"hypercube", "simplex"})
    {
      cell_type              = type;
      const std::string side = "(x < 1e-9 ? -1 : (x > 2 - 1e-9 ? 1 : 0))";

      // slip at speed V with a constant bound: F(V) < F_b at the bottom
      check<2>("slip, bound Fb",
               "rho/k*V*(1-y/H); 0",
               "0; -" + side + "*mv*V/H",
               "mv*V/H + " + num(friction_force(Fb)) + "; -a/2",
               "0",
               "Fb",
               "V*(1-y); 0");

      // the same with the bound Fb + cp u_nu, the block pressed in by d:
      // u0 = (0, -d(1-y)) has the constant elastic stress
      // sigma_B = le d I + 2 me d e_y e_y: side tractions side*le*d e_x,
      // at the bottom (nu = -e_y) -(le + 2 me) d e_y
      check<2>("slip, bound Fb + cp u_nu",
               "rho/k*V*(1-y/H); 0",
               side + "*le*d; -" + side + "*mv*V/H",
               "mv*V/H + " + num(friction_force(Fb + cp * d)) +
                 "; -a/2 - (le + 2*me)*d",
               "0; -d*(1-y)",
               "Fb + cp*u_nu",
               "V*(1-y); 0");

      // stick under a tangential load below the static bound
      check<2>("stick, bound Fb + cp u_nu",
               "0",
               side + "*le*d; 0",
               "0.9*(Fb + cp*d); -a/2 - (le + 2*me)*d",
               "0; -d*(1-y)",
               "Fb + cp*u_nu",
               "0; 0");

      // 3D: slip along (cos q, sin q), q = 0.6, on the friction disk
      const double      c = std::cos(0.6), s = std::sin(0.6);
      const std::string sx    = "(x < 1e-9 ? -1 : (x > 1 - 1e-9 ? 1 : 0))";
      const std::string sy    = "(y < 1e-9 ? -1 : (y > 1 - 1e-9 ? 1 : 0))";
      const double      force = friction_force(Fb + cp * d);
      check<3>("slip 3D, bound Fb + cp u_nu",
               "rho/k*V*(1-z)*" + num(c) + "; rho/k*V*(1-z)*" + num(s) + "; 0",
               sx + "*le*d; " + sy + "*le*d; -mv*V/H*(" + num(c) + "*" + sx +
                 " + " + num(s) + "*" + sy + ")",
               "(mv*V/H + " + num(force) + ")*" + num(c) + "; (mv*V/H + " +
                 num(force) + ")*" + num(s) + "; -a/2 - (le + 2*me)*d",
               "0; 0; -d*(1-z)",
               "Fb + cp*u_nu",
               "V*(1-z)*" + num(c) + "; V*(1-z)*" + num(s) + "; 0");
    }
}
