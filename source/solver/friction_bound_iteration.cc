#include <hemicontact/base/exceptions.h>
#include <hemicontact/solver/friction_bound_iteration.h>

#include <iomanip>
#include <limits>
#include <sstream>

namespace hemicontact
{
  void
  iterate_friction_bound(const std::function<double()>         &update_bounds,
                         const std::function<StepStatistics()> &solve,
                         const NonlinearSolverParameters       &settings,
                         StepStatistics                        &stats)
  {
    double       last_change = std::numeric_limits<double>::infinity();
    unsigned int growths     = 0;
    for (;;)
      {
        const double change = update_bounds();
        ++stats.bound_iterations;
        if (change <= settings.bound_tolerance)
          return;
        growths = change > last_change ? growths + 1 : 0;
        if (stats.bound_iterations >= settings.bound_iterations || growths >= 3)
          {
            std::ostringstream message;
            message << std::setprecision(3)
                    << "the friction bound, which depends on the step's "
                       "own unknown, did not settle: after "
                    << stats.bound_iterations
                    << " fixed-point iterations its relative change is "
                    << change << " (tolerance " << settings.bound_tolerance
                    << ", 'nonlinear solver/friction bound tolerance')"
                    << (growths >= 3 ? " and it grows: the bound does not "
                                       "contract (doc/theory.md, section "
                                       "9.8, gives a sufficient condition)" :
                                       "")
                    << ". Make the bound depend less steeply on the "
                       "state (for Coulomb friction, mu*pos(p_nu): a "
                       "smaller coefficient mu), or raise 'friction bound "
                       "iterations'.";
            throw SolverFailure(message.str());
          }
        last_change = change;
        // the last solve's state and branches, every solve's iterations
        StepStatistics again   = solve();
        again.bound_iterations = stats.bound_iterations;
        again.newton_iterations += stats.newton_iterations;
        again.linear_iterations += stats.linear_iterations;
        again.line_search_reductions += stats.line_search_reductions;
        stats = again;
      }
  }
} // namespace hemicontact
