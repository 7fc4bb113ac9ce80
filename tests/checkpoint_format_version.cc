// A checkpoint's .state records its format version (the class version of
// CheckpointState): one written in another format is refused by name, with
// the version this program reads, before any of its content is used; one
// of the current format reads back with its fields by space and its energy
// terms by name, also when it holds the list without the terms added at its
// end since (CheckpointState::energy_balance() gives them 0); a list with a
// term that is not the program's is refused.
#include <boost/crc.hpp>

#include <hemicontact/output/checkpoint_directory.h>

#include <fstream>
#include <sstream>

#include "tests.h"

using namespace hemicontact;
using namespace hemicontact::checkpoint_directory;

namespace
{
  /** @p body followed by its CRC-32 line, as state_text() ends a file. */
  std::string
  with_checksum(const std::string &body)
  {
    boost::crc_32_type crc;
    crc.process_bytes(body.data(), body.size());
    return body + "crc32 " + std::to_string(crc.checksum()) + "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  CheckpointState state;
  state.step_number = 3;
  state.time_step   = 0.1;
  state.n_steps     = 10;
  state.n_ranks     = 1;
  for (const SavedEnergyTerm &term : saved_energy_terms())
    state.energy.emplace_back(term.name, 1.);
  state.fields = {{"displacement", {"velocity", "displacement"}},
                  {"theta", {"theta"}}};

  const std::string text = state_text(state);
  {
    std::ofstream("current.state") << text;
    CheckpointState   read;
    const std::string why = read_state("current.state", read);
    out() << "current format: " << (why.empty() ? "read" : why) << ", version "
          << read.format_version << ", step " << read.step_number << ", "
          << read.fields.size()
          << " spaces, fields of the second: " << read.fields[1].second[0]
          << ", energy term 0: " << read.energy[0].first << "\n";
  }

  // the list without its last term, and with a last term renamed
  for (const bool renamed : {false, true})
    {
      CheckpointState shorter = state;
      if (renamed)
        shorter.energy.back().first = "no_such_term";
      else
        shorter.energy.pop_back();
      std::ofstream("shorter.state") << state_text(shorter);
      CheckpointState   read;
      const std::string why  = read_state("shorter.state", read);
      const auto       &last = saved_energy_terms().back();
      out() << (renamed ? "a term renamed: " : "without the last term: ")
            << (why.empty() ? "read, " + last.name + " = " +
                                std::to_string(last.in(read.energy_balance())) :
                              "refused")
            << "\n";
    }

  // the class version is the second number after the archive's header
  // ("22 serialization::archive L T V ...": T its tracking, V its version)
  const std::string  body = text.substr(0, text.rfind("crc32 "));
  std::istringstream words(body);
  std::string        size, signature, library, tracking, version;
  words >> size >> signature >> library >> tracking >> version;
  const std::size_t at =
    body.find(" " + tracking + " " + version + " ") + tracking.size() + 2;
  const std::string old_body =
    body.substr(0, at) + "0" + body.substr(at + version.size());
  std::ofstream("old.state") << with_checksum(old_body);
  CheckpointState   read;
  const std::string why = read_state("old.state", read);
  out() << "format version 0: "
        << (why.empty() ? std::string("read (not refused)") : why) << "\n";
}
