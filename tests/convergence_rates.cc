// Reduced versions of the shipped verification studies (prm/verification/):
// three coarse levels of the coupled study (k halved with h) for every
// element type and dimension. Asserts that the observed orders of E_V and
// E_u at the finest pair lie in [0.85, 1.3], that E_H converges at least at
// first order, and that every contact branch occurs on a share of at least
// 5% of the (node, step) pairs.
#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/normal_law.h>
#include <hemicontact/verification/convergence_study.h>

#include <cmath>
#include <iomanip>
#include <sstream>

#include "tests.h"

using namespace hemicontact;

namespace
{
  template <int dim>
  void
  check(const std::string &name, const unsigned int first_refinement)
  {
    const std::string overrides =
      "subsection geometry\n  set global refinements = " +
      std::to_string(first_refinement) +
      "\nend\n"
      "subsection time\n  set time step = 0.25\nend\n"
      "subsection convergence study\n  set type = coupled\n"
      "  set levels = 3\nend\n"
      "subsection output\n  set terminal = quiet\n"
      "  set directory = output-" +
      name + "\nend\n";
    ParameterHandler prm;
    const Parameters parameters =
      read_parameters(prm,
                      std::string(SOURCE_DIR) + "/../prm/verification/" + name +
                        ".prm",
                      overrides);
    const std::vector<LevelResult> r =
      run_convergence_study<dim>(parameters, prm, MPI_COMM_WORLD);

    const auto order = [&](double ErrorNorms::*e) {
      return std::log2(r[r.size() - 2].errors.*e / r.back().errors.*e);
    };
    const auto in = [](const double x, const double lo, const double hi) {
      return (x >= lo && x <= hi) ? "yes" : "no";
    };
    bool all_branches = true;
    for (const double share : r.back().branch_share)
      all_branches &= share >= 0.05;

    std::ostringstream line;
    line << name << ": order E_V in [0.85,1.3]: "
         << in(order(&ErrorNorms::E_V), 0.85, 1.3)
         << ", E_u in [0.85,1.3]: " << in(order(&ErrorNorms::E_u), 0.85, 1.3)
         << ", E_H >= 0.9: " << in(order(&ErrorNorms::E_H), 0.9, 3)
         << ", every branch on >= 5% of (node, step) pairs: "
         << (all_branches ? "yes" : "no");
    out() << line.str() << std::endl;
    // the numbers themselves only when a check fails (they are not
    // reproducible to the last digit across machines)
    const bool ok =
      order(&ErrorNorms::E_V) >= 0.85 && order(&ErrorNorms::E_V) <= 1.3 &&
      order(&ErrorNorms::E_u) >= 0.85 && order(&ErrorNorms::E_u) <= 1.3 &&
      order(&ErrorNorms::E_H) >= 0.9 && all_branches;
    if (!ok)
      out() << std::fixed << std::setprecision(3) << "  orders: E_V "
            << order(&ErrorNorms::E_V) << ", E_u " << order(&ErrorNorms::E_u)
            << ", E_H " << order(&ErrorNorms::E_H) << std::endl;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>("mms_2d_quad_exponential", 2);
  check<2>("mms_2d_quad_piecewise_linear", 2);
  check<2>("mms_2d_simplex_exponential", 2);
  check<3>("mms_3d_hex_exponential", 1);
  check<3>("mms_3d_simplex_exponential", 1);
}
