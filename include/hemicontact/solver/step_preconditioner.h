#pragma once

#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/base/memory_breakdown.h>
#include <hemicontact/input/solver_tuning.h>
#include <hemicontact/solver/projected_operator.h>

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /** What StepPreconditioner::prepare() did with the constrained AMG on a
   *  mesh so far (what it carries from one Newton solve to the next). */
  enum class ConstrainedAmgStatus : unsigned int
  {
    none    = 0, ///< not built (yet)
    built   = 1, ///< built, and in use
    dropped = 2  ///< dropped: the AMG of K0 is used on this mesh
  };

  /**
   * Every AMG hierarchy of a mesh (Trilinos ML, smoothed aggregation, the
   * rigid-body modes as near-null space) and the preconditioner of the
   * projected Newton operator built from them.
   *
   * For a ProjectedOperator with projectors Pi_i and nodal stiffnesses L_i
   * it applies
   *
   *   (Pi - S) P (Pi - S) + sum_i S_i (L_i + D_i)^{-1} S_i,
   *
   * P an AMG hierarchy, D_i the diagonal of K0 at node i and S_i the
   * projector onto the node's directions that P cannot treat: those stiffer
   * than 'stiff_contact_threshold' times D_i (the slip stiffness next to a
   * stick-slip front) and the free ones that P was built to treat as
   * constrained. P is the "constrained AMG" -- of K0 plus a penalty on the
   * directions the contact branches of the mesh's first Newton iteration
   * constrain, so that stuck nodes are Dirichlet conditions for it -- until
   * too many nodes have freed such a direction, and the AMG of K0 after
   * that (doc/performance.md, "Design choices"). The AMG of K0 is freed
   * when the constrained AMG is built (doc/performance.md, "Memory").
   */
  template <int dim>
  class StepPreconditioner
  {
  public:
    StepPreconditioner(const SolverTuning &tuning, MPI_Comm comm);

    /**
     * A new mesh: compute its rigid-body modes and forget every hierarchy.
     */
    void
    reinit(const DoFHandler<dim> &dof_handler, const Mapping<dim> &mapping);

    /** K0 changed (e.g. with the time step): forget every hierarchy. */
    void
    clear();

    /** The AMG of K0, built at the first call after clear(). */
    const TrilinosWrappers::PreconditionAMG &
    step_amg(const TrilinosWrappers::SparseMatrix &step_matrix);

    /**
     * An AMG of another matrix on this mesh (e.g. the elastic matrix B),
     * built now and held until the next call, clear() or reinit().
     */
    const TrilinosWrappers::PreconditionAMG &
    amg_of(const TrilinosWrappers::SparseMatrix &matrix);

    /**
     * Make this the preconditioner of @p op, whose nodes are in the same
     * order in every Newton iteration on a mesh: drop the constrained AMG if
     * it no longer matches the branches, build it if none was built on
     * this mesh yet, and split off the directions the AMG in use cannot
     * treat. @p op must outlive the following vmult() calls.
     */
    void
    prepare(const ProjectedOperator<dim> &op);

    /** dst = the preconditioner of the prepared operator applied to src. */
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src) const;

    /** Whether the constrained AMG (not the AMG of K0) is in use. */
    bool
    uses_constrained_amg() const
    {
      return constrained_amg != nullptr;
    }

    /** What prepare() did with the constrained AMG on this mesh so far. */
    ConstrainedAmgStatus
    constrained_amg_status() const;

    /**
     * Per node of the operators prepared on this mesh, the directions the
     * constrained AMG treats as constrained (empty unless it is built).
     */
    const std::vector<Tensor<2, dim>> &
    constrained_directions() const
    {
      return constrained_amg_directions;
    }

    /**
     * Take the state @p status of another preconditioner on this mesh and
     * step matrix (e.g. of the run a checkpoint saved), whose constrained
     * AMG (if built) was built from the projectors of @p op: the next
     * prepare() then does what it would have done there.
     */
    void
    restore(const ProjectedOperator<dim> &op,
            const ConstrainedAmgStatus    status);

    /** Wall seconds spent in AMG set-ups so far. */
    double
    setup_seconds() const
    {
      return setup_wall_seconds;
    }

    /**
     * Add to @p breakdown each AMG hierarchy held (the heap it added when
     * built), the penalised matrix and the rigid-body modes.
     */
    void
    add_memory(MemoryBreakdown &breakdown) const;

    /** Number of AMG set-ups so far. */
    unsigned int
    n_setups() const
    {
      return setups;
    }

  private:
    /** The nodal part of the preconditioner at one node of the operator. */
    struct NodeSplit
    {
      std::array<unsigned int, dim> local_index;
      Tensor<2, dim>                soft_projector; ///< Pi_i - S_i
      Tensor<2, dim>                stiff_inverse;  ///< S_i (L_i + D_i)^-1 S_i
    };

    std::unique_ptr<TrilinosWrappers::PreconditionAMG>
    make_amg(const TrilinosWrappers::SparseMatrix &matrix,
             const std::vector<double>            &modes);

    /**
     * The share of the operator's nodes with a free direction that the
     * constrained AMG treats as constrained or, if @p either_way, with any
     * constrained directions other than the AMG's (the same on every rank).
     */
    double
    constrained_mismatch(const ProjectedOperator<dim> &op,
                         const bool either_way = false) const;

    /** Build the constrained AMG from the constraints of @p op. */
    void
    build_constrained_amg(const ProjectedOperator<dim> &op);

    SolverTuning        tuning;
    MPI_Comm            mpi_communicator;
    unsigned int        n_modes = 0;
    std::vector<double> rigid_body_modes; ///< column-major, owned rows

    std::unique_ptr<TrilinosWrappers::PreconditionAMG> k0_amg;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> other_amg;
    /** K0 plus the penalty: the matrix the constrained AMG was built from. */
    TrilinosWrappers::SparseMatrix                     penalised_step_matrix;
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> constrained_amg;
    /** Per operator node, the directions the constrained AMG treats as
     *  constrained (I - Pi_i of the iteration it was built in). */
    std::vector<Tensor<2, dim>> constrained_amg_directions;
    /** The constrained AMG was dropped on this mesh: not built again. */
    bool constrained_amg_dropped = false;

    const TrilinosWrappers::PreconditionAMG *amg_in_use = nullptr;
    std::vector<NodeSplit>                   splits;
    mutable TrilinosWrappers::MPI::Vector    projected_src;

    /** Heap bytes each AMG held added when it was built. */
    std::map<const TrilinosWrappers::PreconditionAMG *, double> amg_bytes;

    unsigned int setups             = 0;
    double       setup_wall_seconds = 0;
  };
} // namespace hemicontact
