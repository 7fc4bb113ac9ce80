#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/mesh/discretization.h>
#include <hemicontact/model/energy_balance.h>
#include <hemicontact/output/series_record.h>
#include <hemicontact/state/state_source.h>

#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  template <int dim>
  class ContactProblem;
  template <int dim>
  class RunOutput;

  /**
   * The checkpoints of a run in OUTPUT/checkpoint (doc/robustness.md):
   * when one is due (every 'checkpoint/interval' steps, every 'wall
   * interval' seconds, on SIGTERM or SIGINT and after 'stop after' steps),
   * writing one (the last two of the run are kept) and reading the newest
   * usable one for a resume. Member functions are collective.
   */
  template <int dim>
  class Checkpointer : public StateSource<dim>
  {
  public:
    /** Checkpoints by @p parameters; @p timer is the run's. */
    Checkpointer(const Parameters &parameters,
                 MPI_Comm          comm,
                 TimerOutput      &timer);

    /**
     * The time loop starts: a run not @p resumed gets a new run id and the
     * mesh file's signature, and OUTPUT/checkpoint, if it exists, then
     * names this run (a resume takes no checkpoint of an earlier run).
     * From now on SIGTERM and SIGINT request a checkpoint and a stop.
     */
    void
    start(bool resumed);

    /**
     * Whether the run stops after this step: SIGTERM or SIGINT on any
     * rank, or @p steps_this_run reached 'checkpoint/stop after'.
     */
    bool
    interruption_requested(unsigned int steps_this_run) const;

    /** Whether a checkpoint is due after step @p step. */
    bool
    due(unsigned int step, bool interrupted, bool last_step) const;

    /**
     * Write the state of @p problem and the series of @p output (after
     * its write in progress) to OUTPUT/checkpoint (aside, then renamed).
     */
    void
    write(const ContactProblem<dim> &problem, RunOutput<dim> &output);

    /**
     * Choose the newest usable checkpoint and check that it continues the
     * problem of the parameters (@p n_steps steps of @p time_step, the
     * problem definition, the mesh file); its state.
     */
    const CheckpointState &
    read(unsigned int n_steps, double time_step) override;

    /** The mesh of the checkpoint read() chose, in @p discretization. */
    void
    load_mesh(Discretization<dim> &discretization) const override;

    /**
     * The fields of the checkpoint read() chose, on the mesh of
     * load_mesh(), into the saved fields of @p fields by name (owned
     * entries). Refuses (InputError) a checkpoint that lacks a field of
     * @p fields or holds one it does not have, naming them.
     */
    void
    load_fields(const std::vector<StateField<dim>> &fields) override;

    /** The series of the checkpoint read() chose. */
    std::vector<SeriesRecord>
    series() const;

  private:
    /**
     * Refuse (OutputError on every rank, naming the directory and the
     * space) a checkpoint the file system has no room for: an estimate of
     * its size from the mesh against the free space.
     */
    void
    require_space(const ContactProblem<dim>       &problem,
                  const std::vector<SeriesRecord> &series) const;

    const Parameters &parameters;
    MPI_Comm          mpi_communicator;
    TimerOutput      &timer;
    /** The run (a resumed run continues its run): checkpoints record it. */
    std::string run_id;
    /** file_signature() of the mesh file the run read ("" if none). */
    std::string mesh_signature;
    /** The checkpoint read() chose: its state and its name. */
    CheckpointState state;
    std::string     name;
    /** Wall time since the last checkpoint. */
    Timer since_checkpoint;
  };
} // namespace hemicontact
