#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi_remote_point_evaluation.h>
#include <deal.II/base/point.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/data_out.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/output/background_writer.h>
#include <hemicontact/output/nodal_hdf5_writer.h>
#include <hemicontact/output/output_file.h>
#include <hemicontact/output/performance_summary.h>
#include <hemicontact/output/series_record.h>
#include <hemicontact/solver/step_statistics.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  template <int dim>
  class ContactProblem;

  /**
   * The output of a run in its output directory (doc/outputs.md): the
   * solution series (VTU or HDF5, written on a background thread) with
   * contact_NNNNN.csv, steps.csv, probes.csv, the terminal lines, the
   * performance summary, the directory's lock and the set-aside files of
   * an earlier run. Member functions are collective.
   */
  template <int dim>
  class RunOutput
  {
  public:
    /** Output by @p parameters; @p timer and @p pcout are the run's. */
    RunOutput(const Parameters   &parameters,
              MPI_Comm            comm,
              TimerOutput        &timer,
              ConditionalOStream &pcout);

    /**
     * Check the probe points on the mesh of @p problem, create the output
     * directory, lock it, set an earlier run's files aside (or on resume
     * cut the tables back to the step of @p problem) and open steps.csv and
     * probes.csv.
     */
    void
    open(const ContactProblem<dim> &problem);

    /** The first lines on the terminal: the problem, its convexity. */
    void
    print_start(const ContactProblem<dim> &problem) const;

    /** Continue the series of a resumed run with @p records. */
    void
    continue_series(const std::vector<SeriesRecord> &records);

    /** The time loop starts at @p step (for the time left). */
    void
    start_time_loop(unsigned int step);

    /** Whether the solution of step @p step is written ('vtu interval'). */
    bool
    solution_due(unsigned int step, bool last_step) const;

    /**
     * Write the fields of the current step of @p problem: the solution
     * series file of the step ('output/format', started on a background
     * thread) and contact_NNNNN.csv. Nothing with 'vtu interval = 0'.
     */
    void
    write_solution(const ContactProblem<dim> &problem);

    /**
     * Wait for the solution write in progress, check it on every rank,
     * write the HDF5 file and replace the series file (solution.pvd or
     * solution.xdmf) atomically. Called before the next write, before the
     * mesh changes or a checkpoint saves the series, and at the end of a
     * run.
     */
    void
    finish_solution_output();

    /** Start the series again (a restart from t = 0): the files of the
     *  same steps are replaced. */
    void
    restart_series();

    /** The series written so far (for checkpoints). */
    const std::vector<SeriesRecord> &
    series() const
    {
      return records;
    }

    /** Append the current step of @p problem to probes.csv. */
    void
    write_probes(const ContactProblem<dim> &problem);

    /** The mesh of @p problem has changed: the probes follow it. */
    void
    mesh_changed(const ContactProblem<dim> &problem);

    /** The row of steps.csv and the terminal line of the step @p stats. */
    void
    write_step(const StepStatistics &stats, const ContactProblem<dim> &problem);

    /**
     * The end of the time loop: the summary line, performance.csv and the
     * timing table if asked for.
     */
    void
    finish(const ContactProblem<dim> &problem,
           const RunTotals           &totals,
           double                     run_wall_seconds);

    /**
     * After an input or output error: wait for the solution write and
     * move an earlier run's files back if this run has not completed a
     * step (EarlierOutput).
     */
    void
    restore_earlier_output();

    /** After a solver failure: this run's files stay, an earlier run's go. */
    void
    keep_new_output();

  private:
    void
    write_step_row(const StepStatistics      &stats,
                   const ContactProblem<dim> &problem);
    void
    print_step(const StepStatistics      &stats,
               const ContactProblem<dim> &problem) const;
    /** Start the write of the series file of the current step. */
    void
    start_solution_write(const ContactProblem<dim> &problem);

    const Parameters   &parameters;
    MPI_Comm            mpi_communicator;
    TimerOutput        &timer;
    ConditionalOStream &pcout;

    /** The series written so far. */
    std::vector<SeriesRecord> records;
    /** Wall clock and step number when the time loop started (for the
     *  time left on the progress line). */
    std::chrono::steady_clock::time_point      loop_start;
    unsigned int                               loop_start_step = 0;
    std::vector<Point<dim>>                    probe_points;
    Utilities::MPI::RemotePointEvaluation<dim> probe_cache;
    std::ofstream                              steps_file;
    std::ofstream                              probes_file;
    /** Held by the root while the run writes its output directory. */
    std::unique_ptr<OutputLock> output_lock;
    /** An earlier run's files, until this run completes its first step. */
    EarlierOutput earlier_output;
    /** The nodal fields in double precision ('output/precision = double'). */
    std::unique_ptr<NodalHdf5Writer<dim>> nodal_writer;

    /** What a solution write reads: copies made when the write started. */
    struct SolutionSnapshot
    {
      unsigned int step = 0;
      double       time = 0;
      /** The fields (DataOut copies them when they are added; the copies
       *  need MPI, so they are made before the job starts). */
      std::unique_ptr<DataOut<dim>> data_out;
      /** w and u with ghost entries, for the cell stresses. */
      TrilinosWrappers::MPI::Vector velocity, displacement;
      /** The cell fields added to data_out, by name (deal.II 9.4's
       *  DataOut reads them when the job builds the patches). */
      std::vector<std::pair<std::string, Vector<float>>> cell_data;
      /** HDF5 output: the patches' data in the layout of the file. */
      std::unique_ptr<DataOutBase::DataOutFilter> hdf5_filter;
      /** The cells' kind, for the XDMF grid element. */
      ReferenceCell reference_cell;
    };
    SolutionSnapshot solution_snapshot;
    /** The series entry of the write in progress. */
    SeriesRecord pending_record;
    /** Declared last: destroyed (after waiting) before what its job reads. */
    BackgroundWriter solution_writer;
  };
} // namespace hemicontact
