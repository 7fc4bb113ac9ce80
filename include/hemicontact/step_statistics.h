#pragma once

namespace hemicontact
{
  /** What one time step did: iterations, branch counts, final residual. */
  struct StepStatistics
  {
    unsigned int step                = 0;
    double       time                = 0;
    unsigned int newton_iterations   = 0;
    unsigned int linear_iterations   = 0;
    unsigned int n_separating        = 0;
    unsigned int n_normal_stick      = 0;
    unsigned int n_damped            = 0;
    unsigned int n_stick             = 0;
    unsigned int n_slip              = 0;
    unsigned int n_damped_steps      = 0; ///< line-search reductions
    double       residual            = 0; ///< relative nonsmooth residual
    double       wall_seconds        = 0;
  };
} // namespace hemicontact
