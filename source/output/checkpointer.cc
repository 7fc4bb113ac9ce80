#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/checkpoint_directory.h>
#include <hemicontact/output/checkpointer.h>
#include <hemicontact/output/output_file.h>
#include <hemicontact/output/run_output.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/solver/projected_operator.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

namespace hemicontact
{
  using namespace checkpoint_directory;

  namespace
  {
    /** Whether the field @p f is stored in a checkpoint. */
    template <int dim>
    bool
    is_saved(const StateField<dim> &f)
    {
      return f.saved;
    }

    /** The saved fields of @p fields by name. */
    template <int dim>
    std::map<std::string, const StateField<dim> *>
    saved_fields(const std::vector<StateField<dim>> &fields)
    {
      std::map<std::string, const StateField<dim> *> saved;
      for (const StateField<dim> &f : fields)
        if (f.saved)
          saved[f.name] = &f;
      return saved;
    }

    /** The vectors of the fields @p names of @p saved, in that order. */
    template <int dim>
    std::vector<TrilinosWrappers::MPI::Vector *>
    fields_named(const std::map<std::string, const StateField<dim> *> &saved,
                 const std::vector<std::string>                       &names)
    {
      std::vector<TrilinosWrappers::MPI::Vector *> vectors;
      for (const std::string &name : names)
        vectors.push_back(saved.at(name)->vector);
      return vectors;
    }

    /**
     * The file of a simplex-mesh checkpoint @p name holding this rank's
     * entries of the fields of @p space.
     */
    std::string
    rank_file_name(const std::string &name,
                   const std::string &space,
                   MPI_Comm           comm)
    {
      return name + ".fields." + space + "." +
             std::to_string(Utilities::MPI::this_mpi_process(comm));
    }

    /** Set by SIGTERM or SIGINT; the time loop checks it after every step. */
    volatile std::sig_atomic_t termination_requested = 0;

    extern "C" void
    request_termination(int)
    {
      termination_requested = 1;
    }
  } // namespace

  template <int dim>
  Checkpointer<dim>::Checkpointer(const Parameters &parameters,
                                  MPI_Comm          comm,
                                  TimerOutput      &timer)
    : parameters(parameters)
    , mpi_communicator(comm)
    , timer(timer)
  {}

  EnergyBalance
  CheckpointState::energy_balance() const
  {
    // read_state() checked that the names are those of the list
    EnergyBalance e;
    for (const auto &[name, value] : energy)
      for (const SavedEnergyTerm &term : saved_energy_terms())
        if (term.name == name)
          term.in(e) = value;
    return e;
  }

  template <int dim>
  bool
  Checkpointer<dim>::interruption_requested(
    const unsigned int steps_this_run) const
  {
    const CheckpointParameters &checkpoints = parameters.checkpoint;
    return Utilities::MPI::max(static_cast<int>(termination_requested),
                               mpi_communicator) > 0 ||
           (checkpoints.stop_after > 0 &&
            steps_this_run == checkpoints.stop_after);
  }

  template <int dim>
  bool
  Checkpointer<dim>::due(const unsigned int step,
                         const bool         interrupted,
                         const bool         last_step) const
  {
    const CheckpointParameters &checkpoints = parameters.checkpoint;
    const bool                  periodic =
      (checkpoints.interval > 0 && step % checkpoints.interval == 0) ||
      (checkpoints.wall_interval > 0 &&
       Utilities::MPI::max(since_checkpoint.wall_time(), mpi_communicator) >=
         checkpoints.wall_interval);
    return periodic || (interrupted && !last_step);
  }

  template <int dim>
  void
  Checkpointer<dim>::start(const bool resumed)
  {
    std::string error;
    if (!resumed && Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        run_id         = new_run_id();
        mesh_signature = mesh_signature_of(parameters.geometry);
        // checkpoints of an earlier run no longer match the output this
        // run replaces: from now on the directory names this run, so that
        // a resume does not take them (its first checkpoint removes them)
        const fs::path dir =
          fs::path(parameters.output.directory) / "checkpoint";
        std::error_code ec;
        if (fs::is_directory(dir, ec))
          error =
            write_atomically((dir / run_file_name).string(), run_id + "\n");
      }
    if (!resumed)
      throw_if_any(error, mpi_communicator);
    termination_requested = 0;
    std::signal(SIGTERM, request_termination);
    std::signal(SIGINT, request_termination);
    since_checkpoint.reset();
    since_checkpoint.start();
  }

  template <int dim>
  void
  Checkpointer<dim>::write(const ContactProblem<dim> &problem,
                           RunOutput<dim>            &output)
  {
    output.finish_solution_output(); // the series it saves lists every write
    const std::vector<SeriesRecord> &series = output.series();
    require_space(problem, series); // p4est aborts on a failed write
    const typename ContactProblem<dim>::State s           = problem.state();
    const unsigned int                        step_number = s.step_number;
    TimerOutput::Scope                        t(timer, "checkpoint");
    const fs::path dir   = fs::path(parameters.output.directory) / "checkpoint";
    const fs::path aside = dir / "writing";
    const std::string name = checkpoint_name(step_number);
    const bool  root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    std::string error;
    if (root)
      {
        fs::remove_all(aside);
        fs::create_directories(aside);
        // the directory names the run of its checkpoints before they exist
        error = write_atomically((dir / run_file_name).string(), run_id + "\n");
      }
    throw_if_any(error, mpi_communicator);

    // the saved fields of the state by space (state_fields.cc): attached
    // to the p4est mesh, one SolutionTransfer per space in the order the
    // .state lists them, or, on a simplex mesh (rebuilt from the
    // parameters on resume), one file per space and rank in dof order
    const std::vector<StateField<dim>> all_fields = problem.fields();
    const auto                         saved      = saved_fields(all_fields);
    const auto by_space = field_names_by_space(all_fields, is_saved<dim>);
    if (s.discretization.is_simplex())
      {
        std::string why;
        for (const auto &[space, names] : by_space)
          if (why.empty())
            {
              const std::vector<TrilinosWrappers::MPI::Vector *> v =
                fields_named(saved, names);
              why = write_rank_fields(aside / rank_file_name(name,
                                                             space,
                                                             mpi_communicator),
                                      *saved.at(names[0])->space->owned,
                                      {v.begin(), v.end()});
            }
        throw_if_any(why, mpi_communicator);
      }
    else
      {
        using Transfer = parallel::distributed::
          SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>;
        std::vector<std::unique_ptr<Transfer>>     transfers;
        std::vector<TrilinosWrappers::MPI::Vector> ghosted(saved.size());
        unsigned int                               n = 0;
        for (const auto &[space, names] : by_space)
          {
            const FieldSpace<dim> &fs = *saved.at(names[0])->space;
            std::vector<const TrilinosWrappers::MPI::Vector *> fields;
            for (const std::string &field : names)
              {
                ghosted[n].reinit(*fs.owned, *fs.relevant, mpi_communicator);
                ghosted[n] = *saved.at(field)->vector;
                fields.push_back(&ghosted[n++]);
              }
            transfers.push_back(std::make_unique<Transfer>(*fs.dof_handler));
            transfers.back()->prepare_for_serialization(fields);
          }
        dynamic_cast<const parallel::distributed::Triangulation<dim> &>(
          *s.discretization.triangulation)
          .save((aside / (name + ".mesh")).string());
      }
    MPI_Barrier(mpi_communicator);

    if (root)
      {
        CheckpointState state;
        for (const auto &entry : fs::directory_iterator(aside))
          state.file_signatures.push_back(file_signature(entry.path()));
        std::sort(state.file_signatures.begin(), state.file_signatures.end());
        state.step_number = step_number;
        state.time_step   = s.time_step;
        state.n_steps     = s.n_steps;
        for (const SavedEnergyTerm &term : saved_energy_terms())
          state.energy.emplace_back(term.name, term.in(s.energy));
        state.fields = by_space;
        for (const SeriesRecord &record : series)
          state.pvd_records.push_back(record.stored());
        state.problem_definition = parameters.problem_definition;
        state.n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
        state.last_step_length = s.last_step_length;
        state.run_id           = run_id;
        state.mesh_signature   = mesh_signature;
        state.constrained_amg =
          static_cast<unsigned int>(s.preconditioner.constrained_amg_status());
        state.memory_history = s.memory.saved_values();
        {
          std::ofstream out(aside / (name + ".state"), std::ios::binary);
          out << state_text(state);
        }
        // move in place, the .state last: a checkpoint without its .state
        // (interrupted while moving) is never read
        std::vector<fs::path> files;
        for (const auto &entry : fs::directory_iterator(aside))
          if (entry.path().extension() != ".state")
            files.push_back(entry.path());
        for (const fs::path &f : files)
          fs::rename(f, dir / f.filename());
        fs::rename(aside / (name + ".state"), dir / (name + ".state"));
        fs::remove_all(aside);
        keep_last_two_checkpoints(dir, run_id, step_number);
      }
    MPI_Barrier(mpi_communicator);
    since_checkpoint.reset();
    since_checkpoint.start();
  }

  template <int dim>
  void
  Checkpointer<dim>::require_space(
    const ContactProblem<dim>       &problem,
    const std::vector<SeriesRecord> &series) const
  {
    const typename ContactProblem<dim>::State s              = problem.state();
    const Discretization<dim>                &discretization = s.discretization;
    const bool root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    // the saved fields of the state (on every cell: p4est's data file; or
    // at every dof with its index: the rank files of a simplex mesh), the
    // cells themselves, and the state with the series and the parameters
    std::uintmax_t bytes = 16 * 1024;
    for (const SeriesRecord &record : series)
      bytes += record.stored().second.size() + 32;
    for (const std::string &entry : parameters.problem_definition)
      bytes += entry.size() + 16;
    const std::uintmax_t n_cells =
      discretization.triangulation->n_global_active_cells();
    const std::vector<StateField<dim>> all_fields = problem.fields();
    const auto                         saved      = saved_fields(all_fields);
    for (const auto &[space, names] :
         field_names_by_space(all_fields, is_saved<dim>))
      {
        const DoFHandler<dim> &dofs = *saved.at(names[0])->space->dof_handler;
        bytes += discretization.is_simplex() ?
                   std::uintmax_t(dofs.n_dofs()) * (1 + names.size()) *
                       sizeof(double) +
                     Utilities::MPI::n_mpi_processes(mpi_communicator) * 8 :
                   n_cells * names.size() * dofs.get_fe().n_dofs_per_cell() *
                     sizeof(double);
      }
    if (!discretization.is_simplex())
      bytes += n_cells * 64;
    std::string error;
    if (root)
      {
        const fs::path dir =
          fs::path(parameters.output.directory) / "checkpoint";
        std::error_code ec;
        // a checkpoint write cut short is deleted before the next one
        for (const auto &entry : fs::directory_iterator(dir / "writing", ec))
          {
            const std::uintmax_t size = fs::file_size(entry.path(), ec);
            bytes -= std::min(bytes, ec ? 0 : size);
          }
        error = free_space_shortfall(fs::is_directory(dir, ec) ?
                                       dir.string() :
                                       parameters.output.directory,
                                     bytes);
        if (!error.empty())
          error = "cannot write the checkpoint of step " +
                  std::to_string(s.step_number) + " in '" + dir.string() +
                  "': " + error +
                  "; nothing of it was written, the earlier "
                  "checkpoints are unchanged.";
      }
    throw_if_any(error, mpi_communicator);
  }

  template <int dim>
  const CheckpointState &
  Checkpointer<dim>::read(const unsigned int n_steps, const double time_step)
  {
    const fs::path dir = fs::path(parameters.output.directory) / "checkpoint";
    const std::vector<unsigned int> steps = complete_checkpoints(dir);
    require(!steps.empty(),
            "checkpoint: 'resume' is set but '" + dir.string() +
              "' holds no complete checkpoint; run without resume first (with "
              "'checkpoint/interval' > 0).");
    // the newest checkpoint of the run whose output the directory holds
    // with all its files as written (checked on the root, which reads them
    // anyway); any other is reported and skipped
    int         chosen = -1;
    std::string damage;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        const std::string run = recorded_run(dir);
        for (int i = static_cast<int>(steps.size()) - 1; i >= 0; --i)
          {
            state.format_version = CheckpointState::current_format_version;
            std::string why      = checkpoint_damage(dir, steps[i], state);
            // a whole file of another format version is not damage
            const bool damaged =
              !why.empty() &&
              state.format_version == CheckpointState::current_format_version;
            if (why.empty() && state.run_id != run)
              why = "'" +
                    (dir / (checkpoint_name(steps[i]) + ".state")).string() +
                    "' is of another run than the output in '" +
                    parameters.output.directory + "' (" +
                    (run.empty() ? "'" + (dir / run_file_name).string() +
                                     "' naming that run is missing" :
                                   "a run started there without --resume after "
                                   "it, and wrote no checkpoint yet") +
                    ")";
            if (why.empty())
              {
                chosen = i;
                break;
              }
            damage += (damage.empty() ? "" : "; ") + why;
            std::cerr << "hemicontact: warning: the checkpoint of step "
                      << steps[i]
                      << (damaged ? " is damaged: " : " is skipped: ") << why
                      << "." << (i > 0 ? " Trying the one before it." : "")
                      << std::endl;
          }
      }
    chosen = Utilities::MPI::broadcast(mpi_communicator, chosen, 0);
    damage = Utilities::MPI::broadcast(mpi_communicator, damage, 0);
    require(chosen >= 0,
            "checkpoint: no checkpoint in '" + dir.string() +
              "' can be resumed from: " + damage + ".");
    state = Utilities::MPI::broadcast(mpi_communicator, state, 0);
    name  = checkpoint_name(steps[chosen]);
    require(std::abs(state.time_step - time_step) <= 1e-12 * time_step &&
              state.n_steps == n_steps,
            "checkpoint: the checkpoint was written with another time step or "
            "end time than the parameter file now sets; resume with the "
            "parameters of the interrupted run.");
    {
      // a resume continues the same problem: every entry that defines it
      // must be as the checkpoint recorded it
      const auto split = [](const std::vector<std::string> &entries) {
        std::map<std::string, std::string> result;
        for (const std::string &e : entries)
          {
            const std::size_t eq = e.find(" = ");
            result[e.substr(0, eq)] =
              eq == std::string::npos ? "" : e.substr(eq + 3);
          }
        return result;
      };
      const auto  before = split(state.problem_definition);
      const auto  now    = split(parameters.problem_definition);
      std::string changes, series_changes;
      for (const auto &[entry, value] : now)
        {
          const auto        it = before.find(entry);
          const std::string old_value =
            it == before.end() ? "(not recorded)" : it->second;
          std::string &list =
            entry.rfind("output/", 0) == 0 ? series_changes : changes;
          if (old_value != value)
            list += (list.empty() ? "" : "; ") + entry + " = '" + value +
                    "' (the checkpoint's run: '" + old_value + "')";
        }
      require(changes.empty(),
              "checkpoint: the parameter file defines another problem than "
              "the run that wrote '" +
                (dir / (name + ".state")).string() + "': " + changes +
                ". A resume continues the same problem; restore these "
                "entries, or start a new run without --resume.");
      // ... and writes the series files the run began
      require(series_changes.empty(),
              "checkpoint: the parameter file writes other solution files "
              "than the run that wrote '" +
                (dir / (name + ".state")).string() + "': " + series_changes +
                ". A resume continues that run's series (solution.pvd or "
                "solution.xdmf, nodal.xdmf) in '" +
                parameters.output.directory +
                "', whose files are left as they are; restore these entries, "
                "or start a new run without --resume (in another output "
                "directory to keep these files).");
    }
    {
      // ... and so must the mesh file's content
      const std::string now =
        Utilities::MPI::broadcast(mpi_communicator,
                                  Utilities::MPI::this_mpi_process(
                                    mpi_communicator) == 0 ?
                                    mesh_signature_of(parameters.geometry) :
                                    std::string(),
                                  0);
      const std::string file = parameters.geometry.mesh_file;
      require(now == state.mesh_signature,
              "checkpoint: the mesh file '" + file +
                "' is not the file the run that wrote '" +
                (dir / (name + ".state")).string() +
                "' read (size and CRC-32 '" + signature_values(now) +
                "', recorded '" + signature_values(state.mesh_signature) +
                "'). A resume continues the same problem; restore the mesh "
                "file, or start a new run without --resume.");
    }
    run_id         = state.run_id;
    mesh_signature = state.mesh_signature;
    return state;
  }

  template <int dim>
  void
  Checkpointer<dim>::load_mesh(Discretization<dim> &discretization) const
  {
    const fs::path dir = fs::path(parameters.output.directory) / "checkpoint";
    if (discretization.is_simplex())
      {
        // the same mesh and partition as the run that wrote it, hence only
        // on the same number of ranks
        const unsigned int n_ranks =
          Utilities::MPI::n_mpi_processes(mpi_communicator);
        require(state.n_ranks == n_ranks,
                "checkpoint: '" + (dir / (name + ".state")).string() +
                  "' was written by " + std::to_string(state.n_ranks) +
                  " MPI ranks and this run has " + std::to_string(n_ranks) +
                  "; a simplex mesh resumes only on the number of ranks that "
                  "wrote its checkpoint. Resume with mpirun -np " +
                  std::to_string(state.n_ranks) + ".");
        discretization.make_mesh(parameters.geometry);
      }
    else
      {
        // the coarse mesh, then the refined one
        discretization.make_mesh(parameters.geometry, /*refine=*/false);
        dynamic_cast<parallel::distributed::Triangulation<dim> &>(
          *discretization.triangulation)
          .load((dir / (name + ".mesh")).string());
      }
  }

  template <int dim>
  void
  Checkpointer<dim>::load_fields(const std::vector<StateField<dim>> &fields)
  {
    const fs::path dir   = fs::path(parameters.output.directory) / "checkpoint";
    const auto     saved = saved_fields(fields);
    // the fields by name: those of the checkpoint against the run's
    std::set<std::string> stored;
    for (const auto &[space, names] : state.fields)
      stored.insert(names.begin(), names.end());
    std::string unknown, missing;
    for (const std::string &name : stored)
      if (!saved.count(name))
        unknown += (unknown.empty() ? "'" : ", '") + name + "'";
    for (const auto &[name, field] : saved)
      if (!stored.count(name))
        missing += (missing.empty() ? "'" : ", '") + name + "'";
    require(unknown.empty() && missing.empty(),
            "checkpoint: '" + (dir / (name + ".state")).string() +
              "' does not hold the fields of this run's state" +
              (unknown.empty() ?
                 "" :
                 ": it holds " + unknown + ", which this run does not have") +
              (missing.empty() ? "" :
                                 std::string(unknown.empty() ? ":" : ";") +
                                   " it lacks " + missing) +
              ". A resume continues the same problem with the same program; "
              "start a new run without --resume.");
    for (const auto &[space, names] : state.fields)
      {
        // every field of a space lives on the same space in this run
        const FieldSpace<dim> &fs = *saved.at(names[0])->space;
        for (const std::string &field : names)
          require(saved.at(field)->space == &fs,
                  "checkpoint: '" + (dir / (name + ".state")).string() +
                    "' holds the field '" + field + "' on the space '" + space +
                    "', this run on '" + saved.at(field)->space->name +
                    "'; start a new run without --resume.");
        std::vector<TrilinosWrappers::MPI::Vector *> targets =
          fields_named(saved, names);
        if (fs.dof_handler->get_fe().reference_cell().is_simplex())
          {
            const std::string why =
              read_rank_fields(dir /
                                 rank_file_name(name, space, mpi_communicator),
                               *fs.owned,
                               targets);
            for (TrilinosWrappers::MPI::Vector *v : targets)
              v->compress(VectorOperation::insert);
            require(Utilities::MPI::min(why.empty() ? 1 : 0,
                                        mpi_communicator) == 1,
                    "checkpoint: " +
                      (why.empty() ?
                         std::string("the fields of another rank do "
                                     "not fit this run's mesh") :
                         why) +
                      "; resume with the parameters of the interrupted run.");
          }
        else
          {
            // in the order write() attached them
            parallel::distributed::
              SolutionTransfer<dim, TrilinosWrappers::MPI::Vector>
                transfer(*fs.dof_handler);
            transfer.deserialize(targets);
          }
      }
  }

  template <int dim>
  std::vector<SeriesRecord>
  Checkpointer<dim>::series() const
  {
    std::vector<SeriesRecord> records;
    for (const auto &entry : state.pvd_records)
      records.push_back(SeriesRecord::from_stored(entry));
    return records;
  }

  template class Checkpointer<2>;
  template class Checkpointer<3>;
} // namespace hemicontact
