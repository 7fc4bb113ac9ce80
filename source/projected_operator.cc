#include <hemicontact/projected_operator.h>

namespace hemicontact
{
  template <int dim>
  ProjectedOperator<dim>::ProjectedOperator(
    const TrilinosWrappers::SparseMatrix &step_matrix,
    const IndexSet &                      locally_owned_dofs)
    : step_matrix(&step_matrix)
    , owned(&locally_owned_dofs)
  {}

  template <int dim>
  void
  ProjectedOperator<dim>::clear()
  {
    blocks.clear();
  }

  template <int dim>
  void
  ProjectedOperator<dim>::add_node(
    const std::array<types::global_dof_index, dim> &dofs,
    const Tensor<2, dim> &                          projector,
    const Tensor<2, dim> &                          stiffness)
  {
    NodeBlock block;
    block.dofs = dofs;
    for (unsigned int c = 0; c < dim; ++c)
      block.local_index[c] = owned->index_within_set(dofs[c]);
    block.projector = projector;
    block.stiffness = projector * stiffness * projector;
    blocks.push_back(block);
  }

  template <int dim>
  void
  ProjectedOperator<dim>::add_stiffness_to(
    TrilinosWrappers::SparseMatrix &matrix) const
  {
    for (const NodeBlock &block : blocks)
      for (unsigned int a = 0; a < dim; ++a)
        for (unsigned int b = 0; b < dim; ++b)
          if (block.stiffness[a][b] != 0)
            matrix.add(block.dofs[a], block.dofs[b], block.stiffness[a][b]);
  }

  template <int dim>
  void
  ProjectedOperator<dim>::project(TrilinosWrappers::MPI::Vector &v) const
  {
    double *values = v.begin();
    for (const NodeBlock &block : blocks)
      {
        Tensor<1, dim> x;
        for (unsigned int c = 0; c < dim; ++c)
          x[c] = values[block.local_index[c]];
        const Tensor<1, dim> y = block.projector * x;
        for (unsigned int c = 0; c < dim; ++c)
          values[block.local_index[c]] = y[c];
      }
  }

  template <int dim>
  void
  ProjectedOperator<dim>::vmult(TrilinosWrappers::MPI::Vector &      dst,
                                const TrilinosWrappers::MPI::Vector &src) const
  {
    projected_src = src;
    project(projected_src);
    step_matrix->vmult(dst, projected_src);

    const double *x   = projected_src.begin();
    double *      out = dst.begin();
    for (const NodeBlock &block : blocks)
      {
        Tensor<1, dim> v;
        for (unsigned int c = 0; c < dim; ++c)
          v[c] = x[block.local_index[c]];
        const Tensor<1, dim> contact = block.stiffness * v;
        for (unsigned int c = 0; c < dim; ++c)
          out[block.local_index[c]] += contact[c];
      }
    project(dst);
  }

  template <int dim>
  ProjectedPreconditioner<dim>::ProjectedPreconditioner(
    const ProjectedOperator<dim> &          op,
    const TrilinosWrappers::PreconditionAMG &amg)
    : op(op)
    , amg(amg)
  {}

  template <int dim>
  void
  ProjectedPreconditioner<dim>::vmult(
    TrilinosWrappers::MPI::Vector &      dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    projected_src = src;
    op.project(projected_src);
    amg.vmult(dst, projected_src);
    op.project(dst);
  }

  template class ProjectedOperator<2>;
  template class ProjectedOperator<3>;
  template class ProjectedPreconditioner<2>;
  template class ProjectedPreconditioner<3>;
} // namespace hemicontact
