#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/model/energy_balance.h>
#include <hemicontact/output/checkpointer.h>

#include <filesystem>
#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * The files of the checkpoint directory OUTPUT/checkpoint (doc/outputs.md):
   * their names, the .state file with its CRC-32, the fields of a
   * simplex-mesh checkpoint per rank, the signatures of the files, the run
   * file, and which checkpoints are complete and kept.
   */
  namespace checkpoint_directory
  {
    namespace fs = std::filesystem;

    /**
     * @p state as a text archive followed by the line "crc32 N" of that
     * text (so that a change of any entry is seen).
     */
    std::string
    state_text(const CheckpointState &state);

    /**
     * Read the .state file @p file into @p state; the reason why it cannot
     * be used (unreadable, its checksum or content not as written), or an
     * empty string.
     */
    std::string
    read_state(const fs::path &file, CheckpointState &state);

    /**
     * The fields of one space of a simplex-mesh checkpoint on one rank: the
     * owned entries of @p fields, each with its global dof index
     * (the mesh itself is rebuilt from the parameters, partitioned the same
     * way on the same number of ranks). Returns the reason of a failure.
     */
    std::string
    write_rank_fields(
      const fs::path                                           &file,
      const IndexSet                                           &owned,
      const std::vector<const TrilinosWrappers::MPI::Vector *> &fields);

    /** Read write_rank_fields()'s file; the reason if it does not fit. */
    std::string
    read_rank_fields(
      const fs::path                                     &file,
      const IndexSet                                     &owned,
      const std::vector<TrilinosWrappers::MPI::Vector *> &fields);

    /** "name size crc32" of @p file ("name missing" if it cannot be read). */
    std::string
    file_signature(const fs::path &file);

    /** The name of the files of the checkpoint of @p step: step-NNNNNN. */
    std::string
    checkpoint_name(const unsigned int step);

    /**
     * Read the state of the checkpoint of @p step in @p dir into @p state
     * and check it (it records that step) and every file against the
     * signature it records. Returns why the checkpoint cannot be used, or
     * an empty string.
     */
    std::string
    checkpoint_damage(const fs::path    &dir,
                      const unsigned int step,
                      CheckpointState   &state);

    /** Steps of the complete checkpoints in @p dir (their .state exists). */
    std::vector<unsigned int>
    complete_checkpoints(const fs::path &dir);

    /** The file in OUTPUT/checkpoint naming the run whose output is in
     *  OUTPUT. */
    inline const std::string run_file_name = "run";

    /** The run id in @p dir's run file, "" if there is none. */
    std::string
    recorded_run(const fs::path &dir);

    /** A new run id: 64 random bits in hex. */
    std::string
    new_run_id();

    /** The signature of the mesh file @p geometry reads ("" if none). */
    std::string
    mesh_signature_of(const GeometryParameters &geometry);

    /** The size and CRC-32 of a file_signature() (without the name). */
    std::string
    signature_values(const std::string &signature);

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
                              const unsigned int step);
  } // namespace checkpoint_directory
} // namespace hemicontact
