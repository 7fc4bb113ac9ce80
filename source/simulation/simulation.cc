/**
 * The run of a problem: setup or resume, the time loop with its output,
 * adaptations, checkpoints and restarts (doc/running.md).
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/checkpointer.h>
#include <hemicontact/output/performance_summary.h>
#include <hemicontact/output/run_output.h>
#include <hemicontact/simulation/simulation.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    /**
     * A run whose stored energy exceeds this multiple of the energy put in
     * (initial energy, work of the loads) is unstable: the laws and the
     * viscosity only dissipate.
     */
    constexpr double unstable_energy_growth = 100;

    /**
     * Refuse (SolverFailure) a stored energy E_n above
     * unstable_energy_growth times the energy put in, at time @p t, unless
     * 'time/allow unstable time step' is set: then a warning, once, and the
     * largest growth in @p totals. The energy put in counts the memory's
     * booked work (EnergyBalance::growth()), except when the memory rule
     * runs beyond its stability limit (@p memory_rule_unstable), whose
     * booked work is the energy it creates (EnergyBalance::data_growth(),
     * doc/theory.md 11.13).
     */
    void
    check_energy_growth(const EnergyBalance &energy,
                        const double         t,
                        const bool           memory_rule_unstable,
                        const Parameters    &parameters,
                        MPI_Comm             comm,
                        RunTotals           &totals)
    {
      const double growth =
        memory_rule_unstable ? energy.data_growth() : energy.growth();
      if (!(growth > unstable_energy_growth))
        return;
      const bool reported = totals.unstable_energy_growth > 0;
      totals.unstable_energy_growth =
        std::max(totals.unstable_energy_growth, growth);
      if (reported)
        return;
      std::ostringstream message;
      message << std::setprecision(4)
              << "the stored energy E_n = " << energy.total_energy()
              << " at t = " << t << " is " << growth
              << " times the energy put into the body (initial energy and "
                 "work of the loads"
              << (memory_rule_unstable ? "" : ", and of the memory") << ", "
              << (memory_rule_unstable ? energy.data_energy() :
                                         energy.supplied_energy())
              << "): the time scheme is unstable (doc/theory.md, "
                 "sections 8 and 11.13); reduce the time step.";
      if (!parameters.time.allow_unstable_time_step)
        throw SolverFailure(message.str());
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        std::cerr << "hemicontact: warning: " << message.str() << std::endl;
    }
  } // namespace

  template <int dim>
  Simulation<dim>::Simulation(ContactProblem<dim> &problem)
    : problem(problem)
    , parameters(problem.state().parameters)
    , mpi_communicator(problem.state().mpi_communicator)
    , pcout(std::cout, terminal_output_on(parameters, mpi_communicator))
  {}

  template <int dim>
  void
  Simulation<dim>::adapt_mesh_if_due(StepStatistics &stats,
                                     RunOutput<dim> &output)
  {
    if (!adaptation_due(problem.state()))
      return;
    output.finish_solution_output(); // its job reads the mesh
    problem.adapt_mesh(stats);
    output.mesh_changed(problem);
  }

  template <int dim>
  void
  Simulation<dim>::run()
  {
    TimerOutput      &timer = problem.get_timer();
    RunOutput<dim>    output(parameters, mpi_communicator, timer, pcout);
    Checkpointer<dim> checkpointer(parameters, mpi_communicator, timer);
    // an earlier run's files come back if this run stops on an input or
    // output error before its first step; a solver failure keeps the state
    // it wrote (doc/outputs.md)
    try
      {
        time_loop(output, checkpointer);
      }
    catch (const InputError &)
      {
        output.restore_earlier_output();
        throw;
      }
    catch (const OutputError &)
      {
        output.restore_earlier_output();
        throw;
      }
    catch (const SolverFailure &)
      {
        output.keep_new_output();
        throw;
      }
    catch (const TargetErrorNotReached &)
      {
        output.keep_new_output();
        throw;
      }
  }

  template <int dim>
  void
  Simulation<dim>::time_loop(RunOutput<dim>    &output,
                             Checkpointer<dim> &checkpointer)
  {
    // validate everything (mesh, boundary ids, data) before touching the
    // output directory, so that a bad input does not truncate earlier output
    require_usable_output_directory(parameters.output.directory,
                                    mpi_communicator);
    const bool resumed = parameters.checkpoint.resume;
    if (resumed)
      {
        problem.resume(checkpointer);
        output.continue_series(checkpointer.series());
      }
    else
      problem.setup();
    output.open(problem); // checks the probe points first
    checkpointer.start(resumed);
    output.print_start(problem);

    Timer run_timer; // the time loop with every output
    if (resumed)
      pcout << "resumed from the checkpoint of step "
            << problem.state().step_number << " (t = " << problem.state().time
            << ")" << std::endl;
    else
      {
        output.write_solution(problem);
        output.write_probes(problem);
      }
    unsigned int steps_this_run = 0;
    output.start_time_loop(problem.state().step_number);

    RunTotals totals;
    bool      restarted = false; // by 'adaptivity/pre-refinement steps'
    while (!problem.finished())
      {
        StepStatistics stats;
        try
          {
            stats = parameters.adaptivity.target_error > 0 ?
                      advance_to_target_error(output) :
                      problem.advance();
            const typename ContactProblem<dim>::State s = problem.state();
            check_energy_growth(s.energy,
                                s.time,
                                s.memory_rule_unstable,
                                parameters,
                                mpi_communicator,
                                totals);
          }
        catch (const SolverFailure &failure)
          {
            output.write_solution(problem);
            checkpointer.write(problem, output);
            throw SolverFailure(
              std::string(failure.what()) + " The last converged state (step " +
              std::to_string(problem.state().step_number) +
              ") was written to '" + parameters.output.directory +
              "' with a checkpoint to resume from.");
          }
        totals.add(stats);
        totals.add_estimate(stats, problem.state().time_step);
        const unsigned int step_number = problem.state().step_number;
        // the fields on the mesh the step ran on, then (maybe) a new mesh
        output.write_probes(problem);
        if (output.solution_due(step_number, problem.finished()))
          output.write_solution(problem);
        adapt_mesh_if_due(stats, output);
        output.write_step(stats, problem);
        ++steps_this_run;

        // pre-refinement: once, start again from t = 0 on the mesh reached
        if (!restarted &&
            step_number == parameters.adaptivity.pre_refinement_steps)
          {
            restarted = true;
            problem.restart();
            pcout << "pre-refinement: restart from t = 0 on "
                  << problem.state()
                       .discretization.triangulation->n_global_active_cells()
                  << " cells, " << problem.state().dof_handler.n_dofs()
                  << " dofs" << std::endl;
            output.write_probes(problem);
            // the series shows the restarted run; its files replace those
            // of the same steps before the restart
            output.restart_series();
            output.write_solution(problem);
            continue;
          }

        // checkpoints: periodic, by wall time, and on interruption (the
        // same decision on every rank)
        const bool interrupted =
          checkpointer.interruption_requested(steps_this_run);
        if (checkpointer.due(step_number, interrupted, problem.finished()))
          checkpointer.write(problem, output);
        if (interrupted && !problem.finished())
          {
            output.finish_solution_output();
            throw RunInterrupted(
              "stopped after step " + std::to_string(step_number) +
              " (t = " + std::to_string(problem.state().time) +
              "); a checkpoint was written to '" + parameters.output.directory +
              "/checkpoint'; continue with 'hemicontact --resume FILE.prm'.");
          }
      }

    output.finish_solution_output();
    if (parameters.output.performance_summary)
      {
        // the memory of the run; its AMG hierarchies freed, so that the
        // summary's reference solve, which builds its own, does not add to
        // the run's peak
        totals.memory = memory_breakdown(problem);
        problem.release_preconditioner();
      }
    output.finish(problem, totals, run_timer.wall_time());
  }

  template class Simulation<2>;
  template class Simulation<3>;
} // namespace hemicontact
