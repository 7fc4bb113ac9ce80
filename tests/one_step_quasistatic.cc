// One step of the quasistatic class with the implicit rule (doc/theory.md,
// section 9.1) whose exact discrete answer is known in closed form, on
// quadrilaterals/hexahedra (Q1) and triangles/tetrahedra (P1): the block of
// one_step_block.h, clamped on top, in contact at the bottom, u_0 = 0,
// loaded so that the exact velocity w_1 = U (1 - y/H) e (linear in the
// thickness) lies in the finite element space. The step is
// (A + k B) w_1 = F_1 - B u_0 with the laws on w_1 and no inertia: a
// constant stress with the moduli mu_v + k mu_e, lambda_v + k lambda_e.
// The program must reproduce w_1 to solver tolerance, with the expected
// branch at every contact node:
//   slip      w = (U(1-y/H), 0): the bottom slides, friction at F_b
//   stick     w = 0 under a tangential load below F_b
//   damped    w = (0, -U(1-y/H)): the bottom moves into the foundation
//   separate  w = (0, +U(1-y/H)): the bottom lifts off
//   slip 3D   w = U(1-z/H)(cos q, sin q, 0): the friction disk in 3D
#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/contact_problem.h>

#include <cmath>
#include <sstream>

#include "one_step_block.h"
#include "tests.h"

using namespace hemicontact;

namespace
{
  // the density is set to a value the quasistatic class ignores; me, le
  // are the moduli of the step's constant stress, A + k B
  const double mu_v = 1.5, lambda_v = 0.7, mu_e = 10, lambda_e = 5, k = 0.1,
               U = 0.3, Fb = 0.4, a = 1, b = 0.4, beta = 3, H = 1,
               me = mu_v + k * mu_e, le = lambda_v + k * lambda_e;

  std::string cell_type = "hypercube";

  std::string
  parameter_file(const unsigned int dim,
                 const std::string &f2,
                 const std::string &f3)
  {
    std::ostringstream p;
    p << one_step_block(dim, cell_type, {2, mu_v, lambda_v, mu_e, lambda_e}, k)
      << "subsection problem\n  set class = quasistatic\n"
      << "  set time scheme = implicit\nend\n"
      << "subsection data\n"
      << "  set constants = U=" << num(U) << ", me=" << num(me)
      << ", le=" << num(le) << ", Fb=" << Fb << ", a=" << a << ", H=" << H
      << "\n"
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
        const std::string &f2,
        const std::string &f3,
        const std::string &exact_u)
  {
    const OneStepResult result =
      one_step<dim>(parameter_file(dim, f2, f3), exact_u, U);
    const StepStatistics &stats = result.stats;
    out() << cell_type << " " << name << ": relative max error < 1e-9: "
          << (result.error < 1e-9 ? "yes" : "no")
          << "; contact nodes sep/stick/damped " << stats.n_separating << "/"
          << stats.n_normal_stick << "/" << stats.n_damped << ", stick/slip "
          << stats.n_stick << "/" << stats.n_slip << std::endl;
    if (result.error >= 1e-9)
      out() << "  error = " << result.error << std::endl;
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

      // slip: sigma_xy = -me U/H; the bottom needs f3 = (me U/H + F_b, -a/2)
      // (normal stick with the multiplier a/2)
      check<2>("slip",
               "0; -" + side + "*me*U/H",
               "me*U/H + Fb; -a/2",
               "V*(1-y); 0");

      // stick: tangential load below F_b, normal multiplier inside [0, a]
      check<2>("stick", "0", "0.5*Fb; -a/2", "0");

      // normal velocity w = (0, c(1-y/H)): sigma_xx = -le c/H, the bottom
      // sees sigma nu = (0, (2 me + le) c/H).
      // damped: c = -U, xi = (a-b) exp(-beta U) + b
      const double xi = (a - b) * std::exp(-beta * U) + b;
      check<2>("damped",
               side + "*le*U/H; 0",
               "0; -(2*me+le)*U/H - " + num(xi),
               "0; -V*(1-y)");

      // separating: c = +U, no contact force
      check<2>("separating",
               "-" + side + "*le*U/H; 0",
               "0; (2*me+le)*U/H",
               "0; V*(1-y)");

      // 3D slip along (cos q, sin q) with q = 0.6: the friction disk
      const double      c = std::cos(0.6), s = std::sin(0.6);
      const std::string sx = "(x < 1e-9 ? -1 : (x > 1 - 1e-9 ? 1 : 0))";
      const std::string sy = "(y < 1e-9 ? -1 : (y > 1 - 1e-9 ? 1 : 0))";
      check<3>("slip 3D",
               "0; 0; -me*U/H*(" + num(c) + "*" + sx + " + " + num(s) + "*" +
                 sy + ")",
               "(me*U/H + Fb)*" + num(c) + "; (me*U/H + Fb)*" + num(s) +
                 "; -a/2",
               "V*(1-z)*" + num(c) + "; V*(1-z)*" + num(s) + "; 0");
    }
}
