#include <hemicontact/solver/backtracking.h>

namespace hemicontact
{
  double
  backtracking_step_length(const std::function<double(double)> &energy_change,
                           const double                         scale,
                           const double                         min_step_length,
                           unsigned int                        &n_reductions)
  {
    for (double theta = 1; theta >= min_step_length; theta /= 2)
      {
        const double change = energy_change(theta);
        if (theta == 1 ? change <= 1e-12 * scale : change < 0)
          return theta;
        ++n_reductions;
      }
    return 1; // no decrease found: take the full active-set step
  }
} // namespace hemicontact
