#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <hemicontact/input_error.h>
#include <hemicontact/linear_solver.h>

#include <Teuchos_ParameterList.hpp>

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
    amg.reset();
  }

  void
  LinearSolver::setup_preconditioner(
    const TrilinosWrappers::SparseMatrix &matrix)
  {
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
    ml_list.set("null space: vectors", rigid_body_modes.data());

    amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    amg->initialize(matrix, ml_list);
    ++setups;
  }

  unsigned int
  LinearSolver::solve(const TrilinosWrappers::SparseMatrix &matrix,
                      TrilinosWrappers::MPI::Vector &       x,
                      const TrilinosWrappers::MPI::Vector & b,
                      const bool reuse_preconditioner)
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

    Assert(n_modes > 0, ExcMessage("set_rigid_body_modes() was not called."));
    if (!reuse_preconditioner || amg == nullptr)
      setup_preconditioner(matrix);
    const double  b_norm = b.l2_norm();
    SolverControl control(parameters.max_iterations,
                          std::max(parameters.relative_tolerance * b_norm,
                                   1e-300));
    SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
    try
      {
        cg.solve(matrix, x, b, *amg);
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

  template void
  LinearSolver::set_rigid_body_modes<2>(const DoFHandler<2> &,
                                        const Mapping<2> &);
  template void
  LinearSolver::set_rigid_body_modes<3>(const DoFHandler<3> &,
                                        const Mapping<3> &);
} // namespace hemicontact
