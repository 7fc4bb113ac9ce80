#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools_evaluate.h>

#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/output_file.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    /** Stress components (cell averages) and von Mises, for DataOut. */
    template <int dim>
    std::vector<Vector<float>>
    cell_stresses(const DoFHandler<dim> &dof_handler, const Mapping<dim> &mapping,
                  const Quadrature<dim> &                quadrature,
                  const KelvinVoigtMaterial<dim> &       material,
                  const TrilinosWrappers::MPI::Vector &  w,
                  const TrilinosWrappers::MPI::Vector &  u)
    {
      const unsigned int n_components = dim * (dim + 1) / 2 + 1;
      std::vector<Vector<float>> result(
        n_components,
        Vector<float>(dof_handler.get_triangulation().n_active_cells()));
      FEValues<dim> fe_values(mapping, dof_handler.get_fe(), quadrature,
                              update_gradients | update_JxW_values);
      const FEValuesExtractors::Vector     v(0);
      std::vector<SymmetricTensor<2, dim>> eps_w(quadrature.size()),
        eps_u(quadrature.size());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[v].get_function_symmetric_gradients(w, eps_w);
            fe_values[v].get_function_symmetric_gradients(u, eps_u);
            SymmetricTensor<2, dim> sigma;
            double                  volume = 0;
            for (const unsigned int q : fe_values.quadrature_point_indices())
              {
                sigma += material.stress(eps_w[q], eps_u[q]) * fe_values.JxW(q);
                volume += fe_values.JxW(q);
              }
            sigma /= volume;
            const unsigned int index = cell->active_cell_index();
            unsigned int       c     = 0;
            for (unsigned int i = 0; i < dim; ++i)
              for (unsigned int j = i; j < dim; ++j)
                result[c++][index] = sigma[i][j];
            result[c][index] = KelvinVoigtMaterial<dim>::von_mises(sigma);
          }
      return result;
    }
  } // namespace

  template <int dim>
  void
  ContactProblem<dim>::open_tables()
  {
    const std::string &dir  = parameters.output.directory;
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
                continue_tables();
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
      steps_file
        << "step,time,n_cells,n_dofs,newton_iterations,linear_iterations,"
           "n_separating,n_normal_stick,n_damped,n_stick,n_slip,residual,"
           "kinetic_energy,elastic_energy,viscous_dissipation,"
           "friction_dissipation,normal_damping_dissipation,external_work,"
           "numerical_dissipation,energy_defect,relative_energy_defect,"
           "line_search_reductions,wall_seconds,adapted,"
           "kinetic_before_adaptation,elastic_before_adaptation,"
           "kinetic_after_adaptation,elastic_after_adaptation,"
           "energy_transfer_change,time_step_halvings\n";
    // probes.csv (setup_probes() has checked the points)
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
  }

  template <int dim>
  void
  ContactProblem<dim>::setup_probes()
  {
    probe_points.clear();
    for (const std::string &text :
         Utilities::split_string_list(parameters.output.probe_points, ';'))
      {
        std::vector<double> coordinates;
        try
          {
            coordinates =
              Utilities::string_to_double(Utilities::split_string_list(text, ','));
          }
        catch (...)
          {
            throw InputError("output: 'probe points' entry '" + text +
                             "' is not a list of numbers.");
          }
        require(coordinates.size() == dim,
                "output: 'probe points' entry '" + text + "' needs " +
                  std::to_string(dim) + " coordinates.");
        require(std::all_of(coordinates.begin(), coordinates.end(),
                            [](const double c) { return std::isfinite(c); }),
                "output: 'probe points' entry '" + text +
                  "' has a coordinate that is not a finite number.");
        Point<dim> p;
        for (unsigned int d = 0; d < dim; ++d)
          p[d] = coordinates[d];
        probe_points.push_back(p);
      }
    if (probe_points.empty())
      return;
    probe_cache.reinit(probe_points, *discretization.triangulation,
                       *discretization.mapping);
    require(probe_cache.all_points_found(),
            "output: a probe point lies outside the mesh.");
  }

  template <int dim>
  void
  ContactProblem<dim>::write_probes()
  {
    if (probe_points.empty())
      return;
    TrilinosWrappers::MPI::Vector w(locally_owned_dofs, locally_relevant_dofs,
                                   mpi_communicator);
    TrilinosWrappers::MPI::Vector u(w);
    w = velocity;
    u = displacement;
    const auto w_values =
      VectorTools::point_values<dim>(probe_cache, dof_handler, w);
    const auto u_values =
      VectorTools::point_values<dim>(probe_cache, dof_handler, u);
    std::string error;
    if (probes_file.is_open())
      {
        std::ostringstream rows;
        rows << std::setprecision(10);
        for (unsigned int p = 0; p < probe_points.size(); ++p)
          {
            rows << step_number << "," << get_time() << "," << p;
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
  ContactProblem<dim>::write_solution()
  {
    finish_solution_output();
    TimerOutput::Scope t(timer, "output");

    // copies of what the write reads, so that the run can go on meanwhile
    SolutionSnapshot &snapshot = solution_snapshot;
    snapshot.step              = step_number;
    snapshot.time              = get_time();
    snapshot.velocity.reinit(locally_owned_dofs, locally_relevant_dofs,
                             mpi_communicator);
    snapshot.displacement.reinit(snapshot.velocity);
    snapshot.velocity     = velocity;
    snapshot.displacement = displacement;
    TrilinosWrappers::MPI::Vector traction(snapshot.velocity),
      branch(snapshot.velocity);
    traction = contact_traction;

    TrilinosWrappers::MPI::Vector branch_owned(locally_owned_dofs,
                                               mpi_communicator);
    for (const auto i : locally_owned_dofs)
      branch_owned[i] = -1;
    for (const ContactNode<dim> &node : contact_nodes)
      if (node.locally_owned)
        {
          branch_owned[node.dofs[0]] = static_cast<int>(node.normal_branch);
          branch_owned[node.dofs[1]] = static_cast<int>(node.tangential_branch);
          if (dim == 3)
            branch_owned[node.dofs[dim - 1]] = 1;
        }
    branch_owned.compress(VectorOperation::insert);
    branch = branch_owned;

    snapshot.data_out = std::make_unique<DataOut<dim>>();
    DataOut<dim> &data_out = *snapshot.data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_field(dim, DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(snapshot.velocity,
                             std::vector<std::string>(dim, "velocity"),
                             DataOut<dim>::type_dof_data, vector_field);
    data_out.add_data_vector(snapshot.displacement,
                             std::vector<std::string>(dim, "displacement"),
                             DataOut<dim>::type_dof_data, vector_field);
    data_out.add_data_vector(traction,
                             std::vector<std::string>(dim, "contact_traction"),
                             DataOut<dim>::type_dof_data, vector_field);
    std::vector<std::string> branch_names = {"normal_branch",
                                             "tangential_branch"};
    if (dim == 3)
      branch_names.push_back("contact_node");
    data_out.add_data_vector(
      branch, branch_names, DataOut<dim>::type_dof_data,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim, DataComponentInterpretation::component_is_scalar));

    const Triangulation<dim> &mesh = *discretization.triangulation;
    std::vector<std::pair<std::string, Vector<float>>> cell_data;
    Vector<float> subdomain(mesh.n_active_cells());
    for (auto &s : subdomain)
      s = mesh.locally_owned_subdomain();
    cell_data.emplace_back("subdomain", subdomain);
    Vector<float> level(mesh.n_active_cells());
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        level[cell->active_cell_index()] = cell->level();
    cell_data.emplace_back("level", level);
    if (parameters.adaptivity.interval > 0)
      cell_data.emplace_back("refinement_indicator", refinement_indicators());

    // the job, on the writer's thread and without MPI: stresses, patches
    // and the VTU files, or the data in HDF5 layout
    const bool        hdf5 = parameters.output.format == SolutionFormat::hdf5;
    const std::string directory = parameters.output.directory + "/";
    const unsigned int rank = Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    const Quadrature<dim> quadrature = discretization.cell_quadrature(2);
    const std::string     stem =
      "solution_" + Utilities::int_to_string(snapshot.step, 5);
    pending_record = {snapshot.time, stem + (hdf5 ? ".h5" : ".pvtu")};
    if (hdf5)
      snapshot.hdf5_filter = std::make_unique<DataOutBase::DataOutFilter>(
        DataOutBase::DataOutFilterFlags(/*filter_duplicates=*/false,
                                        /*xdmf_hdf5_output=*/true));
    auto job = [this, hdf5, directory, rank, n_ranks, quadrature, stem,
                cell_data = std::move(cell_data)]() -> std::string {
      const SolutionSnapshot &s        = solution_snapshot;
      DataOut<dim> &          data_out = *s.data_out;
      const std::vector<Vector<float>> stresses =
        cell_stresses(dof_handler, *discretization.mapping, quadrature,
                      material, s.velocity, s.displacement);
      const char * xyz[] = {"x", "y", "z"};
      unsigned int c     = 0;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          data_out.add_data_vector(stresses[c++],
                                   std::string("stress_") + xyz[i] + xyz[j],
                                   DataOut<dim>::type_cell_data);
      data_out.add_data_vector(stresses[c], "von_mises",
                               DataOut<dim>::type_cell_data);
      for (const auto &field : cell_data)
        data_out.add_data_vector(field.second, field.first,
                                 DataOut<dim>::type_cell_data);
      data_out.build_patches(*discretization.mapping);

      // a failed write (no space left) names the files
      errno = 0;
      try
        {
          if (hdf5)
            {
              // the data in HDF5 layout; the file is written (collectively)
              // by finish_solution_output()
              data_out.write_filtered_data(*s.hdf5_filter);
              return "";
            }
          DataOutBase::VtkFlags flags;
          flags.compression_level = parameters.output.compression;
          data_out.set_flags(flags);
          // the files write_vtu_with_pvtu_record() writes, without its MPI
          const unsigned int digits = Utilities::needed_digits(n_ranks - 1);
          auto piece = [&](const unsigned int r) {
            return stem + "." + Utilities::int_to_string(r, digits) + ".vtu";
          };
          std::ofstream vtu(directory + piece(rank));
          data_out.write_vtu(vtu);
          vtu.close();
          if (!vtu)
            return write_failure(errno);
          if (rank == 0)
            {
              std::vector<std::string> pieces;
              for (unsigned int r = 0; r < n_ranks; ++r)
                pieces.push_back(piece(r));
              std::ofstream pvtu(directory + stem + ".pvtu");
              data_out.write_pvtu_record(pvtu, pieces);
              pvtu.close();
              if (!pvtu)
                return write_failure(errno);
            }
        }
      catch (const ExceptionBase &)
        {
          return write_failure(errno);
        }
      return "";
    };
    solution_writer.start(job, std::launch::async);
  }

  template <int dim>
  void
  ContactProblem<dim>::finish_solution_output()
  {
    if (!solution_writer.pending())
      return;
    TimerOutput::Scope t(timer, "output");
    const std::string prefix = "cannot write the solution files of step " +
                               std::to_string(solution_snapshot.step) +
                               " in '" + parameters.output.directory + "': ";
    std::string error = solution_writer.wait();
    if (!error.empty())
      error = prefix + error + ".";
    throw_if_any(error, mpi_communicator);

    // HDF5: the collective write of the data the job arranged
    if (parameters.output.format == SolutionFormat::hdf5)
      {
        const DataOut<dim> &              data_out = *solution_snapshot.data_out;
        const DataOutBase::DataOutFilter &filter =
          *solution_snapshot.hdf5_filter;
        const std::string h5 = pending_record.second;
        errno                = 0;
        try
          {
            data_out.write_hdf5_parallel(filter,
                                         parameters.output.directory + "/" +
                                           h5,
                                         mpi_communicator);
            pending_record.second =
              data_out
                .create_xdmf_entry(filter, h5, pending_record.first,
                                   mpi_communicator)
                .get_xdmf_content(3, discretization.fe->reference_cell());
          }
        catch (const ExceptionBase &)
          {
            error = prefix + write_failure(errno) + ".";
          }
        throw_if_any(error, mpi_communicator);
      }
    // its patches and HDF5 layout are freed while the run goes on
    solution_writer.retire({std::move(solution_snapshot.data_out),
                            std::move(solution_snapshot.hdf5_filter)});

    // the series file lists only the files written completely
    pvd_records.push_back(pending_record);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::ostringstream series;
        if (parameters.output.format == SolutionFormat::hdf5)
          {
            // DataOutBase's XDMF layout, from the grid elements recorded
            series << "<?xml version=\"1.0\" ?>\n"
                   << "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
                   << "<Xdmf Version=\"2.0\">\n"
                   << "  <Domain>\n"
                   << "    <Grid Name=\"CellTime\" GridType=\"Collection\" "
                      "CollectionType=\"Temporal\">\n";
            for (const auto &entry : pvd_records)
              if (!entry.second.empty() && entry.second.front() == ' ')
                series << entry.second;
            series << "    </Grid>\n  </Domain>\n</Xdmf>\n";
          }
        else
          {
            std::vector<std::pair<double, std::string>> files;
            for (const auto &entry : pvd_records)
              if (!entry.second.empty() && entry.second.front() != ' ')
                files.push_back(entry);
            DataOutBase::write_pvd_record(series, files);
          }
        error = write_atomically(
          parameters.output.directory + "/" +
            (parameters.output.format == SolutionFormat::hdf5 ?
               "solution.xdmf" :
               "solution.pvd"),
          series.str());
        if (!error.empty())
          pvd_records.pop_back();
      }
    throw_if_any(error, mpi_communicator);
  }

  template <int dim>
  void
  ContactProblem<dim>::write_step_row(const StepStatistics &s)
  {
    std::string error;
    if (steps_file.is_open())
      {
        const EnergyBalance &e = energy;
        std::ostringstream   row;
        row << std::setprecision(12) << s.step << "," << s.time << ","
            << s.n_cells << "," << s.n_dofs << "," << s.newton_iterations
            << "," << s.linear_iterations << "," << s.n_separating << ","
            << s.n_normal_stick << "," << s.n_damped << "," << s.n_stick << ","
            << s.n_slip << "," << s.residual << "," << e.kinetic << ","
            << e.elastic << "," << e.viscous_dissipation << ","
            << e.friction_dissipation << "," << e.damping_dissipation << ","
            << e.external_work << "," << e.numerical_dissipation << ","
            << e.defect() << "," << e.relative_defect() << ","
            << s.line_search_reductions << "," << s.wall_seconds << ","
            << (s.adapted ? 1 : 0) << "," << s.kinetic_before_adaptation << ","
            << s.elastic_before_adaptation << ","
            << s.kinetic_after_adaptation << "," << s.elastic_after_adaptation
            << "," << e.transfer_change << "," << s.time_step_halvings
            << "\n";
        error = append_complete(steps_file,
                                parameters.output.directory + "/steps.csv",
                                row.str());
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
  ContactProblem<dim>::restore_earlier_output()
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
  ContactProblem<dim>::require_checkpoint_space() const
  {
    namespace fs = std::filesystem;
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    // w_n, u_n and the branches on every cell (p4est's data file) or at
    // every dof with its index (the rank files of a simplex mesh), the
    // cells themselves, and the state with the series and the parameters
    std::uintmax_t bytes = 16 * 1024;
    for (const auto &record : pvd_records)
      bytes += record.second.size() + 32;
    for (const std::string &entry : parameters.problem_definition)
      bytes += entry.size() + 16;
    if (discretization.is_simplex())
      bytes += std::uintmax_t(dof_handler.n_dofs()) * 4 * sizeof(double) +
               Utilities::MPI::n_mpi_processes(mpi_communicator) * 8;
    else
      bytes += std::uintmax_t(
                 discretization.triangulation->n_global_active_cells()) *
               (3 * discretization.fe->n_dofs_per_cell() * sizeof(double) +
                64);
    std::string error;
    if (root)
      {
        const fs::path  dir = fs::path(parameters.output.directory) /
                             "checkpoint";
        std::error_code ec;
        // a checkpoint write cut short is deleted before the next one
        for (const auto &entry : fs::directory_iterator(dir / "writing", ec))
          {
            const std::uintmax_t size = fs::file_size(entry.path(), ec);
            bytes -= std::min(bytes, ec ? 0 : size);
          }
        error = free_space_shortfall(
          fs::is_directory(dir, ec) ? dir.string() : parameters.output.directory,
          bytes);
        if (!error.empty())
          error = "cannot write the checkpoint of step " +
                  std::to_string(step_number) + " in '" + dir.string() +
                  "': " + error + "; nothing of it was written, the earlier "
                  "checkpoints are unchanged.";
      }
    throw_if_any(error, mpi_communicator);
  }

  template <int dim>
  void
  ContactProblem<dim>::print_step(const StepStatistics &s) const
  {
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
        if (s.adapted)
          line << "\n  adapted: " << discretization.triangulation->n_global_active_cells()
               << " cells, " << dof_handler.n_dofs()
               << " dofs; energy before " << s.kinetic_before_adaptation +
                                               s.elastic_before_adaptation
               << ", after " << s.kinetic_after_adaptation +
                                  s.elastic_after_adaptation;
      }
    else
      {
        // the time left, from the mean wall time of this run's steps
        const double elapsed =
          std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                        loop_start)
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
        line << "step " << std::setw(5) << s.step << "/" << n_steps
             << "  left " << std::setw(6) << eta.str() << "  t = " << std::fixed
             << std::setprecision(4) << s.time << "  newton " << std::setw(2)
             << s.newton_iterations << "  krylov " << std::setw(4)
             << s.linear_iterations << "  sep/stick/damped " << s.n_separating
             << "/" << s.n_normal_stick << "/" << s.n_damped
             << "  stick/slip " << s.n_stick << "/" << s.n_slip
             << std::scientific << std::setprecision(2) << "  residual "
             << s.residual << "  energy " << energy.total_energy()
             << "  defect " << energy.relative_defect();
      }
    if (parameters.output.terminal != TerminalOutput::quiet)
      pcout << line.str() << std::endl;
  }

#define HEMICONTACT_INSTANTIATE(dim)                                           \
  template void ContactProblem<dim>::open_tables();                           \
  template void ContactProblem<dim>::setup_probes();                          \
  template void ContactProblem<dim>::write_probes();                          \
  template void ContactProblem<dim>::write_solution();                        \
  template void ContactProblem<dim>::finish_solution_output();                \
  template void ContactProblem<dim>::write_step_row(const StepStatistics &);  \
  template void ContactProblem<dim>::restore_earlier_output();                \
  template void ContactProblem<dim>::require_checkpoint_space() const;        \
  template void ContactProblem<dim>::print_step(const StepStatistics &) const;

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
