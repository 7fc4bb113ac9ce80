#include <deal.II/base/mpi.h>
#include <deal.II/distributed/solution_transfer.h>
#include <deal.II/distributed/tria.h>

#include <hemicontact/contact_problem.h>
#include <hemicontact/input_error.h>
#include <hemicontact/output_file.h>

#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/crc.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    namespace fs = std::filesystem;

    /** Everything of a run that is not a finite element field. */
    struct CheckpointState
    {
      unsigned int                                step_number = 0;
      double                                      time_step   = 0;
      unsigned int                                n_steps     = 0;
      std::vector<double>                         energy;
      std::vector<std::pair<double, std::string>> pvd_records;
      /** Parameters::problem_definition of the run that wrote it. */
      std::vector<std::string> problem_definition;
      /** "name size crc32" of every other file of the checkpoint. */
      std::vector<std::string> file_signatures;
      /** The number of MPI ranks that wrote it. */
      unsigned int n_ranks = 0;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &step_number &time_step &n_steps &energy &pvd_records
          &problem_definition &file_signatures &n_ranks;
      }
    };

    /**
     * The fields of a simplex-mesh checkpoint on one rank: the owned
     * entries of w_n, u_n and the branches, each with its global dof index
     * (the mesh itself is rebuilt from the parameters, partitioned the same
     * way on the same number of ranks). Returns the reason of a failure.
     */
    std::string
    write_rank_fields(const fs::path &file, const IndexSet &owned,
                      const std::vector<const TrilinosWrappers::MPI::Vector *>
                        &fields)
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
    read_rank_fields(const fs::path &file, const IndexSet &owned,
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

    /**
     * Read the state of checkpoint @p name in @p dir into @p state and
     * check every file against the signature it records. Returns why the
     * checkpoint cannot be used, or an empty string.
     */
    std::string
    checkpoint_damage(const fs::path &dir, const std::string &name,
                      CheckpointState &state)
    {
      const fs::path state_file = dir / (name + ".state");
      try
        {
          std::ifstream                 in(state_file);
          boost::archive::text_iarchive archive(in);
          archive >> state;
        }
      catch (const std::exception &e)
        {
          return "cannot read '" + state_file.string() + "': " + e.what();
        }
      if (state.file_signatures.empty())
        return "'" + state_file.string() + "' lists no files";
      for (const std::string &expected : state.file_signatures)
        {
          const std::string file = expected.substr(0, expected.find(' '));
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

    EnergyBalance
    from_vector(const std::vector<double> &v)
    {
      EnergyBalance e;
      AssertThrow(v.size() == 9, ExcMessage("corrupt checkpoint state"));
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

    std::string
    checkpoint_name(const unsigned int step)
    {
      std::ostringstream s;
      s << "step-" << std::setw(6) << std::setfill('0') << step;
      return s.str();
    }

    /** Steps of the complete checkpoints in @p dir (their .state exists). */
    std::vector<unsigned int>
    complete_checkpoints(const fs::path &dir)
    {
      std::vector<unsigned int> steps;
      std::error_code           ec;
      for (const auto &entry : fs::directory_iterator(dir, ec))
        {
          const std::string name = entry.path().filename().string();
          if (name.size() == 17 && name.rfind("step-", 0) == 0 &&
              name.substr(11) == ".state")
            steps.push_back(std::stoul(name.substr(5, 6)));
        }
      std::sort(steps.begin(), steps.end());
      return steps;
    }
  } // namespace

  template <int dim>
  bool
  ContactProblem<dim>::has_checkpoints() const
  {
    return discretization.is_simplex() ||
           dynamic_cast<const parallel::distributed::Triangulation<dim> *>(
             discretization.triangulation.get()) != nullptr;
  }

  template <int dim>
  void
  ContactProblem<dim>::write_checkpoint()
  {
    finish_solution_output(); // the series it saves lists every write
    require_checkpoint_space(); // p4est aborts on a failed write
    TimerOutput::Scope t(timer, "checkpoint");
    const fs::path     dir  = fs::path(parameters.output.directory) / "checkpoint";
    const fs::path     aside = dir / "writing";
    const std::string  name = checkpoint_name(step_number);
    const bool         root = Utilities::MPI::this_mpi_process(mpi_communicator) == 0;
    if (root)
      {
        fs::remove_all(aside);
        fs::create_directories(aside);
      }
    MPI_Barrier(mpi_communicator);

    // the fields: w_n, u_n and the branches (normal at the node's first
    // dof, tangential at its second): attached to the p4est mesh, or, on a
    // simplex mesh (rebuilt from the parameters on resume), one file per
    // rank in dof order
    TrilinosWrappers::MPI::Vector branches(locally_owned_dofs, mpi_communicator);
    for (const ContactNode<dim> &node : contact_nodes)
      if (node.locally_owned)
        {
          branches[node.dofs[0]] = static_cast<double>(node.normal_branch);
          branches[node.dofs[1]] = static_cast<double>(node.tangential_branch);
        }
    branches.compress(VectorOperation::insert);
    if (discretization.is_simplex())
      throw_if_any(write_rank_fields(
                     aside / (name + ".fields." +
                              std::to_string(Utilities::MPI::this_mpi_process(
                                mpi_communicator))),
                     locally_owned_dofs, {&velocity, &displacement, &branches}),
                   mpi_communicator);
    else
      {
        TrilinosWrappers::MPI::Vector w(locally_owned_dofs,
                                        locally_relevant_dofs,
                                        mpi_communicator);
        TrilinosWrappers::MPI::Vector u(w), b(w);
        w = velocity;
        u = displacement;
        b = branches;
        parallel::distributed::SolutionTransfer<dim,
                                                TrilinosWrappers::MPI::Vector>
          transfer(dof_handler);
        transfer.prepare_for_serialization(
          std::vector<const TrilinosWrappers::MPI::Vector *>{&w, &u, &b});
        dynamic_cast<parallel::distributed::Triangulation<dim> &>(
          *discretization.triangulation)
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
        state.time_step   = time_step;
        state.n_steps     = n_steps;
        state.energy      = to_vector(energy);
        state.pvd_records = pvd_records;
        state.problem_definition = parameters.problem_definition;
        state.n_ranks = Utilities::MPI::n_mpi_processes(mpi_communicator);
        {
          std::ofstream                 out(aside / (name + ".state"));
          boost::archive::text_oarchive archive(out);
          archive << state;
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

        // keep the last two
        const std::vector<unsigned int> steps = complete_checkpoints(dir);
        for (std::size_t i = 0; i + 2 < steps.size(); ++i)
          {
            const std::string old = checkpoint_name(steps[i]);
            for (const auto &entry : fs::directory_iterator(dir))
              if (entry.path().filename().string().rfind(old + ".", 0) == 0)
                fs::remove(entry.path());
          }
      }
    MPI_Barrier(mpi_communicator);
  }

  template <int dim>
  void
  ContactProblem<dim>::setup_from_checkpoint()
  {
    TimerOutput::Scope t(timer, "setup");
    const fs::path     dir = fs::path(parameters.output.directory) / "checkpoint";
    const std::vector<unsigned int> steps = complete_checkpoints(dir);
    require(!steps.empty(),
            "checkpoint: 'resume' is set but '" + dir.string() +
              "' holds no complete checkpoint; run without resume first (with "
              "'checkpoint/interval' > 0).");
    // the newest checkpoint whose files are all as written (checked on the
    // root, which reads them anyway); a damaged one is reported and skipped
    int         chosen = -1;
    std::string damage;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      for (int i = static_cast<int>(steps.size()) - 1; i >= 0; --i)
        {
          CheckpointState   probe;
          const std::string why =
            checkpoint_damage(dir, checkpoint_name(steps[i]), probe);
          if (why.empty())
            {
              chosen = i;
              break;
            }
          damage += (damage.empty() ? "" : "; ") + why;
          std::cerr << "hemicontact: warning: the checkpoint of step "
                    << steps[i] << " is damaged: " << why << "."
                    << (i > 0 ? " Trying the one before it." : "")
                    << std::endl;
        }
    chosen = Utilities::MPI::broadcast(mpi_communicator, chosen, 0);
    damage = Utilities::MPI::broadcast(mpi_communicator, damage, 0);
    require(chosen >= 0, "checkpoint: no checkpoint in '" + dir.string() +
                           "' can be resumed from: " + damage + ".");
    const std::string name = checkpoint_name(steps[chosen]);
    CheckpointState   state;
    {
      const std::string why = checkpoint_damage(dir, name, state);
      require(why.empty(), "checkpoint: " + why + ".");
    }
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
          const auto it = before.find(entry);
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

    TrilinosWrappers::MPI::Vector                branches;
    std::vector<TrilinosWrappers::MPI::Vector *> fields{&velocity, &displacement,
                                                        &branches};
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
        discretization.check_boundary_ids(parameters.boundary);
        setup_on_current_mesh();
        branches.reinit(locally_owned_dofs, mpi_communicator);
        const std::string why = read_rank_fields(
          dir / (name + ".fields." +
                 std::to_string(
                   Utilities::MPI::this_mpi_process(mpi_communicator))),
          locally_owned_dofs, fields);
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
        // the coarse mesh, then the refined one with its fields
        discretization.make_mesh(parameters.geometry, /*refine=*/false);
        dynamic_cast<parallel::distributed::Triangulation<dim> &>(
          *discretization.triangulation)
          .load((dir / (name + ".mesh")).string());
        discretization.check_boundary_ids(parameters.boundary);
        setup_on_current_mesh();
        branches.reinit(locally_owned_dofs, mpi_communicator);
        parallel::distributed::SolutionTransfer<dim,
                                                TrilinosWrappers::MPI::Vector>
          transfer(dof_handler);
        transfer.deserialize(fields);
      }
    old_velocity = velocity;
    TrilinosWrappers::MPI::Vector b(locally_owned_dofs, locally_relevant_dofs,
                                   mpi_communicator);
    b = branches;
    for (ContactNode<dim> &node : contact_nodes)
      {
        node.normal_branch =
          static_cast<NormalBranch>(std::lround(b[node.dofs[0]]));
        node.tangential_branch =
          static_cast<TangentialBranch>(std::lround(b[node.dofs[1]]));
      }

    step_number = state.step_number;
    energy      = from_vector(state.energy);
    pvd_records = state.pvd_records;
    update_friction_bounds(get_time());
    check_time_step_stability();
    check_convexity();
  }

  template <int dim>
  void
  ContactProblem<dim>::continue_tables()
  {
    if (Utilities::MPI::this_mpi_process(mpi_communicator) != 0)
      return;
    const fs::path dir = parameters.output.directory;
    for (const char *table : {"steps.csv", "probes.csv"})
      {
        const std::string warning =
          truncate_table((dir / table).string(), step_number);
        if (!warning.empty())
          std::cerr << "hemicontact: warning: " << warning << std::endl;
      }
  }

#define HEMICONTACT_INSTANTIATE(dim)                                           \
  template bool ContactProblem<dim>::has_checkpoints() const;                 \
  template void ContactProblem<dim>::write_checkpoint();                      \
  template void ContactProblem<dim>::setup_from_checkpoint();                 \
  template void ContactProblem<dim>::continue_tables();

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
