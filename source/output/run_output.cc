#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/numerics/vector_tools_evaluate.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/friction_law.h>
#include <hemicontact/output/output_file.h>
#include <hemicontact/output/run_output.h>
#include <hemicontact/output/step_columns.h>
#include <hemicontact/problem/contact_problem.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    /** Drop the rows after step @p step from steps.csv and probes.csv of
     *  @p directory (a resumed run continues them). */
    void
    continue_tables(const std::string &directory, const unsigned int step)
    {
      const std::filesystem::path dir = directory;
      for (const char *table : {"steps.csv", "probes.csv"})
        {
          const std::string warning =
            truncate_table((dir / table).string(), step);
          if (!warning.empty())
            std::cerr << "hemicontact: warning: " << warning << std::endl;
        }
    }

    /**
     * The points of 'output/probe points' (@p text_of_points: "x,y; x,y");
     * an InputError for an entry that is not @p dim finite numbers.
     */
    template <int dim>
    std::vector<Point<dim>>
    parse_probe_points(const std::string &text_of_points)
    {
      std::vector<Point<dim>> points;
      for (const std::string &text :
           Utilities::split_string_list(text_of_points, ';'))
        {
          std::vector<double> coordinates;
          try
            {
              coordinates = Utilities::string_to_double(
                Utilities::split_string_list(text, ','));
            }
          catch (...)
            {
              throw InputError("output: 'probe points' entry '" + text +
                               "' is not a list of numbers.");
            }
          require(coordinates.size() == dim,
                  "output: 'probe points' entry '" + text + "' needs " +
                    std::to_string(dim) + " coordinates.");
          require(std::all_of(coordinates.begin(),
                              coordinates.end(),
                              [](const double c) { return std::isfinite(c); }),
                  "output: 'probe points' entry '" + text +
                    "' has a coordinate that is not a finite number.");
          Point<dim> p;
          for (unsigned int d = 0; d < dim; ++d)
            p[d] = coordinates[d];
          points.push_back(p);
        }
      return points;
    }
  } // namespace

  template <int dim>
  RunOutput<dim>::RunOutput(const Parameters   &parameters,
                            MPI_Comm            comm,
                            TimerOutput        &timer,
                            ConditionalOStream &pcout)
    : parameters(parameters)
    , mpi_communicator(comm)
    , timer(timer)
    , pcout(pcout)
  {
    if (parameters.output.precision == OutputPrecision::double_precision)
      nodal_writer =
        std::make_unique<NodalHdf5Writer<dim>>(parameters.output.directory,
                                               "nodal",
                                               comm);
  }

  template <int dim>
  void
  RunOutput<dim>::open(const ContactProblem<dim> &problem)
  {
    // the probe points, checked before the output is touched
    probe_points = parse_probe_points<dim>(parameters.output.probe_points);
    if (!probe_points.empty())
      {
        mesh_changed(problem);
        require(probe_cache.all_points_found(),
                "output: a probe point lies outside the mesh.");
      }

    const std::string &dir = parameters.output.directory;
    std::string        error;
    // an earlier run's files that cannot be set aside, a table that cannot
    // be continued
    std::string io_error, table_error;
    bool        write_header = true;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        if (ec)
          error = "cannot create the output directory '" + dir +
                  "': " + ec.message() + ".";
        else
          try
            {
              output_lock = std::make_unique<OutputLock>(dir);
            }
          catch (const std::exception &e)
            {
              error = e.what();
            }
        bool continuing = false;
        if (error.empty())
          try
            {
              earlier_output.set_aside(dir, parameters.checkpoint.resume);
              continuing = parameters.checkpoint.resume &&
                           std::filesystem::exists(dir + "/steps.csv");
              if (continuing)
                continue_tables(dir, problem.state().step_number);
            }
          catch (const InputError &e)
            {
              table_error = e.what();
            }
          catch (const OutputError &e)
            {
              io_error = e.what();
            }
        if (error.empty() && table_error.empty() && io_error.empty())
          {
            steps_file.open(dir + "/steps.csv",
                            continuing ? std::ios::app : std::ios::trunc);
            write_header = !continuing;
            if (!steps_file)
              error = "cannot write to the output directory '" + dir +
                      "' (steps.csv could not be opened).";
          }
      }
    error = Utilities::MPI::broadcast(mpi_communicator, error, 0);
    require(error.empty(), "output: " + error);
    table_error = Utilities::MPI::broadcast(mpi_communicator, table_error, 0);
    require(table_error.empty(), table_error);
    throw_if_any(io_error, mpi_communicator);

    if (steps_file.is_open() && write_header)
      steps_file << step_columns_header();
    // probes.csv (the points are checked above)
    if (!probe_points.empty() &&
        Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        const std::string file = dir + "/probes.csv";
        if (parameters.checkpoint.resume && std::filesystem::exists(file))
          probes_file.open(file, std::ios::app); // continue_tables() cut it
        else
          {
            probes_file.open(file);
            probes_file << "step,time,point";
            const char *xyz[] = {"x", "y", "z"};
            for (unsigned int d = 0; d < dim; ++d)
              probes_file << "," << xyz[d];
            for (unsigned int d = 0; d < dim; ++d)
              probes_file << ",w_" << xyz[d];
            for (unsigned int d = 0; d < dim; ++d)
              probes_file << ",u_" << xyz[d];
            probes_file << "\n";
          }
      }
    // the double-precision collection of a resumed run: its files up to
    // the checkpoint's step
    if (nodal_writer && parameters.checkpoint.resume)
      {
        nodal_writer->read_collection();
        nodal_writer->keep_steps_up_to(problem.state().step_number);
      }
  }

  template <int dim>
  void
  RunOutput<dim>::print_start(const ContactProblem<dim> &problem) const
  {
    const typename ContactProblem<dim>::State s = problem.state();
    const unsigned int                        n_nodes =
      Utilities::MPI::sum(static_cast<unsigned int>(
                            std::count_if(s.contact_nodes.begin(),
                                          s.contact_nodes.end(),
                                          [](const ContactNode<dim> &n) {
                                            return n.locally_owned;
                                          })),
                          mpi_communicator);
    pcout << "hemicontact: " << dim << "D, "
          << s.discretization.triangulation->n_global_active_cells()
          << " cells, " << s.dof_handler.n_dofs() << " dofs, " << n_nodes
          << " contact nodes, " << s.n_steps << " steps of k = " << s.time_step
          << ", normal law '" << s.normal_law.name() << "'";
    if (s.friction_law.name() != default_friction_law_name())
      pcout << ", friction law '" << s.friction_law.name() << "'";
    if (s.scheme.name() !=
        StepScheme(ProblemClass::dynamic, TimeScheme::left_point).name())
      pcout << ", " << s.scheme.name();
    if (s.memory.stress_active())
      pcout << ", memory "
            << (s.memory.get_kernel().type() == RelaxationKernelType::prony ?
                  "'prony' (" +
                    std::to_string(s.memory.get_kernel().n_terms()) +
                    " terms)" :
                  std::string("'expression'"));
    if (s.memory.contact_memory().normal_active())
      {
        const NormalMemoryKernel &b = s.memory.contact_memory().get_kernel();
        pcout << ", normal memory "
              << (b.type() == RelaxationKernelType::prony ?
                    "'prony' (" + std::to_string(b.n_terms()) + " terms)" :
                    std::string("'expression'"));
      }
    if (parameters.output.terminal != TerminalOutput::test)
      pcout << ", " << Utilities::MPI::n_mpi_processes(mpi_communicator)
            << " MPI rank(s)";
    pcout << std::endl;
    if (s.convexity.with_friction)
      pcout << "convexity: alpha_nu = "
            << s.normal_law.relaxed_monotonicity_constant()
            << ", alpha_tau <= " << std::setprecision(3)
            << s.convexity.largest_alpha_tau
            << ", smallest eigenvalue against them (estimated) = "
            << s.convexity.bound << " -> "
            << (s.convexity.bound > 1 ? "each step is strongly convex" :
                                        "NOT guaranteed convex")
            << std::endl;
    else if (s.normal_law.relaxed_monotonicity_constant() > 0)
      pcout << "convexity: alpha = "
            << s.normal_law.relaxed_monotonicity_constant()
            << ", bound (estimated) = " << std::setprecision(3)
            << s.convexity.bound << " -> "
            << (s.normal_law.relaxed_monotonicity_constant() <
                    s.convexity.bound ?
                  "each step is strongly convex" :
                  "NOT guaranteed convex")
            << std::endl;
  }

  template <int dim>
  void
  RunOutput<dim>::continue_series(const std::vector<SeriesRecord> &series)
  {
    records = series;
  }

  template <int dim>
  void
  RunOutput<dim>::start_time_loop(const unsigned int step)
  {
    loop_start      = std::chrono::steady_clock::now();
    loop_start_step = step;
  }

  template <int dim>
  bool
  RunOutput<dim>::solution_due(const unsigned int step,
                               const bool         last_step) const
  {
    const unsigned int interval = parameters.output.output_interval;
    return interval > 0 && (step % interval == 0 || last_step);
  }

  template <int dim>
  void
  RunOutput<dim>::mesh_changed(const ContactProblem<dim> &problem)
  {
    if (!probe_points.empty())
      probe_cache.reinit(probe_points,
                         *problem.state().discretization.triangulation,
                         *problem.state().discretization.mapping);
  }

  template <int dim>
  void
  RunOutput<dim>::write_probes(const ContactProblem<dim> &problem)
  {
    if (probe_points.empty())
      return;
    const typename ContactProblem<dim>::State s = problem.state();
    TrilinosWrappers::MPI::Vector             w(s.locally_owned_dofs,
                                    s.locally_relevant_dofs,
                                    mpi_communicator);
    TrilinosWrappers::MPI::Vector             u(w);
    w = s.velocity;
    u = s.displacement;
    const auto w_values =
      VectorTools::point_values<dim>(probe_cache, s.dof_handler, w);
    const auto u_values =
      VectorTools::point_values<dim>(probe_cache, s.dof_handler, u);
    std::string error;
    if (probes_file.is_open())
      {
        std::ostringstream rows;
        rows << std::setprecision(10);
        for (unsigned int p = 0; p < probe_points.size(); ++p)
          {
            rows << s.step_number << "," << s.time << "," << p;
            for (unsigned int d = 0; d < dim; ++d)
              rows << "," << probe_points[p][d];
            for (unsigned int d = 0; d < dim; ++d)
              rows << "," << w_values[p][d];
            for (unsigned int d = 0; d < dim; ++d)
              rows << "," << u_values[p][d];
            rows << "\n";
          }
        error = append_complete(probes_file,
                                parameters.output.directory + "/probes.csv",
                                rows.str());
      }
    throw_if_any(error, mpi_communicator);
  }

  template <int dim>
  void
  RunOutput<dim>::write_step(const StepStatistics      &stats,
                             const ContactProblem<dim> &problem)
  {
    write_step_row(stats, problem);
    print_step(stats, problem);
  }

  template <int dim>
  void
  RunOutput<dim>::write_step_row(const StepStatistics      &s,
                                 const ContactProblem<dim> &problem)
  {
    std::string error;
    if (steps_file.is_open())
      {
        const std::string row = step_columns_row(s, problem.state().energy);
        error                 = append_complete(steps_file,
                                parameters.output.directory + "/steps.csv",
                                row);
        // the run has completed a step: an earlier run's files go
        if (error.empty() && earlier_output.pending())
          {
            const std::string failure = earlier_output.keep_new_output();
            if (!failure.empty())
              std::cerr << "hemicontact: warning: " << failure << std::endl;
          }
      }
    throw_if_any(error, mpi_communicator);
  }

  template <int dim>
  void
  RunOutput<dim>::print_step(const StepStatistics      &s,
                             const ContactProblem<dim> &problem) const
  {
    const typename ContactProblem<dim>::State state   = problem.state();
    const EnergyBalance                      &energy  = state.energy;
    const unsigned int                        n_steps = state.n_steps;
    // the branch counts of kinks and walls, for laws that have them
    const bool has_holds = !state.normal_law.kinks().empty() ||
                           std::isfinite(state.normal_law.penetration_limit());
    std::ostringstream line;
    if (parameters.output.terminal == TerminalOutput::test)
      {
        line << "step " << s.step << ": newton " << s.newton_iterations
             << ", normal sep/stick/damped " << s.n_separating << "/"
             << s.n_normal_stick << "/" << s.n_damped << ", tangential "
             << "stick/slip " << s.n_stick << "/" << s.n_slip
             << std::setprecision(5) << std::scientific << ", kinetic "
             << energy.kinetic << ", elastic " << energy.elastic
             << ", energy defect < 1e-7: "
             << (energy.relative_defect() < 1e-7 ? "yes" : "no");
        if (s.bound_iterations > 0)
          line << ", friction bound iterations " << s.bound_iterations;
        if (has_holds)
          line << ", at breakpoint/wall " << s.n_at_breakpoint << "/"
               << s.n_at_wall;
        for (const SummaryValue &v : state.coupled_fields.summary())
          line << ", " << v.long_label << " " << v.value;
        if (s.coupling_passes > 1)
          line << ", coupling passes " << s.coupling_passes;
        if (s.adapted)
          line << "\n  adapted: "
               << state.discretization.triangulation->n_global_active_cells()
               << " cells, " << state.dof_handler.n_dofs()
               << " dofs; energy before "
               << s.kinetic_before_adaptation + s.elastic_before_adaptation
               << ", after "
               << s.kinetic_after_adaptation + s.elastic_after_adaptation;
      }
    else
      {
        // the time left, from the mean wall time of this run's steps
        const double elapsed = std::chrono::duration<double>(
                                 std::chrono::steady_clock::now() - loop_start)
                                 .count();
        const unsigned int done = s.step - loop_start_step;
        const double left = done > 0 ? elapsed / done * (n_steps - s.step) : 0;
        const auto   seconds = static_cast<unsigned long>(std::lround(left));
        std::ostringstream eta;
        if (seconds >= 3600)
          eta << seconds / 3600 << "h" << std::setw(2) << std::setfill('0')
              << seconds % 3600 / 60 << "m";
        else
          eta << seconds / 60 << "m" << std::setw(2) << std::setfill('0')
              << seconds % 60 << "s";
        line << "step " << std::setw(5) << s.step << "/" << n_steps << "  left "
             << std::setw(6) << eta.str() << "  t = " << std::fixed
             << std::setprecision(4) << s.time << "  newton " << std::setw(2)
             << s.newton_iterations << "  krylov " << std::setw(4)
             << s.linear_iterations << "  sep/stick/damped " << s.n_separating
             << "/" << s.n_normal_stick << "/" << s.n_damped << "  stick/slip "
             << s.n_stick << "/" << s.n_slip << std::scientific
             << std::setprecision(2) << "  residual " << s.residual
             << "  energy " << energy.total_energy() << "  defect "
             << energy.relative_defect();
        if (s.bound_iterations > 0)
          line << "  bound iterations " << s.bound_iterations;
        if (has_holds)
          line << "  breakpoint/wall " << s.n_at_breakpoint << "/"
               << s.n_at_wall;
        for (const SummaryValue &v : state.coupled_fields.summary())
          line << "  " << v.short_label << " " << v.value;
        if (s.coupling_passes > 1)
          line << "  coupling passes " << s.coupling_passes;
      }
    if (parameters.output.terminal != TerminalOutput::quiet)
      pcout << line.str() << std::endl;
  }

  template <int dim>
  void
  RunOutput<dim>::finish(const ContactProblem<dim> &problem,
                         const RunTotals           &totals,
                         const double               run_wall_seconds)
  {
    const typename ContactProblem<dim>::State s = problem.state();
    pcout << "done: " << s.n_steps << " steps, Newton iterations per step mean "
          << std::fixed << std::setprecision(2)
          << double(totals.newton_iterations) / std::max(totals.steps, 1u)
          << " max " << totals.max_newton << ", energy defect < 1e-7 relative: "
          << (s.energy.relative_defect() < 1e-7 ? "yes" : "no");
    if (totals.unstable_energy_growth > 0)
      pcout << "; the stored energy grew to " << std::scientific
            << std::setprecision(3) << totals.unstable_energy_growth
            << " times the energy the data put in: an unstable run";
    pcout << std::endl;
    // the estimate of every step, or the steps it covers named
    const bool partial_estimate =
      totals.estimated_steps > 0 &&
      (totals.first_estimated_step > 1 || totals.estimated_steps < s.n_steps);
    if (partial_estimate)
      pcout << "error estimate of steps " << totals.first_estimated_step
            << " to " << s.step_number << " only, not of the whole run of "
            << s.n_steps
            << " steps (the run resumed from the checkpoint of step "
            << totals.first_estimated_step - 1
            << "; the sums leave out the steps before it): ";
    if (totals.estimated_steps > 0)
      pcout << "error estimate (energy norm of the step, doc/theory.md 12): "
            << "largest eta_n = " << std::scientific << std::setprecision(3)
            << totals.largest_estimate << " (step "
            << totals.largest_estimate_step << "), (sum_n k eta_n^2)^(1/2) = "
            << std::sqrt(totals.estimate_k_sum);
    if (totals.time_estimated_steps > 0)
      pcout << ", time (sum_n k |||w_n - w_{n-1}|||^2)^(1/2) = "
            << std::sqrt(totals.estimate_time_k_sum) << ", total = "
            << std::sqrt(totals.estimate_k_sum + totals.estimate_time_k_sum);
    if (totals.estimated_steps > 0)
      pcout << std::defaultfloat << std::endl;
    if (parameters.output.performance_summary)
      write_performance_summary(problem,
                                parameters,
                                timer,
                                totals,
                                run_wall_seconds,
                                records.size(),
                                mpi_communicator);
    if (parameters.output.timing_summary &&
        parameters.output.terminal != TerminalOutput::test)
      timer.print_wall_time_statistics(mpi_communicator);
  }

  template <int dim>
  void
  RunOutput<dim>::restore_earlier_output()
  {
    // every rank's solution files are complete before they are deleted
    solution_writer.wait();
    MPI_Barrier(mpi_communicator);
    if (!earlier_output.pending())
      return;
    steps_file.close();
    probes_file.close();
    const std::string error = earlier_output.restore();
    std::cerr << "hemicontact: "
              << (error.empty() ?
                    "the earlier run's files in '" +
                      parameters.output.directory + "' are restored." :
                    "warning: " + error)
              << std::endl;
  }

  template <int dim>
  void
  RunOutput<dim>::keep_new_output()
  {
    const std::string error = earlier_output.keep_new_output();
    if (!error.empty())
      std::cerr << "hemicontact: warning: " << error << std::endl;
  }

  template class RunOutput<2>;
  template class RunOutput<3>;
} // namespace hemicontact
