// The error estimate of doc/theory.md section 12 on the manufactured
// solution of the static class with a law with breakpoints
// (prm/verification/mms_2d_quad_breakpoint_static.prm), three levels of
// the h-study from 2 global refinements with 'output/error estimate =
// true'. Asserts, at every level:
// - the effectivity index eta / |||u - u_h||| in [4, 7] (measured 4.94,
//   5.16, 5.27), and max/min over the levels <= 1.2;
// - each of the four terms against the true error |||u - u_h||| in a band
//   that excludes 0 (measured: interior 4.2-4.4, jumps 2.0-2.8, Neumann
//   0.8-1.5, contact 0.26-0.49), so that dropping a term fails;
// - eta^2 = the sum of the squares of the four terms (to 1e-10).
// Without the estimate (the parameter off) every check fails.
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
                                               "  set error estimate = true\n"
                                               "  set directory = output-error-estimate\n"
                                               "end\n";
  ParameterHandler                 prm;
  const Parameters                 parameters =
    read_parameters(prm,
                    std::string(SOURCE_DIR) +
                      "/../prm/verification/mms_2d_quad_breakpoint_static.prm",
                    overrides);
  const std::vector<LevelResult> r =
    run_convergence_study<2>(parameters, prm, MPI_COMM_WORLD);

  const char  *names[4] = {"interior", "jumps", "Neumann", "contact"};
  const double low[4]   = {3.5, 1.5, 0.5, 0.15};
  const double high[4]  = {5.5, 3.5, 2.0, 0.8};
  double       smallest = 1e300, largest = 0;
  for (unsigned int level = 0; level < r.size(); ++level)
    {
      const LevelResult &l = r[level];
      const double       E = l.errors.E_energy;
      const bool         in_band =
        l.estimated && l.effectivity >= 4 && l.effectivity <= 7;
      smallest = std::min(smallest, l.effectivity);
      largest  = std::max(largest, l.effectivity);
      out() << "level " << level
            << ": effectivity in [4, 7]: " << (in_band ? "yes" : "no")
            << std::endl;
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
      out() << "  estimate^2 = sum of the terms^2: "
            << (l.estimated && std::abs(sum - l.estimate * l.estimate) <=
                                 1e-10 * l.estimate * l.estimate ?
                  "yes" :
                  "no")
            << std::endl;
      if (!in_band)
        out() << "  (effectivity " << std::setprecision(3) << l.effectivity
              << ")" << std::endl;
    }
  out() << "max/min effectivity over the levels <= 1.2: "
        << (largest <= 1.2 * smallest ? "yes" : "no") << std::endl;
}
