#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/crc.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/checkpointer.h>
#include <hemicontact/output/output_file.h>
#include <hemicontact/output/run_output.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/solver/projected_operator.h>

#include <cctype>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <random>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    namespace fs = std::filesystem;

    /** The number of values of EnergyBalance in a checkpoint. */
    constexpr std::size_t n_energy_values = 9;

    /** The last line of a .state file: the CRC-32 of everything before it. */
    const std::string state_checksum_label = "crc32 ";

    /** CRC-32 of @p text. */
    std::uint32_t
    crc32_of(const std::string &text)
    {
      boost::crc_32_type crc;
      crc.process_bytes(text.data(), text.size());
      return crc.checksum();
    }

    /**
     * @p state as a text archive followed by the line "crc32 N" of that
     * text (so that a change of any entry is seen).
     */
    std::string
    state_text(const CheckpointState &state)
    {
      std::ostringstream out;
      {
        boost::archive::text_oarchive archive(out);
        archive << state;
      }
      out << "\n";
      return out.str() + state_checksum_label +
             std::to_string(crc32_of(out.str())) + "\n";
    }

    /**
     * Read the .state file @p file into @p state; the reason why it cannot
     * be used (unreadable, its checksum or content not as written), or an
     * empty string.
     */
    std::string
    read_state(const fs::path &file, CheckpointState &state)
    {
      const std::string name = "'" + file.string() + "'";
      std::ifstream     in(file, std::ios::binary);
      if (!in)
        return "cannot read " + name;
      std::ostringstream content;
      content << in.rdbuf();
      const std::string text = content.str();
      const std::size_t last =
        text.size() < 2 ? std::string::npos : text.rfind('\n', text.size() - 2);
      if (last == std::string::npos || text.compare(last + 1,
                                                    state_checksum_label.size(),
                                                    state_checksum_label) != 0)
        return name + " is cut short (no checksum line)";
      const std::string body = text.substr(0, last + 1);
      if (text.substr(last + 1 + state_checksum_label.size()) !=
          std::to_string(crc32_of(body)) + "\n")
        return name + " has been changed (its CRC-32 is not the one recorded "
                      "in it)";
      try
        {
          std::istringstream            body_in(body);
          boost::archive::text_iarchive archive(body_in);
          archive >> state;
        }
      catch (const std::exception &e)
        {
          return "cannot read " + name + ": " + e.what();
        }
      if (state.energy.size() != n_energy_values || state.n_ranks == 0 ||
          !(state.time_step > 0) || state.step_number > state.n_steps ||
          state.constrained_amg > 2)
        return name + " holds an invalid state (" +
               std::to_string(state.energy.size()) + " energy values of " +
               std::to_string(n_energy_values) + ", step " +
               std::to_string(state.step_number) + " of " +
               std::to_string(state.n_steps) + ")";
      return "";
    }

    /**
     * The fields of a simplex-mesh checkpoint on one rank: the owned
     * entries of w_n, u_n and the branches, each with its global dof index
     * (the mesh itself is rebuilt from the parameters, partitioned the same
     * way on the same number of ranks). Returns the reason of a failure.
     */
    std::string
    write_rank_fields(
      const fs::path                                           &file,
      const IndexSet                                           &owned,
      const std::vector<const TrilinosWrappers::MPI::Vector *> &fields)
    {
      std::ofstream       out(file, std::ios::binary);
      const std::uint64_t n = owned.n_elements();
      out.write(reinterpret_cast<const char *>(&n), sizeof n);
      for (const types::global_dof_index i : owned)
        {
          const std::uint64_t index = i;
          out.write(reinterpret_cast<const char *>(&index), sizeof index);
          for (const TrilinosWrappers::MPI::Vector *v : fields)
            {
              const double value = (*v)[i];
              out.write(reinterpret_cast<const char *>(&value), sizeof value);
            }
        }
      out.close();
      return out ? "" : "cannot write '" + file.string() + "'";
    }

    /** Read write_rank_fields()'s file; the reason if it does not fit. */
    std::string
    read_rank_fields(const fs::path                                     &file,
                     const IndexSet                                     &owned,
                     const std::vector<TrilinosWrappers::MPI::Vector *> &fields)
    {
      const std::string other_partition =
        "'" + file.string() +
        "' holds the fields of another mesh partition than this run builds";
      std::ifstream in(file, std::ios::binary);
      std::uint64_t n = 0;
      in.read(reinterpret_cast<char *>(&n), sizeof n);
      if (!in || n != owned.n_elements())
        return other_partition;
      for (std::uint64_t k = 0; k < n; ++k)
        {
          std::uint64_t index = 0;
          in.read(reinterpret_cast<char *>(&index), sizeof index);
          if (!in || !owned.is_element(index))
            return other_partition;
          for (TrilinosWrappers::MPI::Vector *v : fields)
            {
              double value = 0;
              in.read(reinterpret_cast<char *>(&value), sizeof value);
              (*v)[index] = value;
            }
        }
      return in ? "" : "'" + file.string() + "' is cut short";
    }

    /** "name size crc32" of @p file ("name missing" if it cannot be read). */
    std::string
    file_signature(const fs::path &file)
    {
      std::ifstream in(file, std::ios::binary);
      if (!in)
        return file.filename().string() + " missing";
      boost::crc_32_type crc;
      std::vector<char>  buffer(1 << 20);
      std::uintmax_t     size = 0;
      while (in)
        {
          in.read(buffer.data(), buffer.size());
          crc.process_bytes(buffer.data(), in.gcount());
          size += in.gcount();
        }
      return file.filename().string() + " " + std::to_string(size) + " " +
             std::to_string(crc.checksum());
    }

    std::string
    checkpoint_name(const unsigned int step)
    {
      std::ostringstream s;
      s << "step-" << std::setw(6) << std::setfill('0') << step;
      return s.str();
    }

    /**
     * Read the state of the checkpoint of @p step in @p dir into @p state
     * and check it (it records that step) and every file against the
     * signature it records. Returns why the checkpoint cannot be used, or
     * an empty string.
     */
    std::string
    checkpoint_damage(const fs::path    &dir,
                      const unsigned int step,
                      CheckpointState   &state)
    {
      const fs::path    state_file = dir / (checkpoint_name(step) + ".state");
      const std::string why        = read_state(state_file, state);
      if (!why.empty())
        return why;
      if (state.step_number != step)
        return "'" + state_file.string() + "' holds the checkpoint of step " +
               std::to_string(state.step_number) +
               ", not of the step its name says (renamed?)";
      if (state.file_signatures.empty())
        return "'" + state_file.string() + "' lists no files";
      for (const std::string &expected : state.file_signatures)
        {
          const std::string file  = expected.substr(0, expected.find(' '));
          const std::string found = file_signature(dir / file);
          if (found != expected)
            return "'" + (dir / file).string() +
                   "' is not the file the checkpoint wrote (size and CRC-32 '" +
                   found.substr(file.size() + 1) + "', recorded '" +
                   expected.substr(file.size() + 1) + "')";
        }
      return "";
    }

    std::vector<double>
    to_vector(const EnergyBalance &e)
    {
      return {e.kinetic,
              e.elastic,
              e.initial_energy,
              e.viscous_dissipation,
              e.friction_dissipation,
              e.damping_dissipation,
              e.external_work,
              e.numerical_dissipation,
              e.transfer_change};
    }

    /**
     * The step of a file of a checkpoint ("step-" + at least six digits +
     * "." + anything), or -1 for any other name; @p suffix: what follows
     * the digits.
     */
    long long
    checkpoint_step(const std::string &name, std::string &suffix)
    {
      std::size_t end = 5;
      while (end < name.size() && end < 5 + 10 &&
             std::isdigit(static_cast<unsigned char>(name[end])))
        ++end;
      if (name.rfind("step-", 0) != 0 || end < 11 || end == name.size() ||
          name[end] != '.')
        return -1;
      suffix = name.substr(end);
      return std::stoll(name.substr(5, end - 5));
    }

    /** Steps of the complete checkpoints in @p dir (their .state exists). */
    std::vector<unsigned int>
    complete_checkpoints(const fs::path &dir)
    {
      std::vector<unsigned int> steps;
      std::error_code           ec;
      for (const auto &entry : fs::directory_iterator(dir, ec))
        {
          std::string     suffix;
          const long long step =
            checkpoint_step(entry.path().filename().string(), suffix);
          if (step >= 0 && step <= std::numeric_limits<unsigned int>::max() &&
              suffix == ".state")
            steps.push_back(static_cast<unsigned int>(step));
        }
      std::sort(steps.begin(), steps.end());
      return steps;
    }

    /** The file naming the run whose output is in OUTPUT (in
     * OUTPUT/checkpoint). */
    const std::string run_file_name = "run";

    /** The run id in @p dir's run file, "" if there is none. */
    std::string
    recorded_run(const fs::path &dir)
    {
      std::ifstream in(dir / run_file_name);
      std::string   id;
      in >> id;
      return id;
    }

    /** A new run id: 64 random bits in hex. */
    std::string
    new_run_id()
    {
      std::random_device rd;
      std::ostringstream s;
      s << std::hex << std::setw(8) << std::setfill('0') << rd() << std::setw(8)
        << std::setfill('0') << rd();
      return s.str();
    }

    /** The signature of the mesh file @p geometry reads ("" if none). */
    std::string
    mesh_signature_of(const GeometryParameters &geometry)
    {
      return geometry.mesh_type == MeshType::gmsh ?
               file_signature(geometry.mesh_file) :
               "";
    }

    /** The size and CRC-32 of a file_signature() (without the name). */
    std::string
    signature_values(const std::string &signature)
    {
      const std::size_t space = signature.find(' ');
      return space == std::string::npos ? "none" : signature.substr(space + 1);
    }

    /**
     * The branches of the owned nodes of @p nodes as a field: the normal
     * branch at a node's first dof, the tangential at its second.
     */
    template <int dim>
    void
    branches_to_field(const std::vector<ContactNode<dim>> &nodes,
                      TrilinosWrappers::MPI::Vector       &field)
    {
      for (const ContactNode<dim> &node : nodes)
        if (node.locally_owned)
          {
            field[node.dofs[0]] = static_cast<double>(node.normal_branch);
            field[node.dofs[1]] = static_cast<double>(node.tangential_branch);
          }
      field.compress(VectorOperation::insert);
    }

    /**
     * @p nodes with, at the owned ones, the branches whose constrained
     * directions the constrained AMG of @p preconditioner was built for
     * (its operators' nodes are the owned nodes in this order); unchanged
     * if it has none.
     */
    template <int dim>
    std::vector<ContactNode<dim>>
    constrained_amg_branches(const std::vector<ContactNode<dim>> &nodes,
                             const StepPreconditioner<dim> &preconditioner)
    {
      std::vector<ContactNode<dim>>      result(nodes);
      const std::vector<Tensor<2, dim>> &directions =
        preconditioner.constrained_directions();
      if (directions.empty())
        return result;
      unsigned int i = 0;
      for (ContactNode<dim> &node : result)
        if (node.locally_owned)
          {
            AssertIndexRange(i, directions.size());
            // sum e e over nodal::constrained_directions(): nu nu for normal
            // stick, the tangent plane's projector for tangential stick
            const double normal_part =
              node.normal * (directions[i] * node.normal);
            node.normal_branch     = normal_part > 0.5 ? NormalBranch::stick :
                                                         NormalBranch::separating;
            node.tangential_branch = trace(directions[i]) - normal_part > 0.5 ?
                                       TangentialBranch::stick :
                                       TangentialBranch::slip;
            ++i;
          }
      AssertDimension(i, directions.size());
      return result;
    }

    /**
     * After a checkpoint of step @p step of run @p run was written into
     * @p dir: keep it and the one before it of the same run, remove every
     * other checkpoint file (older ones, those of an earlier run whose
     * output this run replaced, unreadable or incomplete ones, and those
     * beyond @p step that a resumed run left behind).
     */
    void
    keep_last_two_checkpoints(const fs::path    &dir,
                              const std::string &run,
                              const unsigned int step)
    {
      std::vector<unsigned int> kept;
      for (const unsigned int s : complete_checkpoints(dir))
        {
          CheckpointState state;
          if (s <= step &&
              read_state(dir / (checkpoint_name(s) + ".state"), state)
                .empty() &&
              state.run_id == run)
            kept.push_back(s);
        }
      if (kept.size() > 2)
        kept.erase(kept.begin(), kept.end() - 2);
      std::vector<fs::path> old;
      std::error_code       ec;
      for (const auto &entry : fs::directory_iterator(dir, ec))
        {
          std::string     suffix;
          const long long s =
            checkpoint_step(entry.path().filename().string(), suffix);
          if (s >= 0 && std::find(kept.begin(), kept.end(), s) == kept.end())
            old.push_back(entry.path());
        }
      for (const fs::path &f : old)
        fs::remove(f, ec);
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
    const std::vector<double> &v = energy;
    EnergyBalance              e;
    AssertDimension(v.size(), n_energy_values); // read_state() checks it
    e.kinetic               = v[0];
    e.elastic               = v[1];
    e.initial_energy        = v[2];
    e.viscous_dissipation   = v[3];
    e.friction_dissipation  = v[4];
    e.damping_dissipation   = v[5];
    e.external_work         = v[6];
    e.numerical_dissipation = v[7];
    e.transfer_change       = v[8];
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

    // the fields: w_n, u_n, the branches, w_{n-1} and the branches the
    // constrained AMG was built for: attached to the p4est mesh, or, on a
    // simplex mesh (rebuilt from the parameters on resume), one file per
    // rank in dof order
    TrilinosWrappers::MPI::Vector branches(s.locally_owned_dofs,
                                           mpi_communicator);
    TrilinosWrappers::MPI::Vector amg_branches(branches);
    branches_to_field(s.contact_nodes, branches);
    branches_to_field(constrained_amg_branches(s.contact_nodes,
                                               s.preconditioner),
                      amg_branches);
    const std::vector<const TrilinosWrappers::MPI::Vector *> owned_fields{
      &s.velocity, &s.displacement, &branches, &s.old_velocity, &amg_branches};
    if (s.discretization.is_simplex())
      throw_if_any(write_rank_fields(
                     aside / (name + ".fields." +
                              std::to_string(Utilities::MPI::this_mpi_process(
                                mpi_communicator))),
                     s.locally_owned_dofs,
                     owned_fields),
                   mpi_communicator);
    else
      {
        std::vector<TrilinosWrappers::MPI::Vector> ghosted(owned_fields.size());
        std::vector<const TrilinosWrappers::MPI::Vector *> fields;
        for (unsigned int i = 0; i < ghosted.size(); ++i)
          {
            ghosted[i].reinit(s.locally_owned_dofs,
                              s.locally_relevant_dofs,
                              mpi_communicator);
            ghosted[i] = *owned_fields[i];
            fields.push_back(&ghosted[i]);
          }
        parallel::distributed::SolutionTransfer<dim,
                                                TrilinosWrappers::MPI::Vector>
          transfer(s.dof_handler);
        transfer.prepare_for_serialization(fields);
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
        state.energy      = to_vector(s.energy);
        for (const SeriesRecord &record : series)
          state.pvd_records.push_back(record.stored());
        state.problem_definition = parameters.problem_definition;
        state.n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
        state.last_step_length = s.last_step_length;
        state.run_id           = run_id;
        state.mesh_signature   = mesh_signature;
        state.constrained_amg =
          static_cast<unsigned int>(s.preconditioner.constrained_amg_status());
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
    // w_n, u_n and the branches on every cell (p4est's data file) or at
    // every dof with its index (the rank files of a simplex mesh), the
    // cells themselves, and the state with the series and the parameters
    std::uintmax_t bytes = 16 * 1024;
    for (const SeriesRecord &record : series)
      bytes += record.stored().second.size() + 32;
    for (const std::string &entry : parameters.problem_definition)
      bytes += entry.size() + 16;
    if (discretization.is_simplex())
      bytes += std::uintmax_t(s.dof_handler.n_dofs()) * 4 * sizeof(double) +
               Utilities::MPI::n_mpi_processes(mpi_communicator) * 8;
    else
      bytes +=
        std::uintmax_t(discretization.triangulation->n_global_active_cells()) *
        (3 * discretization.fe->n_dofs_per_cell() * sizeof(double) + 64);
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
            std::string why     = checkpoint_damage(dir, steps[i], state);
            const bool  damaged = !why.empty();
            if (!damaged && state.run_id != run)
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
      std::string changes;
      for (const auto &[entry, value] : now)
        {
          const auto        it = before.find(entry);
          const std::string old_value =
            it == before.end() ? "(not recorded)" : it->second;
          if (old_value != value)
            changes += (changes.empty() ? "" : "; ") + entry + " = '" + value +
                       "' (the checkpoint's run: '" + old_value + "')";
        }
      require(changes.empty(),
              "checkpoint: the parameter file defines another problem than "
              "the run that wrote '" +
                (dir / (name + ".state")).string() + "': " + changes +
                ". A resume continues the same problem; restore these "
                "entries, or start a new run without --resume.");
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
  Checkpointer<dim>::load_fields(
    const DoFHandler<dim>                              &dof_handler,
    const IndexSet                                     &owned,
    const std::vector<TrilinosWrappers::MPI::Vector *> &fields)
  {
    const fs::path dir = fs::path(parameters.output.directory) / "checkpoint";
    if (dof_handler.get_fe().reference_cell().is_simplex())
      {
        const std::string why =
          read_rank_fields(dir /
                             (name + ".fields." +
                              std::to_string(Utilities::MPI::this_mpi_process(
                                mpi_communicator))),
                           owned,
                           fields);
        for (TrilinosWrappers::MPI::Vector *v : fields)
          v->compress(VectorOperation::insert);
        require(Utilities::MPI::min(why.empty() ? 1 : 0, mpi_communicator) == 1,
                "checkpoint: " +
                  (why.empty() ? std::string("the fields of another rank do "
                                             "not fit this run's mesh") :
                                 why) +
                  "; resume with the parameters of the interrupted run.");
      }
    else
      {
        parallel::distributed::SolutionTransfer<dim,
                                                TrilinosWrappers::MPI::Vector>
                                                     transfer(dof_handler);
        std::vector<TrilinosWrappers::MPI::Vector *> targets(fields);
        transfer.deserialize(targets);
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
