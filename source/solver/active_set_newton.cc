#include <hemicontact/base/exceptions.h>
#include <hemicontact/solver/active_set_newton.h>
#include <hemicontact/solver/backtracking.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    std::string
    format_number(const double x)
    {
      std::ostringstream s;
      s.precision(3);
      s << std::scientific << x;
      return s.str();
    }

    /** An iteration on fixed branches that leaves more than this fraction
     *  of the residual has stalled. */
    constexpr double stalled_reduction = 0.5;
  } // namespace

  std::string
  ActiveSetNewton::failure_message(const double       relative_residual,
                                   const unsigned int n_changed,
                                   const double       last_reduction,
                                   const unsigned int settled_iterations) const
  {
    const std::string limit = "'nonlinear solver/max iterations' = " +
                              std::to_string(settings.max_iterations);
    std::string message = "Newton did not converge in " +
                          std::to_string(settings.max_iterations) +
                          " iterations: relative nonsmooth residual " +
                          format_number(relative_residual) + " (tolerance " +
                          format_number(settings.tolerance) + "), ";
    if (n_changed > 0)
      return message + std::to_string(n_changed) +
             " nodes still changing branch when the limit " + limit +
             " was reached. Raise it, reduce the time step, or check the "
             "convexity warning at start-up.";
    // cut short: the branches settled only in the last iteration, or the
    // residual still fell; else a stall on fixed branches
    if (settled_iterations == 0 || last_reduction < stalled_reduction)
      return message + "no node changing branch" +
             (settled_iterations == 0 ?
                std::string(" (the branches settled in the last iteration)") :
                " and the residual still falling (the last iteration took it "
                "to " +
                  format_number(last_reduction) + " times its value)") +
             " when the limit " + limit +
             " was reached: the iteration was cut short. Raise 'nonlinear "
             "solver/max iterations'.";
    return message + "with no node changing branch for " +
           std::to_string(settled_iterations) +
           " iterations and the residual no longer falling (the last one "
           "took it to " +
           format_number(last_reduction) +
           " times its value): the iteration stalled on fixed branches, "
           "where it is a linear solve, so the residual is limited by the "
           "accuracy of the linear solves ('linear solver/relative "
           "tolerance' = " +
           format_number(settings.linear_relative_tolerance) +
           ") or by the convexity of the step. Loosen the Newton tolerance, "
           "tighten the linear solver's, or reduce the time step.";
  }

  ActiveSetNewton::ActiveSetNewton(const Settings &settings, TimerOutput *timer)
    : settings(settings)
    , timer(timer)
  {}

  void
  ActiveSetNewton::line_search(const ActiveSetProblem &problem,
                               VectorType             &w,
                               const VectorType       &trial,
                               VectorType             &residual,
                               unsigned int           &n_reductions) const
  {
    std::unique_ptr<TimerOutput::Scope> scope;
    if (timer != nullptr)
      scope = std::make_unique<TimerOutput::Scope>(*timer, "line search");

    VectorType direction(trial);
    direction -= w;
    if (!settings.line_search)
      {
        w = trial;
        problem.residual(w, residual);
        return;
      }

    // J_n(w + theta d) - J_n(w) = theta d.R + theta^2/2 d.K0 d + (nodal part)
    VectorType k_d(direction);
    problem.apply_quadratic(direction, k_d);
    const double slope     = direction * residual;
    const double curvature = direction * k_d;
    const double nodal_0   = problem.nodal_energy(w);
    const double scale =
      std::abs(slope) + std::abs(curvature) + std::abs(nodal_0) + 1e-300;

    VectorType   candidate(w);
    const double theta = backtracking_step_length(
      [&](const double t) {
        candidate = w;
        candidate.add(t, direction);
        return t * slope + 0.5 * t * t * curvature +
               problem.nodal_energy(candidate) - nodal_0;
      },
      scale,
      settings.minimum_step_length,
      n_reductions);
    w.add(theta, direction);
    // K0 is linear: R(w + theta d) = R(w) + theta K0 d
    residual.add(theta, k_d);
  }

  ActiveSetNewton::Report
  ActiveSetNewton::solve(ActiveSetProblem &problem,
                         VectorType       &w,
                         VectorType       &residual) const
  {
    Report     report;
    VectorType trial(w);

    double       forcing      = settings.maximum_forcing_term;
    double       previous_res = 0;
    const double load_norm    = problem.load_norm();
    // the tolerance relative to the load, and a floor at the round-off of
    // R = K0 w - b, relative to the same scale: no absolute constant, so
    // that scaling every load scales the test (doc/solver.md)
    const auto target_at = [&](const VectorType &r) {
      return settings.tolerance * load_norm +
             settings.roundoff_tolerance *
               (load_norm + problem.operator_norm(r));
    };

    // the iterations in a row so far that began with no branch changed
    unsigned int settled_iterations = 0;

    problem.make_feasible(w);
    problem.residual(w, residual); // then kept up to date by line_search()
    for (unsigned int iteration = 0;; ++iteration)
      {
        const unsigned int n_changed =
          problem.update_branches(w, residual, iteration);
        const double res         = problem.nonsmooth_residual(residual);
        const double target      = target_at(residual);
        report.relative_residual = res / std::max(load_norm, 1e-300);
        if (!std::isfinite(res))
          throw SolverFailure("the nonsmooth residual is not a finite number "
                              "(NaN or Inf) in Newton iteration " +
                              std::to_string(iteration) + ".");

        // converged: no branch changed and the real residual is small; a
        // residual far below the tolerance is accepted even if a node at a
        // branch boundary flipped its label
        if ((n_changed == 0 && res <= target) || res <= 1e-2 * target)
          return report;
        if (iteration == settings.max_iterations)
          throw SolverFailure(
            failure_message(report.relative_residual,
                            n_changed,
                            iteration > 0 ? res / previous_res : 1.,
                            settled_iterations));
        settled_iterations = n_changed == 0 ? settled_iterations + 1 : 0;

        // inexact Newton: the Krylov tolerance follows the decrease of the
        // nonsmooth residual (Eisenstat-Walker, choice 2), but never asks for
        // more than the Newton tolerance needs; once no node changes branch
        // the step is smooth and is solved to the tolerance at once
        if (iteration > 0)
          {
            const double previous_forcing = forcing;
            forcing = 0.9 * std::pow(res / previous_res, 2);
            if (0.9 * previous_forcing * previous_forcing > 0.1)
              forcing =
                std::max(forcing, 0.9 * previous_forcing * previous_forcing);
            forcing = std::min(forcing, settings.maximum_forcing_term);
          }
        previous_res       = res;
        const bool inexact = settings.eisenstat_walker;
        const bool settled =
          settings.exact_solve_when_settled && n_changed == 0;
        report.linear_iterations +=
          problem.solve_linearized(w,
                                   inexact && !settled ? forcing : 0.,
                                   inexact ?
                                     settings.krylov_floor_fraction * target :
                                     0.,
                                   trial);
        problem.make_feasible(trial);
        line_search(problem, w, trial, residual, report.line_search_reductions);
        ++report.newton_iterations;
      }
  }
} // namespace hemicontact
