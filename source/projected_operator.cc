#include <deal.II/base/symmetric_tensor.h>

#include <hemicontact/projected_operator.h>

namespace hemicontact
{
  template <int dim>
  ProjectedOperator<dim>::ProjectedOperator(
    const TrilinosWrappers::SparseMatrix &step_matrix,
    const IndexSet &                      locally_owned_dofs,
    const double                          stiff_threshold)
    : step_matrix(&step_matrix)
    , owned(&locally_owned_dofs)
    , stiff_threshold(stiff_threshold)
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
    block.soft_projector = projector;
    if (stiff_threshold > 0)
      {
        Tensor<1, dim> k0_diagonal;
        for (unsigned int c = 0; c < dim; ++c)
          k0_diagonal[c] = step_matrix->diag_element(dofs[c]);
        // the stiffness is symmetric: split it along its eigenvectors
        for (const auto &eigenpair : eigenvectors(symmetrize(block.stiffness)))
          {
            const double          mu = eigenpair.first;
            const Tensor<1, dim> &v  = eigenpair.second;
            double                d  = 0;
            for (unsigned int c = 0; c < dim; ++c)
              d += v[c] * v[c] * k0_diagonal[c];
            if (mu > stiff_threshold * d)
              {
                const Tensor<2, dim> vv = outer_product(v, v);
                block.soft_projector -= vv;
                block.stiff_inverse += vv / (mu + d);
              }
          }
      }
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
  ProjectedOperator<dim>::apply_node_tensors(
    TrilinosWrappers::MPI::Vector &v,
    Tensor<2, dim> NodeBlock::*    tensor) const
  {
    double *values = v.begin();
    for (const NodeBlock &block : blocks)
      {
        Tensor<1, dim> x;
        for (unsigned int c = 0; c < dim; ++c)
          x[c] = values[block.local_index[c]];
        const Tensor<1, dim> y = block.*tensor * x;
        for (unsigned int c = 0; c < dim; ++c)
          values[block.local_index[c]] = y[c];
      }
  }

  template <int dim>
  void
  ProjectedOperator<dim>::project(TrilinosWrappers::MPI::Vector &v) const
  {
    apply_node_tensors(v, &NodeBlock::projector);
  }

  template <int dim>
  void
  ProjectedOperator<dim>::project_soft(TrilinosWrappers::MPI::Vector &v) const
  {
    apply_node_tensors(v, &NodeBlock::soft_projector);
  }

  template <int dim>
  void
  ProjectedOperator<dim>::add_node_tensors(
    TrilinosWrappers::MPI::Vector &      dst,
    const TrilinosWrappers::MPI::Vector &src,
    Tensor<2, dim> NodeBlock::*          tensor) const
  {
    const double *x   = src.begin();
    double *      out = dst.begin();
    for (const NodeBlock &block : blocks)
      {
        Tensor<1, dim> v;
        for (unsigned int c = 0; c < dim; ++c)
          v[c] = x[block.local_index[c]];
        const Tensor<1, dim> y = block.*tensor * v;
        for (unsigned int c = 0; c < dim; ++c)
          out[block.local_index[c]] += y[c];
      }
  }

  template <int dim>
  void
  ProjectedOperator<dim>::add_stiff_inverse(
    TrilinosWrappers::MPI::Vector &      dst,
    const TrilinosWrappers::MPI::Vector &src) const
  {
    add_node_tensors(dst, src, &NodeBlock::stiff_inverse);
  }

  template <int dim>
  void
  ProjectedOperator<dim>::vmult(TrilinosWrappers::MPI::Vector &      dst,
                                const TrilinosWrappers::MPI::Vector &src) const
  {
    projected_src = src;
    project(projected_src);
    step_matrix->vmult(dst, projected_src);
    add_node_tensors(dst, projected_src, &NodeBlock::stiffness);
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
    op.project_soft(projected_src);
    amg.vmult(dst, projected_src);
    op.project_soft(dst);
    op.add_stiff_inverse(dst, src);
  }

  template class ProjectedOperator<2>;
  template class ProjectedOperator<3>;
  template class ProjectedPreconditioner<2>;
  template class ProjectedPreconditioner<3>;
} // namespace hemicontact
