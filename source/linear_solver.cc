#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <hemicontact/input_error.h>
#include <hemicontact/linear_solver.h>

#include <Teuchos_ParameterList.hpp>

#include <cmath>
#include <map>

namespace hemicontact
{
  LinearSolver::LinearSolver(const LinearSolverParameters &parameters,
                             MPI_Comm                      comm)
    : parameters(parameters)
    , mpi_communicator(comm)
  {}

  template <int dim>
  void
  LinearSolver::set_rigid_body_modes(const DoFHandler<dim> &dof_handler,
                                     const Mapping<dim> &   mapping)
  {
    const IndexSet &owned   = dof_handler.locally_owned_dofs();
    const unsigned n_owned  = owned.n_elements();
    n_modes                 = dim == 2 ? 3 : 6;
    rigid_body_modes.assign(std::size_t(n_owned) * n_modes, 0.);

    std::map<types::global_dof_index, Point<dim>> support_points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support_points);

    // centre of the owned points, averaged over all processes
    Point<dim> centre;
    for (const auto &p : support_points)
      if (owned.is_element(p.first))
        centre += p.second;
    const double n_points =
      Utilities::MPI::sum(static_cast<double>(n_owned), mpi_communicator);
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = Utilities::MPI::sum(centre[d], mpi_communicator) / n_points;

    const FiniteElement<dim> &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned.is_element(dofs[i]))
              {
                const unsigned int row = owned.index_within_set(dofs[i]);
                const unsigned int c   = fe.system_to_component_index(i).first;
                const Tensor<1, dim> x = support_points.at(dofs[i]) - centre;
                auto mode = [&](const unsigned int m) -> double & {
                  return rigid_body_modes[std::size_t(m) * n_owned + row];
                };
                mode(c) = 1.;
                if constexpr (dim == 2)
                  mode(2) = (c == 0 ? -x[1] : x[0]);
                else
                  {
                    // rotations about the x, y and z axes
                    const double r[3][3] = {{0, -x[2], x[1]},
                                            {x[2], 0, -x[0]},
                                            {-x[1], x[0], 0}};
                    for (unsigned int a = 0; a < 3; ++a)
                      mode(3 + a) = r[a][c];
                  }
              }
        }
    clear_preconditioners();
  }

  void
  LinearSolver::clear_preconditioners()
  {
    amg.reset();
    step_amg.reset();
    contact_amg.reset();
    contact_preconditioner_retired = false;
    reference_work_per_decade = 0;
    lost_seconds              = 0;
  }

  std::unique_ptr<TrilinosWrappers::PreconditionAMG>
  LinearSolver::make_amg(const TrilinosWrappers::SparseMatrix &matrix,
                         const std::vector<double> *          modes)
  {
    Assert(n_modes > 0, ExcMessage("set_rigid_body_modes() was not called."));
    Timer timer;
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = parameters.smoother_sweeps;
    data.aggregation_threshold = parameters.aggregation_threshold;

    Teuchos::ParameterList               ml_list;
    std::unique_ptr<Epetra_MultiVector> unused_modes;
    data.set_parameters(ml_list, unused_modes, matrix);
    ml_list.set("null space: type", "pre-computed");
    ml_list.set("null space: dimension", static_cast<int>(n_modes));
    ml_list.set("null space: vectors",
                modes ? const_cast<double *>(modes->data()) :
                        rigid_body_modes.data());

    auto result = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    result->initialize(matrix, ml_list);
    ++setups;
    last_setup_seconds = Utilities::MPI::max(timer.wall_time(), mpi_communicator);
    setup_wall_seconds += last_setup_seconds;
    reference_work_per_decade = 0;
    lost_seconds              = 0;
    return result;
  }

  const TrilinosWrappers::PreconditionAMG &
  LinearSolver::step_preconditioner(
    const TrilinosWrappers::SparseMatrix &step_matrix)
  {
    if (step_amg == nullptr)
      step_amg = make_amg(step_matrix);
    return *step_amg;
  }

  template <typename OperatorType, typename PreconditionerType>
  unsigned int
  LinearSolver::run_cg(const OperatorType &                 op,
                       const PreconditionerType &           preconditioner,
                       TrilinosWrappers::MPI::Vector &      x,
                       const TrilinosWrappers::MPI::Vector &b,
                       SolverControl &                      control)
  {
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
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      TrilinosWrappers::MPI::Vector &       x,
                      const TrilinosWrappers::MPI::Vector & b)
  {
    if (parameters.type == "direct")
      {
        SolverControl control(1, 0);
        TrilinosWrappers::SolverDirect::AdditionalData data(false,
                                                            "Amesos_Klu");
        TrilinosWrappers::SolverDirect solver(control, data);
        solver.solve(matrix, x, b);
        return 1;
      }

    amg = make_amg(matrix);
    SolverControl control(parameters.max_iterations,
                          std::max(parameters.relative_tolerance * b.l2_norm(),
                                   1e-300));
    return run_cg(matrix, *amg, x, b, control);
  }

  unsigned int
  LinearSolver::solve_mass(const TrilinosWrappers::SparseMatrix &mass,
                           TrilinosWrappers::MPI::Vector &       x,
                           const TrilinosWrappers::MPI::Vector & b)
  {
    TrilinosWrappers::PreconditionJacobi jacobi;
    jacobi.initialize(mass);
    SolverControl control(parameters.max_iterations,
                          std::max(parameters.relative_tolerance * b.l2_norm(),
                                   1e-300));
    return run_cg(mass, jacobi, x, b, control);
  }

  unsigned int
  LinearSolver::solve_with_step_preconditioner(
    const TrilinosWrappers::SparseMatrix &step_matrix,
    TrilinosWrappers::MPI::Vector &       x,
    const TrilinosWrappers::MPI::Vector & b,
    const double                          relative_tolerance)
  {
    if (parameters.type == "direct")
      return solve(step_matrix, x, b);
    const double tolerance = relative_tolerance > 0 ?
                               relative_tolerance :
                               parameters.relative_tolerance;
    SolverControl control(parameters.max_iterations,
                          std::max(tolerance * b.l2_norm(), 1e-300));
    return run_cg(step_matrix, step_preconditioner(step_matrix), x, b,
                  control);
  }

  void
  LinearSolver::rebuild_contact_preconditioner(
    const TrilinosWrappers::SparseMatrix &contact_matrix,
    const std::function<void(std::vector<double> &, unsigned int)> &modify_modes)
  {
    std::vector<double> modes(rigid_body_modes);
    modify_modes(modes, n_modes);
    contact_amg = make_amg(contact_matrix, &modes);
  }

  template <int dim>
  unsigned int
  LinearSolver::solve_projected(const ProjectedOperator<dim> &        op,
                                const TrilinosWrappers::SparseMatrix &step_matrix,
                                TrilinosWrappers::MPI::Vector &       x,
                                const TrilinosWrappers::MPI::Vector & b,
                                const double reduction,
                                const double absolute_tolerance)
  {
    const ProjectedPreconditioner<dim> preconditioner(
      op, contact_amg ? *contact_amg : step_preconditioner(step_matrix));
    ReductionControl control(parameters.max_iterations,
                             std::max(absolute_tolerance, 1e-300), reduction);
    Timer              timer(mpi_communicator, /*sync_lap_times=*/true);
    const unsigned int n = run_cg(op, preconditioner, x, b, control);
    timer.stop();

    // Krylov work per decade of reduction, against the first solve after
    // the last AMG build; the time of the surplus iterations accumulates
    const double decades =
      std::log10(std::max(control.initial_value(), 1e-300) /
                 std::max(control.last_value(), 1e-300));
    if (n > 0 && decades > 0.5)
      {
        const double work_per_decade = n / decades;
        if (reference_work_per_decade == 0)
          reference_work_per_decade = work_per_decade;
        const double surplus =
          std::max(0., n - reference_work_per_decade * decades);
        lost_seconds += surplus * timer.wall_time() / n;
      }
    return n;
  }

  bool
  LinearSolver::contact_preconditioner_is_stale() const
  {
    if (contact_preconditioner_retired)
      return false;
    const double factor = parameters.preconditioner_rebuild_factor;
    const bool   lost_too_much =
      factor > 0 && lost_seconds > factor * last_setup_seconds;
    // with 'constrained preconditioner' the first build of a mesh comes at
    // once: the AMG of K0 alone does not see the constraints
    if (contact_amg == nullptr)
      return parameters.constrained_preconditioner || lost_too_much;
    return lost_too_much;
  }

  template unsigned int
  LinearSolver::solve_projected<2>(const ProjectedOperator<2> &,
                                   const TrilinosWrappers::SparseMatrix &,
                                   TrilinosWrappers::MPI::Vector &,
                                   const TrilinosWrappers::MPI::Vector &,
                                   const double, const double);
  template unsigned int
  LinearSolver::solve_projected<3>(const ProjectedOperator<3> &,
                                   const TrilinosWrappers::SparseMatrix &,
                                   TrilinosWrappers::MPI::Vector &,
                                   const TrilinosWrappers::MPI::Vector &,
                                   const double, const double);

  template void
  LinearSolver::set_rigid_body_modes<2>(const DoFHandler<2> &,
                                        const Mapping<2> &);
  template void
  LinearSolver::set_rigid_body_modes<3>(const DoFHandler<3> &,
                                        const Mapping<3> &);
} // namespace hemicontact
