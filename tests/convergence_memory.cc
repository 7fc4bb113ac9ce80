// Manufactured solutions with long memory (doc/theory.md, section 11.11)
// in prm/verification, three levels of the coupled study each (h and k
// halved together): the static class on 2D quadrilaterals and the dynamic
// and quasistatic classes on 2D quadrilaterals, first with a relaxation
// kernel alone, then with memory in the stress and in the contact (the
// relaxation kernel, memory in the normal response and a friction bound
// weakening with the accumulated slip s_tau). Asserts the observed orders
// at the finest pair: E_u (the energy norm in the static class) and E_V in
// [0.85, 1.3].
#include <hemicontact/input/parameters.h>
#include <hemicontact/verification/convergence_study.h>

#include <cmath>
#include <iomanip>

#include "tests.h"

using namespace hemicontact;

namespace
{
  void
  check(const std::string &name,
        const std::string &problem_class,
        const unsigned int refinements,
        const double       time_step)
  {
    const std::string overrides =
      "subsection geometry\n  set global refinements = " +
      std::to_string(refinements) +
      "\nend\n"
      "subsection time\n  set time step = " +
      std::to_string(time_step) +
      "\nend\n"
      "subsection problem\n  set class = " +
      problem_class +
      "\nend\n"
      "subsection convergence study\n  set levels = 3\nend\n"
      "subsection output\n  set terminal = quiet\n"
      "  set directory = output-" +
      name + "-" + problem_class + "\nend\n";
    ParameterHandler prm;
    const Parameters parameters =
      read_parameters(prm,
                      std::string(SOURCE_DIR) + "/../prm/verification/" + name +
                        ".prm",
                      overrides);
    const std::vector<LevelResult> r =
      run_convergence_study<2>(parameters, prm, MPI_COMM_WORLD);

    const auto order = [&](double ErrorNorms::*e) {
      return std::log2(r[r.size() - 2].errors.*e / r.back().errors.*e);
    };
    const double energy = order(&ErrorNorms::E_u), v = order(&ErrorNorms::E_V);
    const bool   ok = energy >= 0.85 && energy <= 1.3 && v >= 0.85 && v <= 1.3;
    out() << name << " (" << problem_class
          << "): orders of E_u and E_V in [0.85,1.3]: " << (ok ? "yes" : "no")
          << std::endl;
    if (!ok)
      out() << std::fixed << std::setprecision(3) << "  orders: E_u " << energy
            << ", E_V " << v << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check("mms_2d_quad_memory_static", "static", 2, 0.25);
  check("mms_2d_quad_memory", "dynamic", 2, 0.25);
  check("mms_2d_quad_memory", "quasistatic", 2, 0.25);
  check("mms_2d_quad_contact_memory_static", "static", 2, 0.25);
  check("mms_2d_quad_contact_memory", "dynamic", 2, 0.25);
  check("mms_2d_quad_contact_memory", "quasistatic", 2, 0.25);
}
