// The equilibrated bound of doc/theory.md section 12.5 on the manufactured
// solution of the static class (prm/verification/mms_2d_quad_static.prm:
// exponential compliance with its jump at 0, Tresca friction, every branch
// active), three levels of the h-study from 2 global refinements with
// 'output/error estimate = equilibrated'. Asserts, at every level:
// - the effectivity index eta / |||u - u_h||| in [1, 2] (measured 1.81,
//   1.76, 1.70): above 1, the bound holds;
// - each reported term against the true error in a band that excludes 0
//   (measured: stress 1.24 at each level, oscillation 0.12-0.013, faces
//   0.16-0.11, contact 0.11-0.17), so that dropping a term fails;
// - eta >= (sum of the terms' squares)^{1/2} (eta adds them as norms).
// The residual estimate on the same levels has effectivity 6.2-6.4.
#include <hemicontact/input/parameters.h>
#include <hemicontact/verification/convergence_study.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

#include "tests.h"

using namespace hemicontact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                overrides = "subsection geometry\n"
                                               "  set global refinements = 2\nend\n"
                                               "subsection convergence study\n"
                                               "  set levels = 3\nend\n"
                                               "subsection output\n"
                                               "  set terminal = quiet\n"
                                               "  set error estimate = equilibrated\n"
                                               "  set directory = output-equilibrated\n"
                                               "end\n";
  ParameterHandler                 prm;
  const Parameters                 parameters =
    read_parameters(prm,
                    std::string(SOURCE_DIR) +
                      "/../prm/verification/mms_2d_quad_static.prm",
                    overrides);
  const std::vector<LevelResult> r =
    run_convergence_study<2>(parameters, prm, MPI_COMM_WORLD);

  // the slots of ErrorEstimate: interior = oscillation, jumps = stress,
  // Neumann = faces, contact = contact consistency (theory.md 12.5)
  const char  *names[4] = {"oscillation", "stress", "faces", "contact"};
  const double low[4]   = {0.001, 1.1, 0.04, 0.05};
  const double high[4]  = {0.15, 1.4, 0.2, 0.3};
  for (unsigned int level = 0; level < r.size(); ++level)
    {
      const LevelResult &l = r[level];
      const double       E = l.errors.E_energy;
      const bool         in_band =
        l.estimated && l.effectivity >= 1 && l.effectivity <= 2;
      out() << "level " << level
            << ": effectivity in [1, 2]: " << (in_band ? "yes" : "no")
            << std::endl;
      if (!in_band)
        out() << "  (effectivity " << std::setprecision(3) << l.effectivity
              << ")" << std::endl;
      double sum = 0;
      for (unsigned int t = 0; t < 4; ++t)
        {
          const double ratio = l.estimate_terms[t] / E;
          sum += std::pow(l.estimate_terms[t], 2);
          out() << "  " << names[t] << " term / error in [" << low[t] << ", "
                << high[t]
                << "]: " << (ratio >= low[t] && ratio <= high[t] ? "yes" : "no")
                << std::endl;
          if (ratio < low[t] || ratio > high[t])
            out() << "    (" << std::setprecision(3) << ratio << ")"
                  << std::endl;
        }
      out() << "  estimate >= (sum of the terms^2)^(1/2): "
            << (l.estimated && l.estimate >= std::sqrt(sum) ? "yes" : "no")
            << std::endl;
    }
}
