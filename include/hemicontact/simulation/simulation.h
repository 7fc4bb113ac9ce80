#pragma once

#include <hemicontact/problem/contact_problem.h>

namespace hemicontact
{
  template <int dim>
  class RunOutput;
  template <int dim>
  class Checkpointer;

  /**
   * A run of a ContactProblem (doc/running.md): setup or resume, the time
   * loop with the adaptations, the target-error loop of the static class
   * and the pre-refinement restart, the output and the checkpoints, and the
   * summary at the end. It uses only the problem's public step interface;
   * the problem keeps the mathematics of a step.
   */
  template <int dim>
  class Simulation
  {
  public:
    /** The run of @p problem (which must outlive it). */
    explicit Simulation(ContactProblem<dim> &problem);

    /**
     * Run it: an earlier run's files come back if the run stops on an
     * input or output error before its first step; a solver failure keeps
     * the state it wrote (doc/outputs.md). Throws what the run throws.
     */
    void
    run();

  private:
    /** The time loop of run(), its output in @p output. */
    void
    time_loop(RunOutput<dim> &output, Checkpointer<dim> &checkpointer);

    /**
     * Adapt the mesh if it is due after the step just taken
     * (adaptation_due()); the solution write in progress
     * finishes first and the probes follow the new mesh.
     */
    void
    adapt_mesh_if_due(StepStatistics &stats, RunOutput<dim> &output);

    /**
     * advance() under 'adaptivity/target error' (static class,
     * target_error.cc): solve the load value, and while its error estimate
     * eta exceeds the target times a_B(u_h, u_h)^(1/2), adapt the mesh and
     * solve it again. Throws TargetErrorNotReached, after @p output wrote
     * the load value's last solution, if the mesh can grow no further.
     */
    StepStatistics
    advance_to_target_error(RunOutput<dim> &output);

    ContactProblem<dim> &problem;
    const Parameters    &parameters;
    MPI_Comm             mpi_communicator;
    ConditionalOStream   pcout;
  };
} // namespace hemicontact
