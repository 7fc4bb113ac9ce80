#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <hemicontact/output/performance_summary.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/solver/linear_solver.h>

#include <sys/resource.h>

#include <fstream>
#include <iomanip>
#include <map>

namespace hemicontact
{
  namespace
  {
    /** Peak resident set size of this process in bytes. */
    double
    peak_resident_bytes()
    {
      rusage usage;
      getrusage(RUSAGE_SELF, &usage);
      return 1024. * usage.ru_maxrss; // Linux reports kilobytes
    }
  } // namespace

  template <int dim>
  void
  write_performance_summary(const ContactProblem<dim> &problem,
                            const Parameters          &parameters,
                            const TimerOutput         &timer,
                            const RunTotals           &totals,
                            const double               run_wall_seconds,
                            const unsigned int         solution_writes,
                            MPI_Comm                   mpi_communicator)
  {
    const typename ContactProblem<dim>::State s              = problem.state();
    const DoFHandler<dim>                    &dof_handler    = s.dof_handler;
    const Discretization<dim>                &discretization = s.discretization;
    // the linear solver of the run (its parameters; it keeps no state)
    LinearSolver linear_solver(parameters.linear_solver, mpi_communicator);
    // the reference cost: one solve of the step matrix K0 = rho/k M + A with
    // the same solver, AMG set up afresh, CG from zero to the fixed tolerance
    const double setup_before = s.preconditioner.setup_seconds();
    TrilinosWrappers::MPI::Vector x(s.locally_owned_dofs, mpi_communicator);
    TrilinosWrappers::MPI::Vector b(s.step_rhs);
    if (b.l2_norm() == 0)
      b = 1.;
    s.base_constraints.set_zero(b);
    StepPreconditioner<dim> reference(parameters.solver_tuning,
                                      mpi_communicator);
    reference.reinit(dof_handler, *discretization.mapping);
    Timer        solve_timer(mpi_communicator, /*sync_lap_times=*/true);
    unsigned int reference_iterations = 1;
    if (parameters.linear_solver.type == LinearSolverType::direct)
      linear_solver.solve_direct(s.step_matrix, x, b);
    else
      reference_iterations = linear_solver.solve(
        s.step_matrix, reference.step_amg(s.step_matrix), x, b);
    solve_timer.stop();
    const double reference_total = solve_timer.wall_time();
    const double reference_setup =
      Utilities::MPI::max(reference.setup_seconds(), mpi_communicator);

    const std::map<std::string, double> sections =
      timer.get_summary_data(TimerOutput::total_wall_time);
    const auto section = [&](const std::string &name) -> double {
      const auto it = sections.find(name);
      return Utilities::MPI::max(it == sections.end() ? 0. : it->second,
                                 mpi_communicator);
    };
    const double run_setup_amg =
      Utilities::MPI::max(setup_before, mpi_communicator);
    const double peak_bytes =
      Utilities::MPI::sum(peak_resident_bytes(), mpi_communicator);
    // the mesh and the dof numbering on the rank that holds the most
    const double mesh_bytes =
      Utilities::MPI::max(static_cast<double>(
                            discretization.triangulation->memory_consumption() +
                            dof_handler.memory_consumption()),
                          mpi_communicator);
    const double steps = std::max(totals.steps, 1u);
    const double step_wall =
      Utilities::MPI::max(totals.step_wall_seconds, mpi_communicator) / steps;

    // every collective reduction before rank 0 writes alone
    std::map<std::string, double> times;
    for (const char *name : {"setup",
                             "assembly: load",
                             "active set update",
                             "linear solve",
                             "convexity check",
                             "line search",
                             "energy balance",
                             "output"})
      times[name] = section(name);
    const double run_wall =
      Utilities::MPI::max(run_wall_seconds, mpi_communicator);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    std::ofstream out(parameters.output.directory + "/performance.csv");
    out << std::setprecision(6) << "quantity,value\n"
        << "dimension," << dim << "\n"
        << "mpi_ranks," << Utilities::MPI::n_mpi_processes(mpi_communicator)
        << "\n"
        << "n_dofs," << dof_handler.n_dofs() << "\n"
        << "n_cells," << discretization.triangulation->n_global_active_cells()
        << "\n"
        << "steps," << totals.steps << "\n"
        << "newton_mean," << totals.newton_iterations / steps << "\n"
        << "newton_max," << totals.max_newton << "\n"
        << "linear_per_solve,"
        << double(totals.linear_iterations) /
             std::max(totals.newton_iterations, 1u)
        << "\n"
        << "wall_per_step," << step_wall << "\n"
        << "reference_solve_wall," << reference_total << "\n"
        << "reference_setup_wall," << reference_setup << "\n"
        << "reference_cg_wall," << reference_total - reference_setup << "\n"
        << "reference_iterations," << reference_iterations << "\n"
        << "ratio_step_to_reference," << step_wall / reference_total << "\n"
        << "time_setup," << times.at("setup") << "\n"
        << "time_assembly_load," << times.at("assembly: load") << "\n"
        << "time_active_set_update," << times.at("active set update") << "\n"
        << "time_preconditioner_setup," << run_setup_amg << "\n"
        << "time_linear_solve_without_setup,"
        << times.at("linear solve") + times.at("convexity check") -
             run_setup_amg
        << "\n"
        << "time_line_search," << times.at("line search") << "\n"
        << "time_energy," << times.at("energy balance") << "\n"
        << "time_output," << times.at("output") << "\n"
        << "run_wall," << run_wall << "\n"
        << "solution_writes," << solution_writes << "\n"
        << "peak_memory_bytes," << peak_bytes << "\n"
        << "bytes_per_dof," << peak_bytes / dof_handler.n_dofs() << "\n"
        << "mesh_bytes_max_rank," << mesh_bytes << "\n";
  }

#define HEMICONTACT_INSTANTIATE(dim)                                        \
  template void write_performance_summary<dim>(const ContactProblem<dim> &, \
                                               const Parameters &,          \
                                               const TimerOutput &,         \
                                               const RunTotals &,           \
                                               double,                      \
                                               unsigned int,                \
                                               MPI_Comm);

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
