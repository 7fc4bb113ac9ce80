#pragma once

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/input/parameters.h>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The Krylov and direct solves of a run, with the limits of the 'linear
   * solver' parameters; the preconditioners come from the caller
   * (StepPreconditioner owns them). Every failure is a SolverFailure.
   */
  class LinearSolver
  {
  public:
    LinearSolver(const LinearSolverParameters &parameters, MPI_Comm comm);

    /**
     * CG on the symmetric positive definite @p op with @p preconditioner,
     * starting from the given x. Stops when the residual has dropped by
     * @p reduction relative to the initial one (0: never), or below
     * @p absolute_tolerance. Returns the number of iterations.
     */
    template <typename OperatorType, typename PreconditionerType>
    unsigned int
    solve_cg(const OperatorType                  &op,
             const PreconditionerType            &preconditioner,
             TrilinosWrappers::MPI::Vector       &x,
             const TrilinosWrappers::MPI::Vector &b,
             const double                         reduction,
             const double                         absolute_tolerance);

    /**
     * CG on @p matrix with @p preconditioner to 'relative tolerance' times
     * |b|, starting from the given x. Returns the number of iterations.
     */
    template <typename PreconditionerType>
    unsigned int
    solve(const TrilinosWrappers::SparseMatrix &matrix,
          const PreconditionerType             &preconditioner,
          TrilinosWrappers::MPI::Vector        &x,
          const TrilinosWrappers::MPI::Vector  &b)
    {
      return solve_cg(matrix,
                      preconditioner,
                      x,
                      b,
                      0,
                      parameters.relative_tolerance * b.l2_norm());
    }

    /**
     * Solve the mass-matrix system @p mass x = b with CG and Jacobi (a mass
     * matrix is well conditioned on any mesh) to 'relative tolerance',
     * starting from the given x. Returns the number of iterations.
     */
    unsigned int
    solve_mass(const TrilinosWrappers::SparseMatrix &mass,
               TrilinosWrappers::MPI::Vector        &x,
               const TrilinosWrappers::MPI::Vector  &b);

    /** Solve @p matrix x = b by a sparse LU factorisation (Amesos KLU). */
    void
    solve_direct(const TrilinosWrappers::SparseMatrix &matrix,
                 TrilinosWrappers::MPI::Vector        &x,
                 const TrilinosWrappers::MPI::Vector  &b);

  private:
    LinearSolverParameters parameters;
    MPI_Comm               mpi_communicator;
  };
} // namespace hemicontact
