#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/solver/linear_solver.h>
#include <hemicontact/solver/step_preconditioner.h>

#include <algorithm>

namespace hemicontact
{
  LinearSolver::LinearSolver(const LinearSolverParameters &parameters,
                             MPI_Comm                      comm)
    : parameters(parameters)
    , mpi_communicator(comm)
  {}

  template <typename OperatorType, typename PreconditionerType>
  unsigned int
  LinearSolver::solve_cg(const OperatorType                  &op,
                         const PreconditionerType            &preconditioner,
                         TrilinosWrappers::MPI::Vector       &x,
                         const TrilinosWrappers::MPI::Vector &b,
                         const double                         reduction,
                         const double absolute_tolerance)
  {
    ReductionControl                        control(parameters.max_iterations,
                             std::max(absolute_tolerance, 1e-300),
                             reduction);
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    try
      {
        cg.solve(op, x, b, preconditioner);
      }
    catch (const SolverControl::NoConvergence &e)
      {
        throw SolverFailure(
          "the linear solver (CG + AMG) did not converge in " +
          std::to_string(e.last_step) + " iterations (residual " +
          std::to_string(e.last_residual) + ", target " +
          std::to_string(control.tolerance()) +
          "); raise 'linear solver/max iterations' or try 'type = direct'.");
      }
    return control.last_step();
  }

  unsigned int
  LinearSolver::solve_mass(const TrilinosWrappers::SparseMatrix &mass,
                           TrilinosWrappers::MPI::Vector        &x,
                           const TrilinosWrappers::MPI::Vector  &b)
  {
    TrilinosWrappers::PreconditionJacobi jacobi;
    jacobi.initialize(mass);
    return solve(mass, jacobi, x, b);
  }

  void
  LinearSolver::solve_direct(const TrilinosWrappers::SparseMatrix &matrix,
                             TrilinosWrappers::MPI::Vector        &x,
                             const TrilinosWrappers::MPI::Vector  &b)
  {
    SolverControl                                  control(1, 0);
    TrilinosWrappers::SolverDirect::AdditionalData data(false, "Amesos_Klu");
    TrilinosWrappers::SolverDirect                 solver(control, data);
    solver.solve(matrix, x, b);
  }

#define HEMICONTACT_INSTANTIATE(Operator, Preconditioner) \
  template unsigned int LinearSolver::solve_cg(           \
    const Operator &,                                     \
    const Preconditioner &,                               \
    TrilinosWrappers::MPI::Vector &,                      \
    const TrilinosWrappers::MPI::Vector &,                \
    const double,                                         \
    const double);
  HEMICONTACT_INSTANTIATE(TrilinosWrappers::SparseMatrix,
                          TrilinosWrappers::PreconditionAMG)
  HEMICONTACT_INSTANTIATE(TrilinosWrappers::SparseMatrix,
                          TrilinosWrappers::PreconditionJacobi)
  HEMICONTACT_INSTANTIATE(ProjectedOperator<2>, StepPreconditioner<2>)
  HEMICONTACT_INSTANTIATE(ProjectedOperator<3>, StepPreconditioner<3>)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
