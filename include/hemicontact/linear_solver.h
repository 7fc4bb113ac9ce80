#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/parameters.h>

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
     * converge. With @p reuse_preconditioner the AMG hierarchy of the
     * previous call is kept (the caller guarantees the same matrix).
     */
    unsigned int
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          TrilinosWrappers::MPI::Vector &       x,
          const TrilinosWrappers::MPI::Vector & b,
          const bool reuse_preconditioner = false);

    /** Number of preconditioner set-ups so far. */
    unsigned int
    n_setups() const
    {
      return setups;
    }

  private:
    void
    setup_preconditioner(const TrilinosWrappers::SparseMatrix &matrix);

    LinearSolverParameters parameters;
    MPI_Comm               mpi_communicator;
    unsigned int           n_modes = 0;
    std::vector<double>    rigid_body_modes; ///< column-major, owned rows
    std::unique_ptr<TrilinosWrappers::PreconditionAMG> amg;
    unsigned int                                       setups = 0;
  };
} // namespace hemicontact
