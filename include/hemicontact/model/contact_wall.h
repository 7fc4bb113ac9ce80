#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/laws/normal_law.h>
#include <hemicontact/model/contact_node.h>

#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * Set every node's upper_limit, the law's wall in the step's unknown
   * (doc/theory.md section 10): g itself in the static class (@p displacement
   * is nullptr there), and (g - u_nu)/k with u the displacement held when the
   * step starts (ghosted) in the velocity classes, so that the displacement
   * after the step, u + k w, satisfies u_nu <= g. +inf without a wall.
   *
   * With the wear depth omega of each node at its first degree of freedom
   * in @p wear (ghosted; doc/theory.md section 11.12), the wall is at
   * g + omega, and in the static class the law acts on u_nu - omega
   * (ContactNode::law_offset); without, law_offset is zero.
   */
  template <int dim>
  void
  set_wall_limits(std::vector<ContactNode<dim>>       &nodes,
                  const NormalLaw                     &law,
                  const TrilinosWrappers::MPI::Vector *displacement,
                  const double                         time_step,
                  const TrilinosWrappers::MPI::Vector *wear = nullptr);
} // namespace hemicontact
