#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/parameters.h>
#include <hemicontact/projected_operator.h>

#include <functional>
#include <memory>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The linear solver of each Newton step: CG preconditioned by Trilinos ML
   * smoothed-aggregation AMG with the rigid-body modes as near-null space,
   * or a sparse direct solver (Amesos KLU) for small problems.
   */
  class LinearSolver
  {
  public:
    LinearSolver(const LinearSolverParameters &parameters, MPI_Comm comm);

    /** Compute the rigid-body modes of the current mesh (once per mesh). */
    template <int dim>
    void
    set_rigid_body_modes(const DoFHandler<dim> &dof_handler,
                         const Mapping<dim> &   mapping);

    /**
     * Solve @p matrix x = b to the relative tolerance of the parameters
     * (starting from the given x). Returns the number of Krylov iterations
     * (1 for the direct solver). Throws SolverFailure if CG does not
     * converge. The AMG hierarchy is built for @p matrix on every call.
     */
    unsigned int
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          TrilinosWrappers::MPI::Vector &       x,
          const TrilinosWrappers::MPI::Vector & b);

    /**
     * Solve the mass-matrix system @p mass x = b with CG and Jacobi (a mass
     * matrix is well conditioned on any mesh) to 'relative tolerance',
     * starting from the given x. Returns the number of iterations.
     */
    unsigned int
    solve_mass(const TrilinosWrappers::SparseMatrix &mass,
               TrilinosWrappers::MPI::Vector &       x,
               const TrilinosWrappers::MPI::Vector & b);
    /**
     * Solve @p matrix x = b with CG and the AMG hierarchy of the step
     * matrix (see step_preconditioner()), to @p relative_tolerance times
     * |b| (if positive; else 'relative tolerance').
     */
    unsigned int
    solve_with_step_preconditioner(
      const TrilinosWrappers::SparseMatrix &step_matrix,
      TrilinosWrappers::MPI::Vector &       x,
      const TrilinosWrappers::MPI::Vector & b,
      const double                          relative_tolerance = -1);

    /**
     * Solve op x = b on range(Pi) with CG preconditioned by Pi P Pi, P the
     * AMG hierarchy of the contact matrix if one was built
     * (rebuild_contact_preconditioner()), else that of the step matrix. Stops
     * when the residual has dropped by @p reduction relative to the initial
     * one, or below @p absolute_tolerance. x must lie in range(Pi) on entry.
     * Returns the number of iterations.
     */
    template <int dim>
    unsigned int
    solve_projected(const ProjectedOperator<dim> &        op,
                    const TrilinosWrappers::SparseMatrix &step_matrix,
                    TrilinosWrappers::MPI::Vector &       x,
                    const TrilinosWrappers::MPI::Vector & b,
                    const double                          reduction,
                    const double                          absolute_tolerance);

    /**
     * Whether the projected solver should (re)build its AMG hierarchy from
     * the current constraints now: with 'constrained preconditioner', when
     * none is built on this mesh yet; with a 'preconditioner rebuild factor',
     * when the Krylov time lost since the last build, against the first
     * solve after it (iterations per decade of reduction), exceeds the factor
     * times the time of one set-up. Never after
     * retire_contact_preconditioner() on this mesh. The same answer on every
     * rank.
     */
    bool
    contact_preconditioner_is_stale() const;

    /**
     * Build the AMG hierarchy of @p contact_matrix (K0 plus a penalty on the
     * constrained contact directions) to precondition the projected operator
     * from now on, until the next rebuild, retire_contact_preconditioner() or
     * mesh. @p modify_modes changes a copy of the rigid-body modes (n_modes
     * columns over the owned rows) first, e.g. to vanish on the penalised
     * directions.
     */
    void
    rebuild_contact_preconditioner(
      const TrilinosWrappers::SparseMatrix &contact_matrix,
      const std::function<void(std::vector<double> &, unsigned int)>
        &modify_modes);

    /**
     * Drop the contact preconditioner and use the AMG of K0 until the next
     * mesh (clear_preconditioners()): its constraints no longer match.
     */
    void
    retire_contact_preconditioner()
    {
      contact_amg.reset();
      contact_preconditioner_retired = true;
    }

    /** Whether a contact preconditioner (not the AMG of K0) is in use. */
    bool
    has_contact_preconditioner() const
    {
      return contact_amg != nullptr;
    }

    /**
     * The AMG hierarchy of the step matrix K0 = rho/k M + A: built on the
     * first call after set_rigid_body_modes() (i.e. once per mesh), then
     * reused by every later call.
     */
    const TrilinosWrappers::PreconditionAMG &
    step_preconditioner(const TrilinosWrappers::SparseMatrix &step_matrix);

    /**
     * Forget every AMG hierarchy (the matrices changed, e.g. with the time
     * step); the next solve builds them anew.
     */
    void
    clear_preconditioners();

    /** Wall seconds spent in AMG set-ups so far. */
    double
    setup_seconds() const
    {
      return setup_wall_seconds;
    }

    /** Number of preconditioner set-ups so far. */
    unsigned int
    n_setups() const
    {
      return setups;
    }

  private:
    std::unique_ptr<TrilinosWrappers::PreconditionAMG>
    make_amg(const TrilinosWrappers::SparseMatrix &matrix,
             const std::vector<double> *          modes = nullptr);

    /** CG on (matrix or operator, preconditioner); SolverFailure if it stalls. */
    template <typename OperatorType, typename PreconditionerType>
    unsigned int
    run_cg(const OperatorType &op, const PreconditionerType &preconditioner,
           TrilinosWrappers::MPI::Vector &      x,
           const TrilinosWrappers::MPI::Vector &b, SolverControl &control);

    LinearSolverParameters parameters;
    MPI_Comm               mpi_communicator;
    unsigned int           n_modes = 0;
    std::vector<double>    rigid_body_modes; ///< column-major, owned rows
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg; ///< of the last matrix
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> step_amg; ///< of K0
    /** Of K0 plus a penalty on recently constrained contact directions. */
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> contact_amg;
    /** retire_contact_preconditioner() was called on this mesh. */
    bool contact_preconditioner_retired = false;
    /** @name The cost model of rebuilding the projected solver's AMG. */
    double last_setup_seconds        = 0;
    double reference_work_per_decade = 0; ///< first solve after a build
    double lost_seconds              = 0; ///< Krylov time above that rate
    unsigned int                                       setups = 0;
    double setup_wall_seconds = 0;
  };
} // namespace hemicontact
