// One time step whose exact discrete answer is known in closed form, on
// quadrilaterals/hexahedra (Q1) and triangles/tetrahedra (P1): a
// block clamped on top, in contact at the bottom, loaded so that the exact
// velocity w = V (1 - y/H) e (linear in the thickness) lies in the finite
// element space. The scheme must reproduce it to solver tolerance, with the
// expected branch at every contact node:
//   slip      w = (V(1-y/H), 0): bottom slides, friction at its bound F_b
//   stick     w = 0 under a tangential load below F_b
//   damped    w = (0, -V(1-y/H)): bottom moves into the foundation
//   separate  w = (0, +V(1-y/H)): bottom lifts off
//   slip 3D   w = V(1-z/H)(cos q, sin q, 0): friction disk in 3D
#include <deal.II/base/function_parser.h>
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
  const double rho = 2, mu_v = 1.5, lambda_v = 0.7, k = 0.1, V = 0.3, Fb = 0.4,
               a = 1, b = 0.4, beta = 3, H = 1;

  std::string cell_type = "hypercube";

  std::string
  parameter_file(const unsigned int dim,
                 const std::string &f0,
                 const std::string &f2,
                 const std::string &f3)
  {
    std::ostringstream p;
    p << one_step_block(dim, cell_type, {rho, mu_v, lambda_v, 10, 5}, k)
      << "subsection data\n"
      << "  set constants = V=" << num(V) << ", rho=" << rho << ", k=" << k
      << ", mv=" << mu_v << ", lv=" << lambda_v << ", Fb=" << Fb << ", a=" << a
      << ", H=" << H << "\n"
      << "  set body force = " << f0 << "\n"
      << "  set surface traction = " << f2 << "\n"
      << "  set contact traction = " << f3 << "\n"
      << "  set friction bound = Fb\nend\n"
      << "subsection normal law\n  set law = exponential\n"
      << "  subsection exponential\n    set a = " << a << "\n    set b = " << b
      << "\n    set beta = " << beta << "\n  end\nend\n"
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
        const std::string &exact_w)
  {
    const OneStepResult result =
      one_step<dim>(parameter_file(dim, f0, f2, f3), exact_w, V);
    const StepStatistics &stats = result.stats;
    const double          error = result.error;

    out() << cell_type << " " << name
          << ": relative max error < 1e-9: " << (error < 1e-9 ? "yes" : "no")
          << "; contact nodes sep/stick/"
          << "damped " << stats.n_separating << "/" << stats.n_normal_stick
          << "/" << stats.n_damped << ", stick/slip " << stats.n_stick << "/"
          << stats.n_slip << std::endl;
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
      cell_type = type;
      // sides x = 0 and x = 2: sign of the outward normal
      const std::string side = "(x < 1e-9 ? -1 : (x > 2 - 1e-9 ? 1 : 0))";

      // slip: sigma_xy = -mu_v V/H; bottom needs f3 = (mu_v V/H + F_b, -a/2)
      check<2>("slip",
               "rho/k*V*(1-y/H); 0",
               "0; -" + side + "*mv*V/H",
               "mv*V/H + Fb; -a/2",
               "V*(1-y); 0");

      // the same with the contact traction given as plain numbers (constant
      // data take the Functions::ConstantFunction path, not an expression)
      check<2>("slip, numeric contact traction",
               "rho/k*V*(1-y/H); 0",
               "0; -" + side + "*mv*V/H",
               num(mu_v * V / H + Fb) + "; " + num(-a / 2),
               "V*(1-y); 0");

      // stick: tangential load below F_b, normal multiplier inside [0, a]
      check<2>("stick", "0", "0", "0.5*Fb; -a/2", "0");

      // normal motion w = (0, c(1-y/H)): sigma_xx = -lambda_v c/H, so the side
      // traction is side * (-lambda_v c / H); the bottom sees
      // sigma nu = (0, (2 mu_v + lambda_v) c/H).
      // damped: c = -V; xi = (a-b) exp(-beta V) + b
      const double xi = (a - b) * std::exp(-beta * V) + b;
      check<2>("damped",
               "0; -rho/k*V*(1-y/H)",
               side + "*lv*V/H; 0",
               "0; -(2*mv+lv)*V/H - " + num(xi),
               "0; -V*(1-y)");

      // separating: c = +V, no contact force
      check<2>("separating",
               "0; rho/k*V*(1-y/H)",
               "-" + side + "*lv*V/H; 0",
               "0; (2*mv+lv)*V/H",
               "0; V*(1-y)");

      // 3D slip along (cos q, sin q) with q = 0.6: the friction disk
      const double      c = std::cos(0.6), s = std::sin(0.6);
      const std::string sx = "(x < 1e-9 ? -1 : (x > 1 - 1e-9 ? 1 : 0))";
      const std::string sy = "(y < 1e-9 ? -1 : (y > 1 - 1e-9 ? 1 : 0))";
      check<3>("slip 3D",
               "rho/k*V*(1-z)*" + num(c) + "; rho/k*V*(1-z)*" + num(s) + "; 0",
               "0; 0; -mv*V/H*(" + num(c) + "*" + sx + " + " + num(s) + "*" +
                 sy + ")",
               "(mv*V/H + Fb)*" + num(c) + "; (mv*V/H + Fb)*" + num(s) +
                 "; -a/2",
               "V*(1-z)*" + num(c) + "; V*(1-z)*" + num(s) + "; 0");
    }
}
