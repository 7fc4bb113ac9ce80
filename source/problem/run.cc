#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/checkpointer.h>
#include <hemicontact/output/run_output.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/solver/friction_bound_iteration.h>

#include <algorithm>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <tuple>

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
  StepStatistics
  ContactProblem<dim>::advance()
  {
    Timer wall;
    ++step_number;
    const double time = step_number * time_step;

    // w_{n-1} for the time indicator of the velocity classes (old_velocity
    // holds the start of the last sub-step after a halving)
    const bool time_indicated =
      parameters.output.error_estimate && !scheme.is_static();
    TrilinosWrappers::MPI::Vector velocity_before;
    if (time_indicated)
      velocity_before = velocity;

    StepStatistics stats;
    try
      {
        stats = advance_interval(time - time_step, time_step, 0, time_step);
      }
    catch (const SolverFailure &failure)
      {
        --step_number;
        std::ostringstream message;
        message << "step " << step_number + 1 << " (t = " << time
                << ") failed: " << failure.what();
        throw SolverFailure(message.str());
      }
    stats.step         = step_number;
    stats.time         = time;
    stats.wall_seconds = wall.wall_time();
    stats.n_cells      = discretization.triangulation->n_global_active_cells();
    stats.n_dofs       = dof_handler.n_dofs();
    if (parameters.output.error_estimate)
      {
        TimerOutput::Scope t(timer, "error estimate");
        error_estimate          = estimate_error();
        error_estimate_step     = step_number;
        const ErrorEstimate &e  = error_estimate;
        stats.estimated         = true;
        stats.estimate          = e.total();
        stats.estimate_interior = e.part(e.interior_sum);
        stats.estimate_jumps    = e.part(e.jumps_sum);
        stats.estimate_neumann  = e.part(e.neumann_sum);
        stats.estimate_contact  = e.part(e.contact_sum);
        if (time_indicated)
          {
            // its own share of the section 'error estimate'
            TimerOutput::Scope t_time(timer, "time indicator");
            stats.time_estimated = true;
            stats.estimate_time  = time_indicator(velocity_before);
          }
      }
    return stats;
  }

  template <int dim>
  StepStatistics
  ContactProblem<dim>::advance_interval(const double       start,
                                        const double       k,
                                        const unsigned int depth,
                                        const double       following_k)
  {
    const double wall_length = scheme.wall_step_length(k, following_k);
    // u_n = u_{n-1} + k w_{n-1} (left-point rule; the implicit rule adds
    // k w_n after the step, StepScheme), then solve for w_n,
    // starting from the linear extrapolation of w_{n-2}, w_{n-1}; the trend
    // is zero after the start, an adaptation or a resume (old_velocity =
    // velocity there)
    const bool extrapolate =
      parameters.nonlinear_solver.initial_guess == InitialGuess::extrapolated &&
      last_step_length > 0;
    TrilinosWrappers::MPI::Vector trend;
    if (extrapolate)
      {
        trend = velocity;
        trend -= old_velocity;
      }
    old_velocity = velocity;
    // the memory of the states up to t_{n-1} = start, u_{n-1} the last
    // (doc/theory.md, section 11)
    if (memory.active())
      {
        TimerOutput::Scope t(timer, "memory");
        memory.prepare_step(start, k, displacement);
      }
    scheme.displacement_before_step(displacement, old_velocity, k);
    if (extrapolate)
      {
        velocity.add(k / last_step_length, trend);
        base_constraints.distribute(velocity);
      }
    // the contact pressure p_nu of the bound: in the velocity classes the
    // step before's throughout the step, in the static class the last
    // solve's (doc/theory.md, section 9.9)
    const TrilinosWrappers::MPI::Vector traction_before(contact_traction);
    // the branches of the last converged state: a failed step's iterates
    // change them, and the state written after a failure carries its own
    // (a retry with halved steps starts from the failed iterate's)
    const std::vector<ContactNode<dim>>  nodes_before(contact_nodes);
    const TrilinosWrappers::MPI::Vector *pressure =
      scheme.is_static() ? &contact_traction : &traction_before;
    update_friction_bounds(start + k, pressure);
    recheck_convexity_if_bounds_grew(start + k);
    assemble_load(start + k);
    assemble_step_rhs();
    try
      {
        StepStatistics stats = solve_step(wall_length);
        // a bound in the step's own unknown: fixed-point iterations on it
        // (doc/theory.md, sections 9.8 and 9.9)
        const FrictionBound<dim> &bound = *data.friction_bound;
        if (scheme.is_static() ? bound.uses_normal_displacement() ||
                                   bound.uses_contact_pressure() :
                                 bound.uses_normal_velocity())
          iterate_friction_bound(
            [&]() { return update_friction_bounds(start + k, pressure); },
            [&]() {
              recheck_convexity_if_bounds_grew(start + k);
              return solve_step(wall_length);
            },
            parameters.nonlinear_solver,
            stats);
        scheme.displacement_after_step(displacement, velocity, k);
        if (memory.active())
          memory.commit_step(&velocity, &contact_traction);
        update_energy_balance(/*initial=*/false);
        last_step_length = k;
        return stats;
      }
    catch (const SolverFailure &failure)
      {
        // back to the last converged state (w_{n-1}, u_{n-1})
        scheme.undo_displacement_before_step(displacement, old_velocity, k);
        velocity         = old_velocity;
        contact_traction = traction_before;
        if (depth >= parameters.nonlinear_solver.time_step_halvings)
          {
            contact_nodes = nodes_before;
            throw;
          }
      }

    // retry the interval as two steps of k/2 (and so on, recursively)
    pcout << "  Newton failed with k = " << k << " on [" << start << ", "
          << start + k << "]: two steps of k/2" << std::endl;
    set_time_step(k / 2);
    StepStatistics first, second;
    try
      {
        first  = advance_interval(start, k / 2, depth + 1, k / 2);
        second = advance_interval(start + k / 2, k / 2, depth + 1, following_k);
      }
    catch (const SolverFailure &)
      {
        set_time_step(k);
        throw;
      }
    set_time_step(k);
    second.newton_iterations += first.newton_iterations;
    second.linear_iterations += first.linear_iterations;
    second.line_search_reductions += first.line_search_reductions;
    second.time_step_halvings += 1 + first.time_step_halvings;
    second.bound_iterations += first.bound_iterations;
    return second;
  }

  template <int dim>
  void
  ContactProblem<dim>::set_time_step(const double k)
  {
    // everything that depends on k: the step matrix rho/k M + A, its AMG
    // and the stored energy, whose elastic part is that of u_n + k w_n: the
    // change of k changes E_n by itself, booked like a mesh transfer
    const std::pair<double, double> before = stored_energy();
    time_step                              = k;
    assemble_constant_matrices(scheme.step_matrix(time_step));
    preconditioner.clear();
    std::tie(energy.kinetic, energy.elastic) = stored_energy();
    energy.transfer_change +=
      energy.kinetic + energy.elastic - before.first - before.second;
  }

  template <int dim>
  bool
  ContactProblem<dim>::adapt_mesh_if_due(StepStatistics &stats,
                                         RunOutput<dim> *output)
  {
    const unsigned int every = parameters.adaptivity.interval;
    if (every == 0 || step_number % every != 0 || finished())
      return false;
    if (output != nullptr)
      output->finish_solution_output(); // its job reads the mesh
    adapt_mesh(stats);
    if (output != nullptr)
      output->mesh_changed(*this);
    return true;
  }

  template <int dim>
  void
  ContactProblem<dim>::run()
  {
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
  ContactProblem<dim>::time_loop(RunOutput<dim>    &output,
                                 Checkpointer<dim> &checkpointer)
  {
    // validate everything (mesh, boundary ids, data) before touching the
    // output directory, so that a bad input does not truncate earlier output
    require_usable_output_directory(parameters.output.directory,
                                    mpi_communicator);
    const bool resumed = parameters.checkpoint.resume;
    if (resumed)
      {
        resume(checkpointer);
        output.continue_series(checkpointer.series());
      }
    else
      setup();
    output.open(*this); // checks the probe points first
    checkpointer.start(resumed);
    output.print_start(*this);

    Timer run_timer; // the time loop with every output
    if (resumed)
      pcout << "resumed from the checkpoint of step " << step_number
            << " (t = " << step_number * time_step << ")" << std::endl;
    else
      {
        output.write_solution(*this);
        output.write_probes(*this);
      }
    unsigned int steps_this_run = 0;
    output.start_time_loop(step_number);

    RunTotals totals;
    bool      restarted = false; // by 'adaptivity/pre-refinement steps'
    while (!finished())
      {
        StepStatistics stats;
        try
          {
            stats = parameters.adaptivity.target_error > 0 ?
                      advance_to_target_error(output) :
                      advance();
            check_energy_growth(energy,
                                step_number * time_step,
                                memory_rule_unstable,
                                parameters,
                                mpi_communicator,
                                totals);
          }
        catch (const SolverFailure &failure)
          {
            output.write_solution(*this);
            checkpointer.write(*this, output);
            throw SolverFailure(
              std::string(failure.what()) + " The last converged state (step " +
              std::to_string(step_number) + ") was written to '" +
              parameters.output.directory +
              "' with a checkpoint to resume from.");
          }
        totals.add(stats);
        totals.add_estimate(stats, time_step);
        // the fields on the mesh the step ran on, then (maybe) a new mesh
        output.write_probes(*this);
        if (output.solution_due(step_number, finished()))
          output.write_solution(*this);
        adapt_mesh_if_due(stats, &output);
        output.write_step(stats, *this);
        ++steps_this_run;

        // pre-refinement: once, start again from t = 0 on the mesh reached
        if (!restarted &&
            step_number == parameters.adaptivity.pre_refinement_steps)
          {
            restarted = true;
            initialize_state();
            pcout << "pre-refinement: restart from t = 0 on "
                  << discretization.triangulation->n_global_active_cells()
                  << " cells, " << dof_handler.n_dofs() << " dofs" << std::endl;
            output.write_probes(*this);
            // the series shows the restarted run; its files replace those
            // of the same steps before the restart
            output.restart_series();
            output.write_solution(*this);
            continue;
          }

        // checkpoints: periodic, by wall time, and on interruption (the
        // same decision on every rank)
        const bool interrupted =
          checkpointer.interruption_requested(steps_this_run);
        if (checkpointer.due(step_number, interrupted, finished()))
          checkpointer.write(*this, output);
        if (interrupted && !finished())
          {
            output.finish_solution_output();
            throw RunInterrupted(
              "stopped after step " + std::to_string(step_number) +
              " (t = " + std::to_string(step_number * time_step) +
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
        totals.memory = memory_breakdown(*this);
        preconditioner.clear();
      }
    output.finish(*this, totals, run_timer.wall_time());
  }

#define HEMICONTACT_INSTANTIATE(dim)                                      \
  template StepStatistics ContactProblem<dim>::advance();                 \
  template StepStatistics ContactProblem<dim>::advance_interval(          \
    const double, const double, const unsigned int, const double);        \
  template void ContactProblem<dim>::set_time_step(const double);         \
  template bool ContactProblem<dim>::adapt_mesh_if_due(StepStatistics &,  \
                                                       RunOutput<dim> *); \
  template void ContactProblem<dim>::run();                               \
  template void ContactProblem<dim>::time_loop(RunOutput<dim> &,          \
                                               Checkpointer<dim> &);

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
