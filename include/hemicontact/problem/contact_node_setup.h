#pragma once

#include <hemicontact/model/contact_node.h>
#include <hemicontact/problem/problem_state.h>

#include <vector>

namespace hemicontact
{
  /**
   * The locally relevant contact nodes of @p state's mesh: the free vertices
   * on Gamma_3 with their lumped boundary mass m_i = int phi_i, their nodal
   * normal (the average of the faces' normals weighted by phi_i) and the
   * complementarity constant c_i of the active-set Newton (doc/theory.md
   * 3, 10.3); their friction bounds not yet set (contact_node_setup.cc).
   */
  template <int dim>
  std::vector<ContactNode<dim>>
  collect_contact_nodes(const ProblemState<dim> &state);
} // namespace hemicontact
