#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The Newton matrix of one active-set iteration as an operator,
   *
   *   x -> Pi (K0 + sum_i L_i) Pi x,
   *
   * where K0 = rho/k M + A is the step matrix (assembled once per mesh), L_i
   * the dim x dim linearisation of the free contact branches at node i and
   * Pi the node-wise orthogonal projector onto the directions that the
   * node's constrained branches leave free (I - nu nu for normal stick, nu nu
   * for tangential stick, 0 for both). On range(Pi) it is the matrix that
   * eliminating the contact constraints would give, without reassembling
   * anything: a Newton iteration only fills the node blocks. Preconditioning
   * it is StepPreconditioner's job.
   */
  template <int dim>
  class ProjectedOperator
  {
  public:
    /** The operator's data at one owned contact node. */
    struct Node
    {
      std::array<types::global_dof_index, dim> dofs;
      std::array<unsigned int, dim> local_index; ///< into the owned range
      Tensor<2, dim>                projector;   ///< Pi_i
      Tensor<2, dim>                stiffness;   ///< Pi_i L_i Pi_i
    };

    /** @p step_matrix must outlive this object. */
    ProjectedOperator(const TrilinosWrappers::SparseMatrix &step_matrix,
                      const IndexSet                       &locally_owned_dofs);

    /**
     * Add an owned contact node: its dofs, the projector Pi_i and its
     * stiffness L_i (both dim x dim, symmetric).
     */
    void
    add_node(const std::array<types::global_dof_index, dim> &dofs,
             const Tensor<2, dim>                           &projector,
             const Tensor<2, dim>                           &stiffness);

    /** The owned contact nodes, in the order they were added. */
    const std::vector<Node> &
    nodes() const
    {
      return node_blocks;
    }

    /** K0. */
    const TrilinosWrappers::SparseMatrix &
    get_step_matrix() const
    {
      return *step_matrix;
    }

    /** v := Pi v (owned entries only; no communication). */
    void
    project(TrilinosWrappers::MPI::Vector &v) const;

    /** dst = Pi (K0 + sum L_i) Pi src. */
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /**
     * The operator as a sparse matrix, Pi (K0 + sum L_i) Pi + (I - Pi), for
     * a direct solve: the same solution on range(Pi), zero on the
     * constrained directions.
     */
    void
    assemble(TrilinosWrappers::SparseMatrix &matrix) const;

  private:
    const TrilinosWrappers::SparseMatrix *step_matrix;
    const IndexSet                       *owned;
    std::vector<Node>                     node_blocks;
    mutable TrilinosWrappers::MPI::Vector projected_src;
  };

  /** v_i := T_i v_i at every node of @p nodes, T_i = node.*tensor. */
  template <int dim, typename NodeType>
  void
  apply_node_tensors(const std::vector<NodeType> &nodes,
                     Tensor<2, dim> NodeType::     *tensor,
                     TrilinosWrappers::MPI::Vector &v)
  {
    double *values = v.begin();
    for (const NodeType &node : nodes)
      {
        Tensor<1, dim> x;
        for (unsigned int c = 0; c < dim; ++c)
          x[c] = values[node.local_index[c]];
        const Tensor<1, dim> y = node.*tensor * x;
        for (unsigned int c = 0; c < dim; ++c)
          values[node.local_index[c]] = y[c];
      }
  }

  /** dst_i += T_i src_i at every node of @p nodes, T_i = node.*tensor. */
  template <int dim, typename NodeType>
  void
  add_node_tensors(const std::vector<NodeType> &nodes,
                   Tensor<2, dim> NodeType::           *tensor,
                   const TrilinosWrappers::MPI::Vector &src,
                   TrilinosWrappers::MPI::Vector       &dst)
  {
    const double *x   = src.begin();
    double       *out = dst.begin();
    for (const NodeType &node : nodes)
      {
        Tensor<1, dim> v;
        for (unsigned int c = 0; c < dim; ++c)
          v[c] = x[node.local_index[c]];
        const Tensor<1, dim> y = node.*tensor * v;
        for (unsigned int c = 0; c < dim; ++c)
          out[node.local_index[c]] += y[c];
      }
  }
} // namespace hemicontact
