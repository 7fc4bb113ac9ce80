#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

namespace hemicontact
{
  /**
   * out = @p op in with the rows of @p constraints set to zero: a matrix
   * or a preconditioner (anything with vmult()) as the operator of an
   * eigenvalue estimate on the constrained space (largest_generalized_
   * eigenvalue()). Holds references to both.
   */
  template <class Operator>
  auto
  constrained(const Operator                          &op,
              const dealii::AffineConstraints<double> &constraints)
  {
    return [&op, &constraints](const dealii::TrilinosWrappers::MPI::Vector &in,
                               dealii::TrilinosWrappers::MPI::Vector &out) {
      op.vmult(out, in);
      constraints.set_zero(out);
    };
  }
} // namespace hemicontact
