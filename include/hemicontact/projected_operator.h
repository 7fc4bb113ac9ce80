#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_precondition.h>
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
   * anything: a Newton iteration only fills the node blocks.
   */
  template <int dim>
  class ProjectedOperator
  {
  public:
    /** @p step_matrix must outlive this object. */
    ProjectedOperator(const TrilinosWrappers::SparseMatrix &step_matrix,
                      const IndexSet &                      locally_owned_dofs);

    /** Forget all node blocks (every node becomes unconstrained). */
    void
    clear();

    /**
     * Add an owned contact node: its dofs, the projector Pi_i and its
     * stiffness L_i (both dim x dim, symmetric).
     */
    void
    add_node(const std::array<types::global_dof_index, dim> &dofs,
             const Tensor<2, dim> &projector, const Tensor<2, dim> &stiffness);

    /** matrix(i_a, i_b) += (Pi L Pi)_ab at every node block (owned rows). */
    void
    add_stiffness_to(TrilinosWrappers::SparseMatrix &matrix) const;

    /** v := Pi v (owned entries only; no communication). */
    void
    project(TrilinosWrappers::MPI::Vector &v) const;

    /** dst = Pi (K0 + sum L_i) Pi src. */
    void
    vmult(TrilinosWrappers::MPI::Vector &      dst,
          const TrilinosWrappers::MPI::Vector &src) const;

  private:
    struct NodeBlock
    {
      std::array<types::global_dof_index, dim> dofs;
      std::array<unsigned int, dim> local_index; ///< into the owned range
      Tensor<2, dim>                projector;
      Tensor<2, dim>                stiffness; ///< Pi L Pi
    };

    const TrilinosWrappers::SparseMatrix *step_matrix;
    const IndexSet *                      owned;
    std::vector<NodeBlock>                blocks;
    mutable TrilinosWrappers::MPI::Vector projected_src;
  };

  /**
   * Pi P Pi for a symmetric preconditioner P of K0 (the AMG hierarchy of the
   * step matrix, built once per mesh): a symmetric preconditioner on
   * range(Pi) for ProjectedOperator.
   */
  template <int dim>
  class ProjectedPreconditioner
  {
  public:
    ProjectedPreconditioner(const ProjectedOperator<dim> &          op,
                            const TrilinosWrappers::PreconditionAMG &amg);

    void
    vmult(TrilinosWrappers::MPI::Vector &      dst,
          const TrilinosWrappers::MPI::Vector &src) const;

  private:
    const ProjectedOperator<dim> &          op;
    const TrilinosWrappers::PreconditionAMG &amg;
    mutable TrilinosWrappers::MPI::Vector    projected_src;
  };
} // namespace hemicontact
