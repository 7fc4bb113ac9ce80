// A reduced version of the shipped adaptive manufactured-solution study
// (prm/verification/mms_2d_quad_exponential_adaptive.prm): three coarse
// levels of the coupled study on adaptive meshes and the same levels on
// uniform meshes. Asserts that
// - study_parameters() raises the refinements, 'max level' and 'max cells'
//   of an adaptive level and halves k;
// - the adaptive meshes change during a level (max dofs > the starting
//   mesh's) and stay within the cell budget (below 2.5 times the dofs of
//   the starting mesh);
// - against the mean number of dofs, E_V, E_u and E_H decrease at least at
//   rate 0.4 between the last two levels (O(h) is 0.5 in 2D), and the
//   fitted slopes of E_V and E_u are at least the uniform ones less 0.05
//   (E_H is dominated by the time error here, the same k on both meshes:
//   its rate against dofs only follows the growth of the dofs);
// - at the finest level the adaptive E_V and E_u lie below 0.95 times the
//   uniform errors at the adaptive mean dofs (log-log interpolated or
//   extrapolated; about 0.87 and 0.80 when written).
#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/normal_law.h>
#include <hemicontact/verification/convergence_study.h>

#include <cmath>
#include <iomanip>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include "tests.h"

using namespace hemicontact;

namespace
{
  /** The reduced study: levels of 16, 64, 256 cells (budget 25 * 4^L). */
  const std::string overrides =
    "subsection geometry\n  set global refinements = 2\nend\n"
    "subsection time\n  set time step = 0.25\nend\n"
    "subsection convergence study\n  set levels = 3\nend\n"
    "subsection adaptivity\n  set max cells = 25\n  set max level = 5\n"
    "  set min level = 1\nend\n";

  /** The reduced study on adaptive or uniform ('adaptivity/interval = 0')
   * meshes. */
  std::vector<LevelResult>
  study(const bool adaptive, Parameters &parameters)
  {
    const std::string name = adaptive ? "adaptive" : "uniform";
    ParameterHandler  prm;
    parameters = read_parameters(
      prm,
      std::string(SOURCE_DIR) +
        "/../prm/verification/mms_2d_quad_exponential_adaptive.prm",
      overrides +
        "subsection adaptivity\n  set interval = " + (adaptive ? "1" : "0") +
        "\nend\n"
        "subsection output\n  set terminal = quiet\n"
        "  set directory = output-" +
        name + "\nend\n");
    return run_convergence_study<2>(parameters, prm, MPI_COMM_WORLD);
  }

  /** Minus the least-squares slope of log(error) against log(mean dofs). */
  double
  fitted_slope(const std::vector<LevelResult> &r, double ErrorNorms::*e)
  {
    std::vector<double> x, y;
    for (const LevelResult &level : r)
      {
        x.push_back(std::log(level.mean_dofs));
        y.push_back(std::log(level.errors.*e));
      }
    const double n   = x.size();
    const double mx  = std::accumulate(x.begin(), x.end(), 0.) / n;
    const double my  = std::accumulate(y.begin(), y.end(), 0.) / n;
    double       sxy = 0, sxx = 0;
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        sxy += (x[i] - mx) * (y[i] - my);
        sxx += (x[i] - mx) * (x[i] - mx);
      }
    return -sxy / sxx;
  }

  /** The rate between the last two levels against the mean dofs. */
  double
  last_rate(const std::vector<LevelResult> &r, double ErrorNorms::*e)
  {
    const LevelResult &a = r[r.size() - 2], &b = r.back();
    return std::log(a.errors.*e / b.errors.*e) /
           std::log(b.mean_dofs / a.mean_dofs);
  }

  /**
   * The uniform error at @p dofs, interpolated log-log between levels (or
   * extrapolated along the last two).
   */
  double
  uniform_at(const std::vector<LevelResult> &u,
             double ErrorNorms::*e,
             const double        dofs)
  {
    for (unsigned int i = 1; i < u.size(); ++i)
      if (dofs <= u[i].mean_dofs || i + 1 == u.size())
        {
          const double s = std::log(dofs / u[i - 1].mean_dofs) /
                           std::log(u[i].mean_dofs / u[i - 1].mean_dofs);
          return std::exp((1 - s) * std::log(u[i - 1].errors.*e) +
                          s * std::log(u[i].errors.*e));
        }
    return 0;
  }

  const char *
  yes_no(const bool b)
  {
    return b ? "yes" : "no";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  Parameters                     parameters, uniform_parameters;
  const std::vector<LevelResult> adaptive = study(true, parameters);
  const std::vector<LevelResult> uniform  = study(false, uniform_parameters);

  const Parameters level2 = study_parameters(parameters, 2);
  out() << "level 2: refinements " << level2.geometry.global_refinements
        << ", max level " << level2.adaptivity.max_level << ", max cells "
        << level2.adaptivity.max_cells << ", k " << level2.time.time_step
        << std::endl;

  // the uniform study has the starting meshes; the budget is 25/16 of
  // their cells
  bool adapted = true, within_budget = true;
  for (unsigned int level = 0; level < adaptive.size(); ++level)
    {
      adapted &= adaptive[level].max_dofs > uniform[level].n_dofs;
      within_budget &= adaptive[level].max_dofs < 2.5 * uniform[level].n_dofs;
    }
  out() << "adaptive meshes change during every level: " << yes_no(adapted)
        << ", stay below 2.5 times the uniform dofs: " << yes_no(within_budget)
        << std::endl;

  std::ostringstream numbers;
  numbers << std::fixed << std::setprecision(3);
  for (const auto &[name, e] :
       {std::pair<const char *, double ErrorNorms::*>{"E_V", &ErrorNorms::E_V},
        {"E_u", &ErrorNorms::E_u},
        {"E_H", &ErrorNorms::E_H}})
    {
      const double rate          = last_rate(adaptive, e);
      const double slope         = fitted_slope(adaptive, e);
      const double uniform_slope = fitted_slope(uniform, e);
      const bool   time_error    = e == &ErrorNorms::E_H;
      const bool   ok_rate       = rate >= 0.4;
      const bool   ok_slope      = time_error || slope >= uniform_slope - 0.05;
      out() << name << ": rate against mean dofs >= 0.4: " << yes_no(ok_rate);
      if (!time_error)
        out() << ", fitted slope >= uniform - 0.05: " << yes_no(ok_slope);
      out() << std::endl;
      if (!ok_rate || !ok_slope)
        numbers << "  " << name << ": last rate " << rate << ", slope " << slope
                << ", uniform slope " << uniform_slope << "\n";
    }
  for (const auto &[name, e] :
       {std::pair<const char *, double ErrorNorms::*>{"E_V", &ErrorNorms::E_V},
        {"E_u", &ErrorNorms::E_u}})
    {
      const double ratio = adaptive.back().errors.*e /
                           uniform_at(uniform, e, adaptive.back().mean_dofs);
      out() << name << " below 0.95 times the uniform error at the same dofs: "
            << yes_no(ratio < 0.95) << std::endl;
      if (ratio >= 0.95)
        numbers << "  " << name << ": adaptive / uniform " << ratio << "\n";
    }
  // the numbers only when a check fails (not reproducible to the last digit)
  out() << numbers.str();
}
