// Manufactured (u, theta) solutions (doc/theory.md, section 13.6) in
// prm/verification, three levels of the coupled study each (h and k
// halved together): 2D quadrilaterals in the dynamic and the quasistatic
// class, 2D triangles (anisotropic K) in the dynamic class, each with heat
// exchange and frictional heating on Gamma_3. Asserts the observed orders
// at the finest pair of E_V, E_u, E_theta and E_theta_H1 in [0.85, 1.3].
#include <hemicontact/input/parameters.h>
#include <hemicontact/verification/convergence_study.h>

#include <cmath>
#include <iomanip>

#include "tests.h"

using namespace hemicontact;

namespace
{
  void
  check(const std::string &name, const std::string &problem_class)
  {
    const std::string overrides =
      "subsection geometry\n  set global refinements = 2\nend\n"
      "subsection time\n  set time step = 0.25\nend\n"
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
    const double orders[4] = {order(&ErrorNorms::E_V),
                              order(&ErrorNorms::E_u),
                              order(&ErrorNorms::E_theta),
                              order(&ErrorNorms::E_theta_H1)};
    bool         ok        = r.back().with_temperature;
    for (const double o : orders)
      ok = ok && o >= 0.85 && o <= 1.3;
    out() << name << " (" << problem_class
          << "): orders of E_V, E_u, E_theta, E_theta_H1 in [0.85,1.3]: "
          << (ok ? "yes" : "no") << std::endl;
    if (!ok)
      out() << std::fixed << std::setprecision(3) << "  orders: " << orders[0]
            << ", " << orders[1] << ", " << orders[2] << ", " << orders[3]
            << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check("mms_2d_quad_temperature", "dynamic");
  check("mms_2d_quad_temperature", "quasistatic");
  check("mms_2d_simplex_temperature", "dynamic");
}
