#pragma once

namespace hemicontact
{
  /**
   * The step solver's tuning constants: not parameters of the input file,
   * because they change how fast a step is solved, never its solution (to
   * the Newton tolerance). Each default is the measured choice
   * (doc/performance.md, "Design choices"); tests and benchmarks change them
   * from C++ to show what each one buys.
   */
  struct SolverTuning
  {
    /** @name Newton (ActiveSetNewton) */
    /** @{ */
    /**
     * The round-off floor of the Newton residual test, relative to
     * |b| + |K0 w| (doc/solver.md, "When a step has converged"): it scales
     * with the loads, so a change of units does not change the answer.
     */
    double roundoff_tolerance = 1e-14;
    /** Smallest step length the backtracking line search tries. */
    double minimum_step_length = 1e-3;
    /** The projection constant c_i = factor * (K0)_ii / m_i of every node. */
    double complementarity_factor = 1;
    /**
     * From the second iteration of a step on, a node that would jump
     * between separating and damped is held at normal stick for one
     * iteration (nodal::gradual_normal_branch()).
     */
    bool gradual_normal_branches = true;
    /** @} */

    /** @name Krylov stopping rule (forcing term = eisenstat-walker) */
    /** @{ */
    /** Largest Eisenstat-Walker forcing term eta_k. */
    double maximum_forcing_term = 0.01;
    /**
     * An iteration in which no node changed branch solves to the Krylov
     * floor at once instead of by eta_k: the step is smooth there, so one
     * accurate solve usually ends it.
     */
    bool exact_solve_when_settled = true;
    /**
     * The Krylov floor: no solve goes below this fraction of the Newton
     * target (tolerance times the load plus the absolute tolerance).
     */
    double krylov_floor_fraction = 0.5;
    /** @} */

    /** @name Preconditioner (StepPreconditioner) */
    /** @{ */
    /**
     * Build each mesh's AMG from K0 plus a penalty on the directions the
     * contact branches of its first Newton iteration constrain (else: the
     * AMG of K0 throughout).
     */
    bool constrained_preconditioner = true;
    /** The penalty of the constrained AMG, times the diagonal of K0. */
    double constraint_penalty = 1e3;
    /**
     * The share of contact nodes with a free direction the constrained AMG
     * treats as constrained beyond which the AMG of K0 is used instead.
     */
    double constrained_mismatch_limit = 0.05;
    /**
     * Rebuild the constrained AMG in every iteration whose constrained
     * directions differ from the AMG's (either way), instead of splitting
     * mismatched directions off or dropping the AMG. Krylov iterations then
     * no longer grow under refinement, but one ML set-up costs about 20 CG
     * iterations at 2D r6: off (doc/performance.md, "Alternatives measured").
     */
    bool constrained_amg_follows_branches = false;
    /**
     * Contact directions stiffer than this times the diagonal of K0 are
     * inverted node by node instead of by the AMG (0: never).
     */
    double stiff_contact_threshold = 0.3;
    /** ML smoothed-aggregation threshold. */
    double aggregation_threshold = 1e-4;
    /** ML smoother sweeps. */
    unsigned int smoother_sweeps = 2;
    /** @} */
  };
} // namespace hemicontact
