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
    /**
     * @p step_matrix must outlive this object. A positive
     * @p stiff_threshold makes add_node() split off the node's stiff
     * directions for the preconditioner (see ProjectedPreconditioner).
     */
    ProjectedOperator(const TrilinosWrappers::SparseMatrix &step_matrix,
                      const IndexSet &                      locally_owned_dofs,
                      const double                          stiff_threshold = 0);

    /** Forget all node blocks (every node becomes unconstrained). */
    void
    clear();

    /**
     * Add an owned contact node: its dofs, the projector Pi_i and its
     * stiffness L_i (both dim x dim, symmetric). @p amg_constrained is the
     * projector onto the node's directions that the AMG in use was built to
     * treat as constrained (add_constraint_penalty_to(); zero for the AMG of
     * K0): those of them that are free now are inverted node by node, like
     * the stiff ones, since the AMG cannot move them.
     */
    void
    add_node(const std::array<types::global_dof_index, dim> &dofs,
             const Tensor<2, dim> &projector, const Tensor<2, dim> &stiffness,
             const Tensor<2, dim> &amg_constrained = Tensor<2, dim>());

    /**
     * The projector I - Pi_i onto the constrained directions of the @p i-th
     * added node: what an AMG built now (add_constraint_penalty_to()) treats
     * as constrained.
     */
    Tensor<2, dim>
    preconditioner_constraints(const unsigned int i) const;

    /**
     * matrix(i_c, i_c) += gamma d_i (I - Pi_i)_cc at every node block, d_i
     * the mean diagonal of K0 at the node: a penalty on the constrained
     * directions, so that an AMG built from the result treats them as the
     * Dirichlet conditions they are for the projected operator, not as free
     * (Neumann) ones. Only the diagonal is penalised: a point smoother cannot
     * handle a large penalty coupling the components of a node, so this is
     * exact for constrained directions along the coordinate axes (flat
     * contact boundaries aligned with the mesh) and a diagonal approximation
     * otherwise.
     */
    void
    add_constraint_penalty_to(TrilinosWrappers::SparseMatrix &matrix,
                              const double                    gamma) const;

    /**
     * modes := Pi modes at every node block, for @p n_modes vectors stored
     * column by column over the owned rows: the near-null space of the
     * penalised matrix vanishes on the constrained directions.
     */
    void
    project_out_preconditioner_constraints(std::vector<double> &modes,
                                           const unsigned int   n_modes) const;

    /** v := Pi v (owned entries only; no communication). */
    void
    project(TrilinosWrappers::MPI::Vector &v) const;

    /**
     * v := (Pi - S) v, S the node-wise projector onto the stiff directions
     * (owned entries only). Without a stiff threshold, the same as project().
     */
    void
    project_soft(TrilinosWrappers::MPI::Vector &v) const;

    /**
     * dst += sum_i S_i (L_i + D_i)^{-1} S_i src at every node with stiff
     * directions, D_i the diagonal of K0 at the node: the nodal (Jacobi)
     * inverse on the stiff directions.
     */
    void
    add_stiff_inverse(TrilinosWrappers::MPI::Vector &      dst,
                      const TrilinosWrappers::MPI::Vector &src) const;

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
      /** Pi - S: Pi without the stiff directions. */
      Tensor<2, dim> soft_projector;
      /** The Jacobi inverse on the directions split off: the stiff ones
       *  (eigenvectors of L) and those the AMG wrongly treats as constrained;
       *  zero at nodes without either. */
      Tensor<2, dim> stiff_inverse;
    };

    /** dst_i += T_i src_i at every node block, T_i = block.*tensor. */
    void
    add_node_tensors(TrilinosWrappers::MPI::Vector &      dst,
                     const TrilinosWrappers::MPI::Vector &src,
                     Tensor<2, dim> NodeBlock::*          tensor) const;

    /** v_i := T_i v_i at every node block, T_i = block.*tensor. */
    void
    apply_node_tensors(TrilinosWrappers::MPI::Vector &v,
                       Tensor<2, dim> NodeBlock::*    tensor) const;

    const TrilinosWrappers::SparseMatrix *step_matrix;
    const IndexSet *                      owned;
    double                                stiff_threshold;
    std::vector<NodeBlock>                blocks;
    mutable TrilinosWrappers::MPI::Vector projected_src;
  };

  /**
   * Pi P Pi for a symmetric preconditioner P of K0 (the AMG hierarchy of the
   * step matrix, built once per mesh): a symmetric preconditioner on
   * range(Pi) for ProjectedOperator.
   *
   * With a stiff threshold theta > 0 the operator splits off, at each node,
   * the eigendirections v of L_i whose stiffness exceeds theta times that of
   * K0 (v.L v > theta v.D v, D the diagonal of K0 at the node): the slip
   * stiffness F_b c/(|q| - F_b) near a stick-slip front, which P, built
   * without it, cannot see. The preconditioner becomes
   *
   *   (Pi - S) P (Pi - S) + sum_i S_i (L_i + D_i)^{-1} S_i,
   *
   * a block-diagonal (additive) splitting: the AMG treats the stiff
   * directions as constrained, and a nodal solve handles them. Both parts
   * are node-wise, so an application costs what Pi P Pi costs.
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
