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
    const Tensor<2, dim> &                          stiffness,
    const Tensor<2, dim> &                          amg_constrained)
  {
    NodeBlock block;
    block.dofs = dofs;
    for (unsigned int c = 0; c < dim; ++c)
      block.local_index[c] = owned->index_within_set(dofs[c]);
    block.projector = projector;
    block.stiffness = projector * stiffness * projector;
    block.soft_projector = projector;

    Tensor<2, dim> k0_diagonal;
    for (unsigned int c = 0; c < dim; ++c)
      k0_diagonal[c][c] = step_matrix->diag_element(dofs[c]);
    // the nodal (Jacobi) inverse on the unit direction v, which the AMG
    // then no longer sees
    auto split_off = [&](const Tensor<1, dim> &v) {
      const Tensor<2, dim> vv = outer_product(v, v);
      block.soft_projector -= vv;
      block.stiff_inverse +=
        vv / (v * (block.stiffness * v) + v * (k0_diagonal * v));
    };
    if (stiff_threshold > 0)
      // the stiffness is symmetric: split it along its eigenvectors
      for (const auto &eigenpair : eigenvectors(symmetrize(block.stiffness)))
        if (eigenpair.first >
            stiff_threshold *
              (eigenpair.second * (k0_diagonal * eigenpair.second)))
          split_off(eigenpair.second);

    // free directions that the AMG was built to treat as constrained
    if (amg_constrained.norm() > 0)
      {
        const Tensor<2, dim> overlap =
          block.soft_projector * amg_constrained * block.soft_projector;
        for (const auto &eigenpair : eigenvectors(symmetrize(overlap)))
          if (eigenpair.first > 0.5)
            split_off(eigenpair.second);
      }
    blocks.push_back(block);
  }

  template <int dim>
  void
  ProjectedOperator<dim>::add_constraint_penalty_to(
    TrilinosWrappers::SparseMatrix &matrix, const double gamma) const
  {
    for (const NodeBlock &block : blocks)
      {
        double d = 0;
        for (unsigned int c = 0; c < dim; ++c)
          d += step_matrix->diag_element(block.dofs[c]) / dim;
        // the diagonal of I - Pi: the constrained share of each component
        for (unsigned int c = 0; c < dim; ++c)
          if (1. - block.projector[c][c] > 0)
            matrix.add(block.dofs[c], block.dofs[c],
                       gamma * d * (1. - block.projector[c][c]));
      }
  }

  template <int dim>
  void
  ProjectedOperator<dim>::project_out_preconditioner_constraints(
    std::vector<double> &modes, const unsigned int n_modes) const
  {
    const std::size_t n_owned = modes.size() / n_modes;
    for (const NodeBlock &block : blocks)
      for (unsigned int m = 0; m < n_modes; ++m)
        {
          Tensor<1, dim> x;
          for (unsigned int c = 0; c < dim; ++c)
            x[c] = modes[m * n_owned + block.local_index[c]];
          const Tensor<1, dim> y = block.projector * x;
          for (unsigned int c = 0; c < dim; ++c)
            modes[m * n_owned + block.local_index[c]] = y[c];
        }
  }

  template <int dim>
  Tensor<2, dim>
  ProjectedOperator<dim>::preconditioner_constraints(const unsigned int i) const
  {
    AssertIndexRange(i, blocks.size());
    return unit_symmetric_tensor<dim>() - blocks[i].projector;
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
