#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <hemicontact/base/memory_breakdown.h>
#include <hemicontact/output/performance_summary.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/solver/linear_solver.h>

#include <cctype>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>

namespace hemicontact
{
  namespace
  {
    /** "AMG of K0" -> "amg_of_k0". */
    std::string
    csv_name(const std::string &part)
    {
      std::string name;
      for (const char c : part)
        if (std::isalnum(static_cast<unsigned char>(c)))
          name +=
            static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        else if (!name.empty() && name.back() != '_')
          name += '_';
      while (!name.empty() && name.back() == '_')
        name.pop_back();
      return name;
    }

  } // namespace

  template <int dim>
  MemoryBreakdown
  memory_breakdown(const ContactProblem<dim> &problem)
  {
    const typename ContactProblem<dim>::State s = problem.state();
    MemoryBreakdown                           breakdown;
    breakdown.add_matrix("step matrix K", s.step_matrix);
    breakdown.add_matrix("mass matrix M", s.mass_matrix);
    breakdown.add_matrix("elastic matrix B", s.elastic_matrix);
    s.preconditioner.add_memory(breakdown);
    // w_n, w_{n-1}, u_n, F_n, b, the contact traction
    breakdown.add("vectors",
                  6. * s.locally_owned_dofs.n_elements() * sizeof(double));
    // the fields added to the state, on spaces of their own
    double added = 0;
    for (const StateField<dim> &f : problem.fields())
      if (f.space->dof_handler != &s.dof_handler)
        added += f.vector->memory_consumption();
    if (added > 0)
      breakdown.add("added fields of the state", added);
    breakdown.add("mesh, dofs and constraints",
                  s.discretization.triangulation->memory_consumption() +
                    s.dof_handler.memory_consumption() +
                    s.base_constraints.memory_consumption() +
                    s.locally_owned_dofs.memory_consumption() +
                    s.locally_relevant_dofs.memory_consumption());
    breakdown.add("contact nodes",
                  s.contact_nodes.capacity() * sizeof(ContactNode<dim>));
    // A_mu, A_lambda and the history of a memory kernel (doc/theory.md 11)
    if (s.memory.active())
      breakdown.add(s.memory.stress_active() ? "memory of the stress" :
                                               "memory of the contact",
                    s.memory.memory_consumption());
    return breakdown;
  }

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
    const typename ContactProblem<dim>::State s           = problem.state();
    const DoFHandler<dim>                    &dof_handler = s.dof_handler;
    // the peak of the run, before the reference solve below adds its AMG
    const double run_peak_bytes =
      Utilities::MPI::sum(peak_resident_bytes(), mpi_communicator);
    const Discretization<dim> &discretization = s.discretization;
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
    // the parts at the end of the time loop (the run's AMG hierarchies were
    // freed after it) and the reference solve's AMG
    MemoryBreakdown parts = totals.memory;
    MemoryBreakdown of_reference;
    reference.add_memory(of_reference);
    for (const auto &part : of_reference.summed(MPI_COMM_SELF))
      if (part.first == "AMG of K0")
        parts.add("AMG of the reference solve", part.second);
    const std::vector<std::pair<std::string, double>> memory =
      parts.summed(mpi_communicator);
    const double heap_bytes =
      Utilities::MPI::sum(heap_bytes_in_use(), mpi_communicator);
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
        << "mesh_bytes_max_rank," << mesh_bytes << "\n"
        << "run_peak_memory_bytes," << run_peak_bytes << "\n"
        << "heap_in_use_bytes," << heap_bytes << "\n";
    double accounted = 0;
    for (const auto &part : memory)
      {
        out << "memory_" << csv_name(part.first) << "_bytes," << part.second
            << "\n";
        accounted += part.second;
      }
    out << "memory_accounted_bytes," << accounted << "\n";

    if (parameters.output.terminal != TerminalOutput::progress)
      return;
    const double n_dofs = dof_handler.n_dofs();
    std::cout << "memory, summed over "
              << Utilities::MPI::n_mpi_processes(mpi_communicator)
              << " rank(s): peak " << std::fixed << std::setprecision(1)
              << peak_bytes / 1e6 << " MB (" << peak_bytes / n_dofs
              << " B/dof), before the reference solve " << run_peak_bytes / 1e6
              << " MB, heap in use at the end " << heap_bytes / 1e6
              << " MB, of which\n";
    for (const auto &part : memory)
      if (part.second > 0)
        std::cout << "  " << std::left << std::setw(30) << part.first
                  << std::right << std::setw(10) << part.second / 1e6 << " MB "
                  << std::setw(8) << part.second / n_dofs << " B/dof\n";
    std::cout << "  " << std::left << std::setw(30) << "(the parts above)"
              << std::right << std::setw(10) << accounted / 1e6 << " MB "
              << std::setw(8) << accounted / n_dofs << " B/dof" << std::endl;
  }

#define HEMICONTACT_INSTANTIATE(dim)                                           \
  template MemoryBreakdown memory_breakdown<dim>(const ContactProblem<dim> &); \
  template void write_performance_summary<dim>(const ContactProblem<dim> &,    \
                                               const Parameters &,             \
                                               const TimerOutput &,            \
                                               const RunTotals &,              \
                                               double,                         \
                                               unsigned int,                   \
                                               MPI_Comm);

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
