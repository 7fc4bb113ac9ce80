// The time indicator of the velocity classes (doc/theory.md 12.4) on the
// manufactured solution prm/verification/mms_2d_quad_exponential.prm in the
// quasistatic class: three levels of the coupled study from 2 global
// refinements and k = 0.25 with 'output/error estimate = true'. Asserts:
// - at every level the time part (k sum_n |||w_n - w_{n-1}|||^2)^{1/2} is
//   evaluated and against the true error E_energy in [0.5, 1] (measured
//   0.76, 0.71, 0.68), so that dropping it fails;
// - between levels (k and h halved) it falls at order 1 (log2 of the ratio
//   in [0.9, 1.1]; measured 1.04, 1.03), the order of w_n - w_{n-1} = O(k);
// - the total effectivity (estimate^2 + estimate_time^2)^{1/2} / E_energy
//   in [12, 16] (measured 14.45, 13.84, 13.60), max/min <= 1.2, and equal
//   to the space and time parts' squares summed (to 1e-10);
// and that the static class (one level of
// prm/verification/mms_2d_quad_breakpoint_static.prm) has no time part.
// With time_indicator() returning 0 the three time-part
// checks and the two order checks fail.
#include <hemicontact/input/parameters.h>
#include <hemicontact/verification/convergence_study.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

#include "tests.h"

using namespace hemicontact;

namespace
{
  std::vector<LevelResult>
  study(const std::string &file,
        const std::string &overrides,
        ParameterHandler  &prm)
  {
    const Parameters parameters =
      read_parameters(prm,
                      std::string(SOURCE_DIR) + "/../prm/verification/" + file,
                      overrides);
    return run_convergence_study<2>(parameters, prm, MPI_COMM_WORLD);
  }

  const char *
  yes(const bool condition)
  {
    return condition ? "yes" : "no";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                output = "subsection output\n"
                                            "  set terminal = quiet\n"
                                            "  set error estimate = true\n"
                                            "  set directory = output-error-estimate-time\n"
                                            "end\n";
  ParameterHandler                 prm;
  const std::vector<LevelResult>   r =
    study("mms_2d_quad_exponential.prm",
          output + "subsection problem\n  set class = quasistatic\nend\n"
                   "subsection geometry\n  set global refinements = 2\nend\n"
                   "subsection time\n  set time step = 0.25\nend\n"
                   "subsection convergence study\n  set type = coupled\n"
                   "  set levels = 3\nend\n",
          prm);

  double smallest = 1e300, largest = 0;
  for (unsigned int level = 0; level < r.size(); ++level)
    {
      const LevelResult &l     = r[level];
      const double       E     = l.errors.E_energy;
      const double       ratio = l.estimate_time / E;
      const bool in_band = l.time_estimated && l.effectivity_total >= 12 &&
                           l.effectivity_total <= 16;
      smallest = std::min(smallest, l.effectivity_total);
      largest  = std::max(largest, l.effectivity_total);
      out() << "level " << level << ": time part / error in [0.5, 1]: "
            << yes(l.time_estimated && ratio >= 0.5 && ratio <= 1) << std::endl;
      if (!(ratio >= 0.5 && ratio <= 1))
        out() << "  (" << std::setprecision(3) << ratio << ")" << std::endl;
      out() << "  total effectivity in [12, 16]: " << yes(in_band) << std::endl;
      if (!in_band)
        out() << "  (" << std::setprecision(3) << l.effectivity_total << ")"
              << std::endl;
      const double squares = std::pow(l.effectivity, 2) + std::pow(ratio, 2);
      out() << "  total^2 = space^2 + time^2: "
            << yes(std::abs(std::pow(l.effectivity_total, 2) - squares) <=
                   1e-10 * squares)
            << std::endl;
      if (level > 0)
        {
          const double order =
            std::log2(r[level - 1].estimate_time / l.estimate_time);
          out() << "  order of the time part in [0.9, 1.1]: "
                << yes(order >= 0.9 && order <= 1.1) << std::endl;
          if (!(order >= 0.9 && order <= 1.1))
            out() << "  (" << std::setprecision(3) << order << ")" << std::endl;
        }
    }
  out() << "max/min total effectivity over the levels <= 1.2: "
        << yes(largest <= 1.2 * smallest) << std::endl;

  ParameterHandler               prm_static;
  const std::vector<LevelResult> s =
    study("mms_2d_quad_breakpoint_static.prm",
          output + "subsection geometry\n  set global refinements = 2\nend\n"
                   "subsection convergence study\n  set type = single\nend\n",
          prm_static);
  out() << "static class: space part, no time part: "
        << yes(s[0].estimated && !s[0].time_estimated &&
               s[0].estimate_time == 0)
        << std::endl;
}
