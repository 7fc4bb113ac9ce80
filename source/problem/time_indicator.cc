#include <hemicontact/model/contact_step.h>
#include <hemicontact/problem/contact_problem.h>

#include <algorithm>
#include <cmath>

namespace hemicontact
{
  template <int dim>
  double
  ContactProblem<dim>::time_indicator(
    const TrilinosWrappers::MPI::Vector &w_before) const
  {
    // the change d = w_n - w_{n-1} without its constrained entries (the
    // matrices are condensed), and |||d|||^2 = c_A d.A d + c_B d.B d =
    // d.K d - c_M d.rho M d: A is not held (doc/theory.md 12.4)
    TrilinosWrappers::MPI::Vector d(velocity);
    d -= w_before;
    d = without_constrained(d, base_constraints);
    TrilinosWrappers::MPI::Vector tmp(d);
    step_matrix.vmult(tmp, d);
    double                       energy = d * tmp;
    const StepMatrixCoefficients c      = scheme.step_matrix(time_step);
    if (c.mass != 0)
      {
        mass_matrix.vmult(tmp, d);
        energy -= c.mass * (d * tmp);
      }
    return std::sqrt(std::max(energy, 0.));
  }

  template double
  ContactProblem<2>::time_indicator(
    const TrilinosWrappers::MPI::Vector &) const;
  template double
  ContactProblem<3>::time_indicator(
    const TrilinosWrappers::MPI::Vector &) const;
} // namespace hemicontact
