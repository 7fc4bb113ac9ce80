#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/contact_table.h>
#include <hemicontact/output/output_file.h>
#include <hemicontact/output/run_output.h>
#include <hemicontact/problem/error_indicators.h>

#include <cerrno>
#include <list>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    /** Stress components (cell averages) and von Mises, for DataOut. */
    template <int dim>
    std::vector<Vector<float>>
    cell_stresses(const DoFHandler<dim>               &dof_handler,
                  const Mapping<dim>                  &mapping,
                  const Quadrature<dim>               &quadrature,
                  const KelvinVoigtMaterial<dim>      &material,
                  const TrilinosWrappers::MPI::Vector &w,
                  const TrilinosWrappers::MPI::Vector &u)
    {
      const unsigned int         n_components = dim * (dim + 1) / 2 + 1;
      std::vector<Vector<float>> result(
        n_components,
        Vector<float>(dof_handler.get_triangulation().n_active_cells()));
      FEValues<dim>                        fe_values(mapping,
                              dof_handler.get_fe(),
                              quadrature,
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

    /**
     * The scalar nodal field @p f (on a space of its own) on w and u's
     * space of @p state: its value at each vertex in the vertex's first
     * component, 0 in the others.
     */
    template <int dim>
    TrilinosWrappers::MPI::Vector
    first_component_at_nodes(const StateField<dim>   &f,
                             const ProblemState<dim> &state)
    {
      TrilinosWrappers::MPI::Vector field(*f.space->owned,
                                          *f.space->relevant,
                                          state.mpi_communicator);
      field = *f.vector;
      TrilinosWrappers::MPI::Vector result(state.locally_owned_dofs,
                                           state.mpi_communicator);
      for (const auto &cell : state.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const typename DoFHandler<dim>::active_cell_iterator other(
              &cell->get_triangulation(),
              cell->level(),
              cell->index(),
              f.space->dof_handler);
            for (const unsigned int v : cell->vertex_indices())
              if (const auto i = cell->vertex_dof_index(v, 0);
                  state.locally_owned_dofs.is_element(i))
                result[i] = field[other->vertex_dof_index(v, 0)];
          }
      result.compress(VectorOperation::insert);
      return result;
    }
  } // namespace

  template <int dim>
  void
  RunOutput<dim>::write_solution(const ContactProblem<dim> &problem)
  {
    if (parameters.output.output_interval == 0)
      return;
    start_solution_write(problem);
    TimerOutput::Scope t(timer, "output");
    write_contact_table(problem, parameters.output.directory, mpi_communicator);
    if (nodal_writer)
      {
        const typename ContactProblem<dim>::State state = problem.state();
        // the written fields of the state on w and u's space
        // (state_fields.cc), then the memory's nodal values
        const std::vector<StateField<dim>> state_fields = problem.fields();
        std::vector<typename NodalHdf5Writer<dim>::Field> fields;
        // the scalar nodal fields of other spaces (the temperature), their
        // value at each node in its first component
        std::list<TrilinosWrappers::MPI::Vector> on_nodes;
        for (const StateField<dim> &f : state_fields)
          if (f.written && f.space->dof_handler == &state.dof_handler)
            fields.push_back({f.name, f.vector});
          else if (f.written && f.layout == FieldLayout::scalar_nodal)
            {
              on_nodes.push_back(first_component_at_nodes(f, state));
              fields.push_back({f.name, &on_nodes.back()});
            }
        // N_i nu_i, the memory's part of the traction (doc/theory.md 11.9)
        if (state.memory.contact_memory().normal_active())
          fields.push_back(
            {"normal_memory", &state.memory.contact_memory().pressure()});
        // the wear depth at each contact node's first dof (11.12)
        if (state.memory.contact_memory().wear_active())
          fields.push_back({"wear", &state.memory.contact_memory().wear()});
        nodal_writer->write(state.dof_handler,
                            fields,
                            state.step_number,
                            state.time,
                            "displacement");
      }
  }

  template <int dim>
  void
  RunOutput<dim>::start_solution_write(const ContactProblem<dim> &problem)
  {
    finish_solution_output();
    TimerOutput::Scope t(timer, "output");

    const typename ContactProblem<dim>::State state       = problem.state();
    const DoFHandler<dim>                    &dof_handler = state.dof_handler;
    const Discretization<dim>      &discretization = state.discretization;
    const KelvinVoigtMaterial<dim> &material       = state.material;

    // copies of what the write reads, so that the run can go on meanwhile
    SolutionSnapshot &snapshot = solution_snapshot;
    snapshot.step              = state.step_number;
    snapshot.time              = state.time;
    snapshot.velocity.reinit(state.locally_owned_dofs,
                             state.locally_relevant_dofs,
                             mpi_communicator);
    snapshot.displacement.reinit(snapshot.velocity);
    snapshot.velocity     = state.velocity;
    snapshot.displacement = state.displacement;
    TrilinosWrappers::MPI::Vector branch(snapshot.velocity);

    TrilinosWrappers::MPI::Vector branch_owned(state.locally_owned_dofs,
                                               mpi_communicator);
    for (const auto i : state.locally_owned_dofs)
      branch_owned[i] = -1;
    for (const ContactNode<dim> &node : state.contact_nodes)
      if (node.locally_owned)
        {
          branch_owned[node.dofs[0]] = static_cast<int>(node.normal_branch);
          branch_owned[node.dofs[1]] = static_cast<int>(node.tangential_branch);
          if (dim == 3)
            branch_owned[node.dofs[dim - 1]] = 1;
        }
    branch_owned.compress(VectorOperation::insert);
    branch = branch_owned;

    snapshot.data_out      = std::make_unique<DataOut<dim>>();
    DataOut<dim> &data_out = *snapshot.data_out;
    data_out.attach_dof_handler(dof_handler);
    // the written fields of the state (state_fields.cc), each on its space
    // (DataOut copies them)
    for (const StateField<dim> &f : problem.fields())
      if (f.written)
        {
          const FieldSpace<dim>        &space = *f.space;
          TrilinosWrappers::MPI::Vector field(*space.owned,
                                              *space.relevant,
                                              mpi_communicator);
          field                = *f.vector;
          const unsigned int n = space.dof_handler->get_fe().n_components();
          const bool vec = n == dim && f.layout != FieldLayout::scalar_nodal;
          const std::vector<std::string> names(n, f.name);
          const std::vector<
            DataComponentInterpretation::DataComponentInterpretation>
            interpretation(
              n,
              vec ? DataComponentInterpretation::component_is_part_of_vector :
                    DataComponentInterpretation::component_is_scalar);
          if (space.dof_handler == &dof_handler)
            data_out.add_data_vector(field,
                                     names,
                                     DataOut<dim>::type_dof_data,
                                     interpretation);
          else
            data_out.add_data_vector(*space.dof_handler,
                                     field,
                                     names,
                                     interpretation);
        }
    std::vector<std::string> branch_names = {"normal_branch",
                                             "tangential_branch"};
    if (dim == 3)
      branch_names.push_back("contact_node");
    data_out.add_data_vector(
      branch,
      branch_names,
      DataOut<dim>::type_dof_data,
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
      cell_data.emplace_back("refinement_indicator",
                             refinement_indicators(problem));
    // the memory part M_n of the stress, which stress_* leaves out
    // (doc/theory.md, section 11)
    if (state.memory.stress_active())
      {
        const std::vector<Vector<float>> memory_stress =
          state.memory.cell_stress(dof_handler,
                                   *discretization.mapping,
                                   discretization.cell_quadrature(2));
        const char  *xyz[] = {"x", "y", "z"};
        unsigned int c     = 0;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j)
            cell_data.emplace_back(std::string("memory_stress_") + xyz[i] +
                                     xyz[j],
                                   memory_stress[c++]);
      }
    // the coupled fields' cell data, e.g. the thermal part -c_e theta of
    // the stress and the heat flux (doc/theory.md, section 13)
    for (auto &field : state.coupled_fields.cell_output(state.added_fields))
      cell_data.push_back(std::move(field));
    // eta_K of the step written; 0 before the first step
    if (parameters.output.error_estimate)
      {
        const ErrorEstimate *estimate = problem.last_error_estimate();
        cell_data.emplace_back("error_estimate",
                               estimate != nullptr ?
                                 estimate->cell_values() :
                                 Vector<float>(mesh.n_active_cells()));
      }

    // the cell stresses and the cell fields are added here, on the calling
    // thread: deal.II 9.6's add_data_vector() copies even a cell vector into
    // a distributed vector, a collective MPI call, which on the writer's
    // thread would race with the next step's MPI calls (OpenMPI 5 aborted
    // in free() then); deal.II 9.4 keeps a pointer to each, so they live in
    // the snapshot until the job has built the patches
    const Quadrature<dim> quadrature = discretization.cell_quadrature(2);
    {
      std::vector<Vector<float>> stresses =
        cell_stresses(dof_handler,
                      *discretization.mapping,
                      quadrature,
                      material,
                      snapshot.velocity,
                      snapshot.displacement);
      const char *xyz[] = {"x", "y", "z"};
      snapshot.cell_data.clear();
      unsigned int c = 0;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          snapshot.cell_data.emplace_back(std::string("stress_") + xyz[i] +
                                            xyz[j],
                                          std::move(stresses[c++]));
      snapshot.cell_data.emplace_back("von_mises", std::move(stresses[c]));
      for (auto &field : cell_data)
        snapshot.cell_data.push_back(std::move(field));
      for (const auto &[name, field] : snapshot.cell_data)
        data_out.add_data_vector(field, name, DataOut<dim>::type_cell_data);
    }

    // the job, on the writer's thread and without MPI: the patches and the
    // VTU files, or the data in HDF5 layout
    const bool         hdf5 = parameters.output.format == SolutionFormat::hdf5;
    const std::string  directory = parameters.output.directory + "/";
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    const std::string stem =
      "solution_" + Utilities::int_to_string(snapshot.step, 5);
    pending_record = {snapshot.time, stem + (hdf5 ? ".h5" : ".pvtu"), ""};
    if (hdf5)
      snapshot.hdf5_filter = std::make_unique<DataOutBase::DataOutFilter>(
        DataOutBase::DataOutFilterFlags(/*filter_duplicates=*/false,
                                        /*xdmf_hdf5_output=*/true));
    snapshot.reference_cell = discretization.fe->reference_cell();
    // the job reads the problem's mesh, dofs and material, which stay
    // unchanged until finish_solution_output()
    auto job = [this,
                mapping = &*discretization.mapping,
                hdf5,
                directory,
                rank,
                n_ranks,
                stem]() -> std::string {
      const SolutionSnapshot &s        = solution_snapshot;
      DataOut<dim>           &data_out = *s.data_out;
      data_out.build_patches(*mapping);

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
          auto               piece  = [&](const unsigned int r) {
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
  RunOutput<dim>::finish_solution_output()
  {
    if (!solution_writer.pending())
      return;
    TimerOutput::Scope t(timer, "output");
    const std::string  prefix = "cannot write the solution files of step " +
                               std::to_string(solution_snapshot.step) +
                               " in '" + parameters.output.directory + "': ";
    std::string error = solution_writer.wait();
    if (!error.empty())
      error = prefix + error + ".";
    throw_if_any(error, mpi_communicator);

    // HDF5: the collective write of the data the job arranged
    if (parameters.output.format == SolutionFormat::hdf5)
      {
        const DataOut<dim> &data_out = *solution_snapshot.data_out;
        const DataOutBase::DataOutFilter &filter =
          *solution_snapshot.hdf5_filter;
        const std::string h5 = pending_record.file;
        errno                = 0;
        try
          {
            data_out.write_hdf5_parallel(filter,
                                         parameters.output.directory + "/" + h5,
                                         mpi_communicator);
            pending_record.xdmf_grid =
              data_out
                .create_xdmf_entry(filter,
                                   h5,
                                   pending_record.time,
                                   mpi_communicator)
                .get_xdmf_content(3, solution_snapshot.reference_cell);
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
    records.push_back(pending_record);
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
            for (const SeriesRecord &record : records)
              series << record.xdmf_grid;
            series << "    </Grid>\n  </Domain>\n</Xdmf>\n";
          }
        else
          {
            std::vector<std::pair<double, std::string>> files;
            for (const SeriesRecord &record : records)
              if (record.xdmf_grid.empty() && !record.file.empty())
                files.emplace_back(record.time, record.file);
            DataOutBase::write_pvd_record(series, files);
          }
        error =
          write_atomically(parameters.output.directory + "/" +
                             (parameters.output.format == SolutionFormat::hdf5 ?
                                "solution.xdmf" :
                                "solution.pvd"),
                           series.str());
        if (!error.empty())
          records.pop_back();
      }
    throw_if_any(error, mpi_communicator);
  }

  template <int dim>
  void
  RunOutput<dim>::restart_series()
  {
    finish_solution_output();
    records.clear();
    if (nodal_writer)
      nodal_writer->keep_steps_up_to(0);
  }

  template class RunOutput<2>;
  template class RunOutput<3>;
} // namespace hemicontact
