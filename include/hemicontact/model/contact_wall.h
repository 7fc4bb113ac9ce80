#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/laws/normal_law.h>
#include <hemicontact/model/contact_node.h>

#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The wear depth omega at @p node, held at its first degree of freedom
   * in @p wear (nullptr: no wear, 0; doc/theory.md 11.12), and with it the
   * wall of the normal law at the node, wall_position() = g + omega: the
   * one definition of the worn wall's position, which the step's limits
   * and the adaptation's check take from here.
   */
  template <int dim>
  double
  wear_depth_at(const ContactNode<dim>              &node,
                const TrilinosWrappers::MPI::Vector *wear)
  {
    return wear != nullptr ? (*wear)[node.dofs[0]] : 0.;
  }

  /** g + wear_depth_at(): see above. */
  template <int dim>
  double
  wall_position(const double                         g,
                const ContactNode<dim>              &node,
                const TrilinosWrappers::MPI::Vector *wear)
  {
    return g + wear_depth_at(node, wear);
  }

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
