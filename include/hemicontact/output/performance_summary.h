#pragma once

#include <deal.II/base/timer.h>

#include <hemicontact/base/memory_breakdown.h>
#include <hemicontact/solver/step_statistics.h>

#include <mpi.h>

#include <algorithm>
#include <string>

namespace hemicontact
{
  using namespace dealii;

  template <int dim>
  class ContactProblem;
  struct Parameters;

  /** Totals over the run's steps (for the summary line and performance.csv). */
  struct RunTotals
  {
    unsigned int steps             = 0;
    unsigned int newton_iterations = 0;
    unsigned int max_newton        = 0;
    unsigned int linear_iterations = 0;
    double       step_wall_seconds = 0; ///< advance() only, no output
    /** @name The error estimates of the steps ('output/error estimate') */
    unsigned int estimated_steps = 0;
    /** The first step with an estimate (0: none), e.g. after a resume. */
    unsigned int first_estimated_step  = 0;
    double       estimate_k_sum        = 0; ///< sum_n k_n eta_n^2
    double       largest_estimate      = 0; ///< max_n eta_n
    unsigned int largest_estimate_step = 0;
    /** sum_n k_n |||w_n - w_{n-1}|||^2, the time indicator (velocity
     *  classes) */
    unsigned int time_estimated_steps = 0;
    double       estimate_time_k_sum  = 0;
    /**
     * The largest stored energy E_n of the run relative to the energy the
     * data put in (EnergyBalance::growth()), when it exceeded the limit of
     * a stable run and 'time/allow unstable time step' let it go on; 0
     * otherwise.
     */
    double unstable_energy_growth = 0;
    /** The parts of the memory at the end of the time loop. */
    MemoryBreakdown memory;

    /** Count the step of @p stats. */
    void
    add(const StepStatistics &stats)
    {
      ++steps;
      newton_iterations += stats.newton_iterations;
      max_newton = std::max(max_newton, stats.newton_iterations);
      linear_iterations += stats.linear_iterations;
      step_wall_seconds += stats.wall_seconds;
    }

    /** Count the estimate of the step of @p stats, of length @p k. */
    void
    add_estimate(const StepStatistics &stats, const double k)
    {
      if (!stats.estimated)
        return;
      if (estimated_steps == 0)
        first_estimated_step = stats.step;
      ++estimated_steps;
      estimate_k_sum += k * stats.estimate * stats.estimate;
      if (stats.time_estimated)
        {
          ++time_estimated_steps;
          estimate_time_k_sum += k * stats.estimate_time * stats.estimate_time;
        }
      if (stats.estimate >= largest_estimate)
        {
          largest_estimate      = stats.estimate;
          largest_estimate_step = stats.step;
        }
    }
  };

  /**
   * The parts of the memory of @p problem on this rank: its matrices, AMG
   * hierarchies, vectors, mesh, dofs and contact nodes.
   */
  template <int dim>
  MemoryBreakdown
  memory_breakdown(const ContactProblem<dim> &problem);

  /**
   * Write OUTPUT/performance.csv (doc/outputs.md): the run's costs by
   * @p timer's sections against a reference solve of the step matrix of
   * @p problem, memory, @p run_wall_seconds (the time loop with every
   * output) and the number of solution writes. Collective.
   */
  template <int dim>
  void
  write_performance_summary(const ContactProblem<dim> &problem,
                            const Parameters          &parameters,
                            const TimerOutput         &timer,
                            const RunTotals           &totals,
                            double                     run_wall_seconds,
                            unsigned int               solution_writes,
                            MPI_Comm                   mpi_communicator);
} // namespace hemicontact
