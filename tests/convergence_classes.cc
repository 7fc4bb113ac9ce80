// The manufactured case prm/verification/mms_2d_quad_exponential.prm in
// the quasistatic class (left point and implicit) and in the dynamic class
// with the implicit rule (doc/theory.md, section 9.7): three coarse levels
// of the coupled study (k halved with h). Asserts that the observed orders
// of E_V and E_u at the finest pair lie in [0.85, 1.3].
#include <hemicontact/input/parameters.h>
#include <hemicontact/verification/convergence_study.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "tests.h"

using namespace hemicontact;

namespace
{
  void
  check(const std::string &problem_class, const std::string &scheme)
  {
    const std::string name = "mms_2d_quad_exponential";
    const std::string overrides =
      "subsection geometry\n  set global refinements = 2\nend\n"
      "subsection time\n  set time step = 0.25\nend\n"
      "subsection problem\n  set class = " +
      problem_class + "\n  set time scheme = " + scheme +
      "\nend\n"
      "subsection convergence study\n  set type = coupled\n"
      "  set levels = 3\nend\n"
      "subsection output\n  set terminal = quiet\n"
      "  set directory = output-" +
      problem_class + "-" + scheme + "\nend\n";
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
    const auto in = [](const double x, const double lo, const double hi) {
      return (x >= lo && x <= hi) ? "yes" : "no";
    };
    out() << name << ", " << problem_class << ", " << scheme
          << ": order E_V in [0.85,1.3]: "
          << in(order(&ErrorNorms::E_V), 0.85, 1.3)
          << ", E_u in [0.85,1.3]: " << in(order(&ErrorNorms::E_u), 0.85, 1.3)
          << std::endl;
    // the numbers themselves only when a check fails (they are not
    // reproducible to the last digit across machines)
    const bool ok =
      order(&ErrorNorms::E_V) >= 0.85 && order(&ErrorNorms::E_V) <= 1.3 &&
      order(&ErrorNorms::E_u) >= 0.85 && order(&ErrorNorms::E_u) <= 1.3;
    if (!ok)
      out() << std::fixed << std::setprecision(3) << "  orders: E_V "
            << order(&ErrorNorms::E_V) << ", E_u " << order(&ErrorNorms::E_u)
            << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check("quasistatic", "left point");
  check("quasistatic", "implicit");
  check("dynamic", "implicit");
}
