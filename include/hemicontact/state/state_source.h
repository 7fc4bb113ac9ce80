#pragma once

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <boost/serialization/version.hpp>

#include <hemicontact/mesh/discretization.h>
#include <hemicontact/model/energy_balance.h>
#include <hemicontact/state/state_field.h>

#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  /** Everything of a run that is not a finite element field (the .state
   *  file of a checkpoint). */
  struct CheckpointState
  {
    /**
     * The layout of the .state file this program writes and reads
     * (doc/outputs.md, "Checkpoints"); a file of another is refused with
     * its number.
     */
    static constexpr unsigned int current_format_version = 2;
    /** The format of the file read (its class version). */
    unsigned int format_version = current_format_version;

    unsigned int step_number = 0;
    double       time_step   = 0;
    unsigned int n_steps     = 0;
    /** The terms of saved_energy_terms(), by name. */
    std::vector<std::pair<std::string, double>> energy;
    /**
     * The names of the saved fields of the state, by space in the order
     * the fields files hold them (field_names_by_space()).
     */
    std::vector<std::pair<std::string, std::vector<std::string>>> fields;
    /** The solution series, each as SeriesRecord::stored(). */
    std::vector<std::pair<double, std::string>> pvd_records;
    /** Parameters::problem_definition of the run that wrote it. */
    std::vector<std::string> problem_definition;
    /** "name size crc32" of every other file of the checkpoint. */
    std::vector<std::string> file_signatures;
    /** The number of MPI ranks that wrote it. */
    unsigned int n_ranks = 0;
    /** The length of the last converged step (the extrapolated guess). */
    double last_step_length = 0;
    /** The run that wrote it (a resumed run keeps its run's id). */
    std::string run_id;
    /** "name size crc32" of the mesh file the run read ("" if none). */
    std::string mesh_signature;
    /** The preconditioner's ConstrainedAmgStatus. */
    unsigned int constrained_amg = 0;
    /** MemoryHistory::saved_values() (its vectors are fields). */
    std::vector<double> memory_history;

    /** The energy balance it records. */
    EnergyBalance
    energy_balance() const;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int version)
    {
      // a file of another format: only its version is read
      format_version = version;
      if (version != current_format_version)
        return;
      ar &step_number &time_step &n_steps &energy &fields &pvd_records
        &problem_definition &file_signatures &n_ranks &last_step_length &run_id
          &mesh_signature &constrained_amg &memory_history;
    }
  };

} // namespace hemicontact

BOOST_CLASS_VERSION(hemicontact::CheckpointState,
                    hemicontact::CheckpointState::current_format_version)

namespace hemicontact
{
  /**
   * Where a resume reads the state from (a Checkpointer): the values of
   * the run, the mesh and the fields by name. The problem resumes from it
   * without knowing where the state is kept.
   */
  template <int dim>
  class StateSource
  {
  public:
    virtual ~StateSource() = default;

    /**
     * The state to resume from, checked to continue the problem of
     * @p n_steps steps of @p time_step.
     */
    virtual const CheckpointState &
    read(unsigned int n_steps, double time_step) = 0;

    /** Its mesh, into @p discretization. */
    virtual void
    load_mesh(Discretization<dim> &discretization) const = 0;

    /**
     * Its fields into the saved fields of @p fields by name, on the mesh
     * of load_mesh(); refuses (InputError) fields that do not match.
     */
    virtual void
    load_fields(const std::vector<StateField<dim>> &fields) = 0;
  };
} // namespace hemicontact
