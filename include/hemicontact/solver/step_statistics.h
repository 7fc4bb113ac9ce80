#pragma once

namespace hemicontact
{
  /** What one time step did: iterations, branch counts, final residual. */
  struct StepStatistics
  {
    unsigned int step                   = 0;
    double       time                   = 0;
    unsigned int newton_iterations      = 0;
    unsigned int linear_iterations      = 0;
    unsigned int n_separating           = 0;
    unsigned int n_normal_stick         = 0;
    unsigned int n_damped               = 0;
    unsigned int n_stick                = 0;
    unsigned int n_slip                 = 0;
    unsigned int n_at_breakpoint        = 0; ///< normal: held at a kink
    unsigned int n_at_wall              = 0; ///< normal: held at the wall
    unsigned int line_search_reductions = 0;
    double       residual               = 0; ///< relative nonsmooth residual
    double       wall_seconds           = 0;
    unsigned int time_step_halvings     = 0; ///< sub-steps added after failures
    /** Fixed-point iterations on the friction bound (doc/theory.md 9.8). */
    unsigned int bound_iterations = 0;
    /** Passes of the mechanical step with a temperature (1: staggered;
     *  more with 'temperature/coupling = iterated', doc/theory.md 13.2);
     *  0 without the heat equation. */
    unsigned int coupling_passes = 0;
    unsigned int n_cells         = 0; ///< of the mesh the step ran on
    unsigned int n_dofs          = 0;
    /** @name Mesh adaptation after this step (all zero if none) */
    bool   adapted                   = false;
    double kinetic_before_adaptation = 0;
    double elastic_before_adaptation = 0;
    double kinetic_after_adaptation  = 0;
    double elastic_after_adaptation  = 0;
    /** @name The error estimate of the step ('output/error estimate',
     *  doc/theory.md 12); not estimated: all zero */
    bool   estimated         = false;
    double estimate          = 0; ///< eta_n in the energy norm of the step
    double estimate_interior = 0; ///< each term alone, same scaling
    double estimate_jumps    = 0;
    double estimate_neumann  = 0;
    double estimate_contact  = 0;
    /** The time indicator |||w_n - w_{n-1}||| in the energy norm of the
     *  step (velocity classes, doc/theory.md 12.4); static class: none */
    bool   time_estimated = false;
    double estimate_time  = 0;
  };
} // namespace hemicontact
