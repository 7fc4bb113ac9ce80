#include <hemicontact/model/contact_step.h>
#include <hemicontact/problem/error_indicators.h>

#include <algorithm>
#include <cmath>

namespace hemicontact
{
  template <int dim>
  double
  time_indicator(const ProblemState<dim>             &state,
                 const TrilinosWrappers::MPI::Vector &w_before)
  {
    // the change d = w_n - w_{n-1} without its constrained entries (the
    // matrices are condensed), and |||d|||^2 = c_A d.A d + c_B d.B d =
    // d.K d - c_M d.rho M d: A is not held (doc/theory.md 12.4)
    TrilinosWrappers::MPI::Vector d(state.velocity);
    d -= w_before;
    d = without_constrained(d, state.base_constraints);
    TrilinosWrappers::MPI::Vector tmp(d);
    state.step_matrix.vmult(tmp, d);
    double                       energy = d * tmp;
    const StepMatrixCoefficients c = state.scheme.step_matrix(state.time_step);
    if (c.mass != 0)
      {
        state.mass_matrix.vmult(tmp, d);
        energy -= c.mass * (d * tmp);
      }
    return std::sqrt(std::max(energy, 0.));
  }

  template double
  time_indicator(const ProblemState<2> &,
                 const TrilinosWrappers::MPI::Vector &);
  template double
  time_indicator(const ProblemState<3> &,
                 const TrilinosWrappers::MPI::Vector &);
} // namespace hemicontact
