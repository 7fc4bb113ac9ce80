#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/base/exceptions.h>

#include <algorithm>
#include <tuple>
#include <csignal>
#include <iomanip>
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

    /** Set by SIGTERM or SIGINT; the time loop checks it after every step. */
    volatile std::sig_atomic_t termination_requested = 0;

    extern "C" void
    request_termination(int)
    {
      termination_requested = 1;
    }
  } // namespace

  template <int dim>
  StepStatistics
  ContactProblem<dim>::advance()
  {
    Timer wall;
    ++step_number;
    const double time = get_time();

    StepStatistics stats;
    try
      {
        stats = advance_interval(time - time_step, time_step, 0);
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
    return stats;
  }

  template <int dim>
  StepStatistics
  ContactProblem<dim>::advance_interval(const double       start,
                                        const double       k,
                                        const unsigned int depth)
  {
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
    scheme.displacement_before_step(displacement, old_velocity, k);
    if (extrapolate)
      {
        velocity.add(k / last_step_length, trend);
        base_constraints.distribute(velocity);
      }
    update_friction_bounds(start + k);
    recheck_convexity_if_bounds_grew(start + k);
    assemble_load(start + k);
    assemble_step_rhs();
    try
      {
        const StepStatistics stats = solve_step();
        scheme.displacement_after_step(displacement, velocity, k);
        update_energy_balance(/*initial=*/false);
        last_step_length = k;
        return stats;
      }
    catch (const SolverFailure &failure)
      {
        // back to the last converged state (w_{n-1}, u_{n-1})
        scheme.undo_displacement_before_step(displacement, old_velocity, k);
        velocity = old_velocity;
        if (depth >= parameters.nonlinear_solver.time_step_halvings)
          throw;
      }

    // retry the interval as two steps of k/2 (and so on, recursively)
    pcout << "  Newton failed with k = " << k << " on [" << start << ", "
          << start + k << "]: two steps of k/2" << std::endl;
    set_time_step(k / 2);
    StepStatistics first, second;
    try
      {
        first  = advance_interval(start, k / 2, depth + 1);
        second = advance_interval(start + k / 2, k / 2, depth + 1);
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
    assemble_constant_matrices();
    preconditioner.clear();
    std::tie(energy.kinetic, energy.elastic) = stored_energy();
    energy.transfer_change += energy.kinetic + energy.elastic -
                              before.first - before.second;
  }

  template <int dim>
  bool
  ContactProblem<dim>::adapt_mesh_if_due(StepStatistics &stats)
  {
    const unsigned int every = parameters.adaptivity.interval;
    if (every == 0 || step_number % every != 0 || finished())
      return false;
    adapt_mesh(stats);
    return true;
  }

  template <int dim>
  void
  ContactProblem<dim>::run()
  {
    // an earlier run's files come back if this run stops on an input or
    // output error before its first step; a solver failure keeps the state
    // it wrote (doc/outputs.md)
    try
      {
        run_and_write();
      }
    catch (const InputError &)
      {
        restore_earlier_output();
        throw;
      }
    catch (const OutputError &)
      {
        restore_earlier_output();
        throw;
      }
    catch (const SolverFailure &)
      {
        const std::string error = earlier_output.keep_new_output();
        if (!error.empty())
          std::cerr << "hemicontact: warning: " << error << std::endl;
        throw;
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::run_and_write()
  {
    // validate everything (mesh, boundary ids, data) before touching the
    // output directory, so that a bad input does not truncate earlier output
    require_usable_output_directory(parameters.output.directory,
                                    mpi_communicator);
    const CheckpointParameters &checkpoints = parameters.checkpoint;
    require(parameters.adaptivity.pre_refinement_steps <= n_steps,
            "adaptivity: 'pre-refinement steps' (" +
              std::to_string(parameters.adaptivity.pre_refinement_steps) +
              ") exceeds the number of time steps (" +
              std::to_string(n_steps) + ").");
    if (checkpoints.resume)
      setup_from_checkpoint();
    else
      setup();
    setup_probes(); // checks the points before the output is touched
    open_tables();
    if (!checkpoints.resume)
      start_checkpoint_run();
    termination_requested = 0;
    std::signal(SIGTERM, request_termination);
    std::signal(SIGINT, request_termination);

    const unsigned int n_nodes = Utilities::MPI::sum(
      static_cast<unsigned int>(std::count_if(
        contact_nodes.begin(), contact_nodes.end(),
        [](const ContactNode<dim> &n) { return n.locally_owned; })),
      mpi_communicator);
    pcout << "hemicontact: " << dim << "D, "
          << discretization.triangulation->n_global_active_cells()
          << " cells, " << dof_handler.n_dofs() << " dofs, " << n_nodes
          << " contact nodes, " << n_steps << " steps of k = " << time_step
          << ", normal law '" << law->name() << "'";
    if (friction->name() != default_friction_law_name())
      pcout << ", friction law '" << friction->name() << "'";
    if (scheme.name() != StepScheme(ProblemClass::dynamic,
                                    TimeScheme::left_point).name())
      pcout << ", " << scheme.name();
    if (parameters.output.terminal != "test")
      pcout << ", " << Utilities::MPI::n_mpi_processes(mpi_communicator)
            << " MPI rank(s)";
    pcout << std::endl;
    if (convexity_with_friction)
      pcout << "convexity: alpha_nu = " << law->relaxed_monotonicity_constant()
            << ", alpha_tau <= " << std::setprecision(3) << largest_alpha_tau
            << ", smallest eigenvalue against them (estimated) = "
            << convexity_bound << " -> "
            << (convexity_bound > 1 ? "each step is strongly convex" :
                                      "NOT guaranteed convex")
            << std::endl;
    else if (law->relaxed_monotonicity_constant() > 0)
      pcout << "convexity: alpha = " << law->relaxed_monotonicity_constant()
            << ", bound (estimated) = " << std::setprecision(3)
            << convexity_bound << " -> "
            << (law->relaxed_monotonicity_constant() < convexity_bound ?
                  "each step is strongly convex" :
                  "NOT guaranteed convex")
            << std::endl;

    const unsigned int interval = parameters.output.vtu_interval;
    Timer              run_timer; // the time loop with every output
    if (checkpoints.resume)
      pcout << "resumed from the checkpoint of step " << step_number
            << " (t = " << get_time() << ")" << std::endl;
    else
      {
        if (interval > 0)
          {
            write_solution();
            write_contact_csv();
          }
        write_probes();
      }
    Timer        since_checkpoint;
    unsigned int steps_this_run = 0;
    loop_start      = std::chrono::steady_clock::now();
    loop_start_step = step_number;

    RunTotals totals;
    bool      restarted = false; // by 'adaptivity/pre-refinement steps'
    bool      growth_reported = false;
    while (!finished())
      {
        StepStatistics stats;
        try
          {
            stats = advance();
            if (energy.growth() > unstable_energy_growth && !growth_reported)
              {
                std::ostringstream message;
                message << std::setprecision(4) << "the stored energy E_n = "
                        << energy.total_energy() << " at t = " << get_time()
                        << " is " << energy.growth()
                        << " times the energy put into the body (initial "
                           "energy and work of the loads, "
                        << energy.supplied_energy()
                        << "): the time scheme is unstable (doc/theory.md, "
                           "section 8); reduce the time step.";
                if (!parameters.time.allow_unstable_time_step)
                  throw SolverFailure(message.str());
                growth_reported = true;
                if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
                  std::cerr << "hemicontact: warning: " << message.str()
                            << std::endl;
              }
          }
        catch (const SolverFailure &failure)
          {
            if (interval > 0)
              {
                write_solution();
                write_contact_csv();
              }
            finish_solution_output();
            write_checkpoint();
            throw SolverFailure(std::string(failure.what()) +
                                " The last converged state (step " +
                                std::to_string(step_number) +
                                ") was written to '" +
                                parameters.output.directory +
                                "' with a checkpoint to resume from.");
          }
        ++totals.steps;
        totals.newton_iterations += stats.newton_iterations;
        totals.max_newton = std::max(totals.max_newton, stats.newton_iterations);
        totals.linear_iterations += stats.linear_iterations;
        totals.step_wall_seconds += stats.wall_seconds;
        // the fields on the mesh the step ran on, then (maybe) a new mesh
        write_probes();
        if (interval > 0 && (step_number % interval == 0 || finished()))
          {
            write_solution();
            write_contact_csv();
          }
        adapt_mesh_if_due(stats);
        write_step_row(stats);
        print_step(stats);
        ++steps_this_run;

        // pre-refinement: once, start again from t = 0 on the mesh reached
        if (!restarted &&
            step_number == parameters.adaptivity.pre_refinement_steps)
          {
            restarted = true;
            initialize_state();
            pcout << "pre-refinement: restart from t = 0 on "
                  << discretization.triangulation->n_global_active_cells()
                  << " cells, " << dof_handler.n_dofs() << " dofs"
                  << std::endl;
            write_probes();
            if (interval > 0)
              {
                // the series shows the restarted run; its files replace
                // those of the same steps before the restart
                finish_solution_output();
                pvd_records.clear();
                write_solution();
                write_contact_csv();
              }
            continue;
          }

        // checkpoints: periodic, by wall time, and on interruption (the
        // same decision on every rank)
        const bool interrupted =
          Utilities::MPI::max(static_cast<int>(termination_requested),
                              mpi_communicator) > 0 ||
          (checkpoints.stop_after > 0 &&
           steps_this_run == checkpoints.stop_after);
        const bool periodic =
          (checkpoints.interval > 0 && step_number % checkpoints.interval == 0) ||
          (checkpoints.wall_interval > 0 &&
           Utilities::MPI::max(since_checkpoint.wall_time(), mpi_communicator) >=
             checkpoints.wall_interval);
        if (periodic || (interrupted && !finished()))
          {
            write_checkpoint();
            since_checkpoint.reset();
            since_checkpoint.start();
          }
        if (interrupted && !finished())
          {
            finish_solution_output();
            throw RunInterrupted(
              "stopped after step " + std::to_string(step_number) + " (t = " +
              std::to_string(get_time()) + "); a checkpoint was written to '" +
              parameters.output.directory +
              "/checkpoint'; continue with 'hemicontact --resume FILE.prm'.");
          }
      }

    finish_solution_output();
    run_wall_seconds = run_timer.wall_time();
    pcout << "done: " << n_steps << " steps, Newton iterations per step mean "
          << std::fixed << std::setprecision(2)
          << double(totals.newton_iterations) / std::max(totals.steps, 1u)
          << " max " << totals.max_newton
          << ", energy defect < 1e-7 relative: "
          << (energy.relative_defect() < 1e-7 ? "yes" : "no") << std::endl;
    if (parameters.output.performance_summary)
      write_performance_summary(totals);
    if (parameters.output.timing_summary && parameters.output.terminal != "test")
      timer.print_wall_time_statistics(mpi_communicator);
  }

#define HEMICONTACT_INSTANTIATE(dim)                                           \
  template StepStatistics ContactProblem<dim>::advance();                     \
  template StepStatistics ContactProblem<dim>::advance_interval(              \
    const double, const double, const unsigned int);                           \
  template void ContactProblem<dim>::set_time_step(const double);                     \
  template bool ContactProblem<dim>::adapt_mesh_if_due(StepStatistics &);    \
  template void           ContactProblem<dim>::run();                        \
  template void           ContactProblem<dim>::run_and_write();

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
