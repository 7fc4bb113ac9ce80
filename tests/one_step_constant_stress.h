#pragma once
// Shared by the one-step tests of the static and quasistatic classes
// (one_step_static.cc, one_step_quasistatic.cc): the block of
// one_step_block.h loaded so that the step's unknown v = U (1 - y/H) e is
// exact in the finite element space and its stress is constant, with the
// moduli me, le of the class's step (B in the static class, A + k B in the
// implicit quasistatic step). Five cases, on hypercubes and simplices:
//   slip      v = (U(1-y/H), 0): the bottom slides, friction at F_b
//   stick     v = 0 under a tangential load below F_b
//   normal    v = (0, -U(1-y/H)): into the foundation (compliant/damped)
//   separate  v = (0, +U(1-y/H)): the bottom lifts off
//   slip 3D   v = U(1-z/H)(cos q, sin q, 0): the friction disk in 3D
#include <cmath>
#include <sstream>
#include <string>

#include "one_step_block.h"
#include "tests.h"

/** The length k of the step (the load value t = k in the static class). */
constexpr double constant_stress_time_step = 0.1;

/** A class's one-step block: what differs between the two tests. */
struct ConstantStressBlock
{
  std::string   problem;  ///< the subsection 'problem'
  BlockMaterial material; ///< the parameter file's material
  double        me, le;   ///< the moduli of the step's constant stress
  std::string   normal;   ///< the name of the branch into the foundation
};

/** Run the five cases of @p block and print one line each. */
inline void
check_constant_stress_cases(const ConstantStressBlock &block)
{
  using namespace hemicontact;
  const double k = constant_stress_time_step, U = 0.3, Fb = 0.4, a = 1, b = 0.4,
               beta = 3, H = 1;
  std::string cell_type;

  const auto parameter_file =
    [&](const unsigned int dim, const std::string &f2, const std::string &f3) {
      std::ostringstream p;
      p << one_step_block(dim, cell_type, block.material, k) << block.problem
        << "subsection data\n"
        << "  set constants = U=" << num(U) << ", me=" << num(block.me)
        << ", le=" << num(block.le) << ", Fb=" << Fb << ", a=" << a
        << ", H=" << H << "\n"
        << "  set surface traction = " << f2 << "\n"
        << "  set contact traction = " << f3 << "\n"
        << "  set friction bound = Fb\nend\n"
        << "subsection normal law\n  set law = exponential\n"
        << "  subsection exponential\n    set a = " << a
        << "\n    set b = " << b << "\n    set beta = " << beta
        << "\n  end\nend\n"
        << "subsection nonlinear solver\n  set tolerance = 1e-12\nend\n"
        << "subsection linear solver\n  set relative tolerance = 1e-13\nend\n"
        << "subsection output\n  set terminal = quiet\nend\n";
      return p.str();
    };

  const auto report = [&](const std::string   &name,
                          const OneStepResult &result) {
    const StepStatistics &stats = result.stats;
    out() << cell_type << " " << name << ": relative max error < 1e-9: "
          << (result.error < 1e-9 ? "yes" : "no") << "; contact nodes "
          << "sep/stick/" << block.normal << " " << stats.n_separating << "/"
          << stats.n_normal_stick << "/" << stats.n_damped << ", stick/slip "
          << stats.n_stick << "/" << stats.n_slip << std::endl;
    if (result.error >= 1e-9)
      out() << "  error = " << result.error << std::endl;
  };
  const auto check2 = [&](const std::string &name,
                          const std::string &f2,
                          const std::string &f3,
                          const std::string &exact) {
    report(name, one_step<2>(parameter_file(2, f2, f3), exact, U));
  };

  for (const std::string type : {"hypercube", "simplex"})
    {
      cell_type = type;
      // sides x = 0 and x = 2: sign of the outward normal
      const std::string side = "(x < 1e-9 ? -1 : (x > 2 - 1e-9 ? 1 : 0))";

      // slip: sigma_xy = -me U/H; the bottom needs f3 = (me U/H + F_b, -a/2)
      // (normal stick with the multiplier a/2)
      check2("slip",
             "0; -" + side + "*me*U/H",
             "me*U/H + Fb; -a/2",
             "V*(1-y); 0");

      // stick: tangential load below F_b, normal multiplier inside [0, a]
      check2("stick", "0", "0.5*Fb; -a/2", "0");

      // v = (0, c(1-y/H)): sigma_xx = -le c/H, the bottom sees
      // sigma nu = (0, (2 me + le) c/H).
      // into the foundation: c = -U, xi = (a-b) exp(-beta U) + b
      const double xi = (a - b) * std::exp(-beta * U) + b;
      check2(block.normal,
             side + "*le*U/H; 0",
             "0; -(2*me+le)*U/H - " + num(xi),
             "0; -V*(1-y)");

      // separating: c = +U, no contact force
      check2("separating",
             "-" + side + "*le*U/H; 0",
             "0; (2*me+le)*U/H",
             "0; V*(1-y)");

      // 3D slip along (cos q, sin q) with q = 0.6: the friction disk
      const double      c = std::cos(0.6), s = std::sin(0.6);
      const std::string sx = "(x < 1e-9 ? -1 : (x > 1 - 1e-9 ? 1 : 0))";
      const std::string sy = "(y < 1e-9 ? -1 : (y > 1 - 1e-9 ? 1 : 0))";
      report("slip 3D",
             one_step<3>(parameter_file(3,
                                        "0; 0; -me*U/H*(" + num(c) + "*" + sx +
                                          " + " + num(s) + "*" + sy + ")",
                                        "(me*U/H + Fb)*" + num(c) +
                                          "; (me*U/H + Fb)*" + num(s) +
                                          "; -a/2"),
                         "V*(1-z)*" + num(c) + "; V*(1-z)*" + num(s) + "; 0",
                         U));
    }
}
