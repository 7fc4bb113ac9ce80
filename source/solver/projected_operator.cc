#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <hemicontact/solver/projected_operator.h>

namespace hemicontact
{
  template <int dim>
  ProjectedOperator<dim>::ProjectedOperator(
    const TrilinosWrappers::SparseMatrix &step_matrix,
    const IndexSet                       &locally_owned_dofs)
    : step_matrix(&step_matrix)
    , owned(&locally_owned_dofs)
  {}

  template <int dim>
  void
  ProjectedOperator<dim>::add_node(
    const std::array<types::global_dof_index, dim> &dofs,
    const Tensor<2, dim>                           &projector,
    const Tensor<2, dim>                           &stiffness)
  {
    Node node;
    node.dofs = dofs;
    for (unsigned int c = 0; c < dim; ++c)
      node.local_index[c] = owned->index_within_set(dofs[c]);
    node.projector = projector;
    node.stiffness = projector * stiffness * projector;
    node_blocks.push_back(node);
  }

  template <int dim>
  void
  ProjectedOperator<dim>::project(TrilinosWrappers::MPI::Vector &v) const
  {
    apply_node_tensors<dim>(node_blocks, &Node::projector, v);
  }

  template <int dim>
  void
  ProjectedOperator<dim>::vmult(TrilinosWrappers::MPI::Vector       &dst,
                                const TrilinosWrappers::MPI::Vector &src) const
  {
    projected_src = src;
    project(projected_src);
    step_matrix->vmult(dst, projected_src);
    add_node_tensors<dim>(node_blocks, &Node::stiffness, projected_src, dst);
    project(dst);
  }

  template <int dim>
  void
  ProjectedOperator<dim>::assemble(TrilinosWrappers::SparseMatrix &matrix) const
  {
    // Pi as a matrix (identity off the contact nodes), then Pi K Pi by two
    // sparse products, K = K0 + sum L_i
    const MPI_Comm comm = step_matrix->get_mpi_communicator();
    TrilinosWrappers::SparsityPattern pi_pattern(*owned, comm);
    for (const types::global_dof_index i : *owned)
      pi_pattern.add(i, i);
    for (const Node &node : node_blocks)
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          pi_pattern.add(node.dofs[a], node.dofs[b]);
    pi_pattern.compress();
    TrilinosWrappers::SparseMatrix pi(pi_pattern);
    for (const types::global_dof_index i : *owned)
      pi.set(i, i, 1.);
    TrilinosWrappers::SparseMatrix k;
    k.copy_from(*step_matrix);
    for (const Node &node : node_blocks)
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          {
            pi.set(node.dofs[a], node.dofs[b], node.projector[a][b]);
            k.add(node.dofs[a], node.dofs[b], node.stiffness[a][b]);
          }
    pi.compress(VectorOperation::insert);
    k.compress(VectorOperation::add);

    TrilinosWrappers::SparseMatrix pi_k, pi_k_pi;
    pi.mmult(pi_k, k);
    pi_k.mmult(pi_k_pi, pi);

    // plus I - Pi on the node blocks, which the product leaves out of its
    // pattern where Pi_i has zero entries: a pattern of both
    TrilinosWrappers::SparsityPattern pattern(*owned, comm);
    for (const types::global_dof_index i : *owned)
      for (auto entry = pi_k_pi.begin(i); entry != pi_k_pi.end(i); ++entry)
        pattern.add(i, entry->column());
    for (const Node &node : node_blocks)
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          pattern.add(node.dofs[a], node.dofs[b]);
    pattern.compress();
    matrix.reinit(pattern);
    for (const types::global_dof_index i : *owned)
      for (auto entry = pi_k_pi.begin(i); entry != pi_k_pi.end(i); ++entry)
        matrix.set(i, entry->column(), entry->value());
    matrix.compress(VectorOperation::insert);
    for (const Node &node : node_blocks)
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          matrix.add(node.dofs[a],
                     node.dofs[b],
                     (a == b ? 1. : 0.) - node.projector[a][b]);
    matrix.compress(VectorOperation::add);
  }

  template class ProjectedOperator<2>;
  template class ProjectedOperator<3>;
} // namespace hemicontact
