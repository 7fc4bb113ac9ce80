#include <boost/archive/text_iarchive.hpp>
#include <boost/archive/text_oarchive.hpp>
#include <boost/crc.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/output/checkpoint_directory.h>
#include <hemicontact/output/output_file.h>

#include <fstream>
#include <iomanip>
#include <random>
#include <sstream>

namespace hemicontact
{
  namespace checkpoint_directory
  {
    namespace
    {
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
    } // namespace

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
      if (state.format_version != CheckpointState::current_format_version)
        return name + " was written by checkpoint format version " +
               std::to_string(state.format_version) +
               ", this program reads version " +
               std::to_string(CheckpointState::current_format_version) +
               "; start a new run without --resume";
      // the list as written, or without the terms added at its end since
      bool energy_terms = state.energy.size() <= saved_energy_terms().size();
      for (std::size_t i = 0; energy_terms && i < state.energy.size(); ++i)
        energy_terms = state.energy[i].first == saved_energy_terms()[i].name;
      if (!energy_terms || state.n_ranks == 0 || !(state.time_step > 0) ||
          state.step_number > state.n_steps || state.constrained_amg > 2)
        return name + " holds an invalid state (" +
               std::to_string(state.energy.size()) + " energy terms of " +
               std::to_string(saved_energy_terms().size()) + ", step " +
               std::to_string(state.step_number) + " of " +
               std::to_string(state.n_steps) + ")";
      return "";
    }

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

    std::string
    recorded_run(const fs::path &dir)
    {
      std::ifstream in(dir / run_file_name);
      std::string   id;
      in >> id;
      return id;
    }

    std::string
    new_run_id()
    {
      std::random_device rd;
      std::ostringstream s;
      s << std::hex << std::setw(8) << std::setfill('0') << rd() << std::setw(8)
        << std::setfill('0') << rd();
      return s.str();
    }

    std::string
    mesh_signature_of(const GeometryParameters &geometry)
    {
      return geometry.mesh_type == MeshType::gmsh ?
               file_signature(geometry.mesh_file) :
               "";
    }

    std::string
    signature_values(const std::string &signature)
    {
      const std::size_t space = signature.find(' ');
      return space == std::string::npos ? "none" : signature.substr(space + 1);
    }

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
  } // namespace checkpoint_directory
} // namespace hemicontact
