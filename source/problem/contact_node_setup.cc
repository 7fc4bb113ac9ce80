#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/problem/contact_node_setup.h>

#include <map>

namespace hemicontact
{
  template <int dim>
  std::vector<ContactNode<dim>>
  collect_contact_nodes(const ProblemState<dim> &state)
  {
    const BoundaryParameters  &boundary           = state.parameters.boundary;
    const Discretization<dim> &discretization     = state.discretization;
    const DoFHandler<dim>     &dof_handler        = state.dof_handler;
    const IndexSet            &locally_owned_dofs = state.locally_owned_dofs;
    const IndexSet &locally_relevant_dofs         = state.locally_relevant_dofs;
    const AffineConstraints<double> &base_constraints = state.base_constraints;
    MPI_Comm                         mpi_communicator = state.mpi_communicator;

    // lumped boundary mass m_j = int_{Gamma_3} phi_j and the nodal normal
    // n_j = int_{Gamma_3} phi_j nu_{c(j)}, condensed onto the free nodes
    TrilinosWrappers::MPI::Vector mass(locally_owned_dofs, mpi_communicator);
    TrilinosWrappers::MPI::Vector normal(locally_owned_dofs, mpi_communicator);
    const FiniteElement<dim>     &fe = *discretization.fe;
    FEFaceValues<dim>             fe_face(*discretization.mapping,
                              fe,
                              discretization.face_quadrature(2),
                              update_values | update_normal_vectors |
                                update_JxW_values);
    const unsigned int            dofs_per_cell = fe.n_dofs_per_cell();
    Vector<double> local_mass(dofs_per_cell), local_normal(dofs_per_cell);
    std::vector<types::global_dof_index> dofs(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              boundary.part(cell->face(f)->boundary_id()) ==
                BoundaryPart::contact)
            {
              fe_face.reinit(cell, f);
              local_mass   = 0;
              local_normal = 0;
              for (const unsigned int q : fe_face.quadrature_point_indices())
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  {
                    const unsigned int c =
                      fe.system_to_component_index(i).first;
                    const double phi =
                      fe_face.shape_value_component(i, q, c) * fe_face.JxW(q);
                    local_mass(i) += phi;
                    local_normal(i) += phi * fe_face.normal_vector(q)[c];
                  }
              cell->get_dof_indices(dofs);
              base_constraints.distribute_local_to_global(local_mass,
                                                          dofs,
                                                          mass);
              base_constraints.distribute_local_to_global(local_normal,
                                                          dofs,
                                                          normal);
            }
    mass.compress(VectorOperation::add);
    normal.compress(VectorOperation::add);

    TrilinosWrappers::MPI::Vector diagonal(locally_owned_dofs,
                                           mpi_communicator);
    for (const auto i : locally_owned_dofs)
      diagonal[i] = state.step_matrix.diag_element(i);
    diagonal.compress(VectorOperation::insert);

    TrilinosWrappers::MPI::Vector ghosted(locally_owned_dofs,
                                          locally_relevant_dofs,
                                          mpi_communicator);
    TrilinosWrappers::MPI::Vector mass_g(ghosted), normal_g(ghosted),
      diagonal_g(ghosted);
    mass_g     = mass;
    normal_g   = normal;
    diagonal_g = diagonal;

    std::vector<ContactNode<dim>>                   contact_nodes;
    std::map<types::global_dof_index, unsigned int> seen;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              boundary.part(cell->face(f)->boundary_id()) ==
                BoundaryPart::contact)
            for (const unsigned int v : cell->face(f)->vertex_indices())
              {
                ContactNode<dim> node;
                for (unsigned int c = 0; c < dim; ++c)
                  node.dofs[c] = cell->face(f)->vertex_dof_index(v, c);
                if (seen.count(node.dofs[0]) ||
                    base_constraints.is_constrained(node.dofs[0]) ||
                    mass_g[node.dofs[0]] <= 0)
                  continue;
                seen[node.dofs[0]] = contact_nodes.size();
                node.position      = cell->face(f)->vertex(v);
                node.mass          = mass_g[node.dofs[0]];
                double diag        = 0;
                for (unsigned int c = 0; c < dim; ++c)
                  {
                    node.normal[c] = normal_g[node.dofs[c]];
                    diag += diagonal_g[node.dofs[c]] / dim;
                  }
                node.normal /= node.normal.norm();
                node.c = state.parameters.solver_tuning.complementarity_factor *
                         diag / node.mass;
                // above the law's steepest rise, so that q = s + c w_nu
                // grows along every free segment of the path even where an
                // iterate sits off its segment (doc/theory.md 10.3)
                node.c =
                  std::max(node.c,
                           2 * state.normal_law.largest_remainder_slope());
                node.locally_owned =
                  locally_owned_dofs.is_element(node.dofs[0]);
                contact_nodes.push_back(node);
              }
    return contact_nodes;
  }

  template std::vector<ContactNode<2>>
  collect_contact_nodes(const ProblemState<2> &);
  template std::vector<ContactNode<3>>
  collect_contact_nodes(const ProblemState<3> &);
} // namespace hemicontact
