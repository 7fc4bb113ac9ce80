#include <deal.II/base/utilities.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/problem/cell_matrices.h>
#include <hemicontact/problem/state_projection.h>

#include <map>
#include <vector>

// 'adaptivity/state transfer = projection'. The next step sees the state
// only through the functional rho/k M w_n - B u_{n+1}, u_{n+1} = u_n + k w_n
// (see assemble_step_rhs()). On refined and kept cells interpolation moves
// it exactly (the old fields are in the new space there); on coarsened cells
// nodal injection does not. So on coarsened cells we keep the functionals
// instead: int rho w . phi and a_B(u_{n+1}, phi) for the parent's shape
// functions phi, summed over the children before they disappear; on the new
// mesh, M w = (rho M w)_old and B u_{n+1} = (B u_{n+1})_old are solved.

namespace hemicontact
{
  namespace
  {
    // What the mesh tells the data-transfer callbacks about a cell: deal.II
    // 9.6 names it dealii::CellStatus (Triangulation::CellStatus and
    // CELL_COARSEN are deprecated there), deal.II 9.4 has only the latter.
#if DEAL_II_VERSION_GTE(9, 6, 0)
    template <int dim>
    using TransferStatus = CellStatus;
    template <int dim>
    constexpr TransferStatus<dim> children_coarsened =
      CellStatus::children_will_be_coarsened;
#else
    template <int dim>
    using TransferStatus = typename Triangulation<dim>::CellStatus;
    template <int dim>
    constexpr TransferStatus<dim> children_coarsened =
      Triangulation<dim>::CELL_COARSEN;
#endif

    /** The parent's local vectors [rho M w; B u_next] in one array. */
    using CellFunctionals = std::vector<double>;

    /** FEValues for the cell matrices (values, gradients, JxW). */
    template <int dim>
    FEValues<dim>
    matrix_fe_values(const Discretization<dim> &discretization)
    {
      return FEValues<dim>(*discretization.mapping,
                           *discretization.fe,
                           discretization.cell_quadrature(2),
                           update_values | update_gradients |
                             update_JxW_values);
    }

    /** The cell's rho M w and B u_next (its local vectors m_w, b_u). */
    template <int dim>
    void
    cell_functionals(const KelvinVoigtMaterial<dim>                &material,
                     FEValues<dim>                                 &fe_values,
                     const typename DoFHandler<dim>::cell_iterator &cell,
                     const TrilinosWrappers::MPI::Vector           &w,
                     const TrilinosWrappers::MPI::Vector           &u_next,
                     Vector<double>                                &m_w,
                     Vector<double>                                &b_u)
    {
      const unsigned int n = fe_values.dofs_per_cell;
      FullMatrix<double> mass(n, n), viscous(n, n), elastic(n, n);
      Vector<double>     w_cell(n), u_cell(n);
      fe_values.reinit(cell);
      cell_matrices(material, fe_values, mass, viscous, elastic);
      cell->get_dof_values(w, w_cell);
      cell->get_dof_values(u_next, u_cell);
      mass.vmult(m_w, w_cell);
      elastic.vmult(b_u, u_cell);
    }
  } // namespace

  template <int dim>
  unsigned int
  attach_coarsened_functionals(const ProblemState<dim>             &state,
                               const TrilinosWrappers::MPI::Vector &w,
                               const TrilinosWrappers::MPI::Vector &u_next)
  {
    auto *tria = dynamic_cast<parallel::DistributedTriangulationBase<dim> *>(
      state.discretization.triangulation.get());
    AssertThrow(tria != nullptr, ExcInternalError());

    // (the mesh keeps the callback until execute_coarsening_and_refinement():
    // it holds the problem's objects, not the view @p state)
    const auto pack =
      [&discretization = state.discretization,
       &dof_handler    = state.dof_handler,
       &material       = state.material,
       &w,
       &u_next](const typename Triangulation<dim>::cell_iterator &cell,
                const TransferStatus<dim>                         status) {
        if (status != children_coarsened<dim>)
          return std::vector<char>();
        // called on the parent, while its children and the old dofs still exist
        const FiniteElement<dim> &fe        = *discretization.fe;
        const unsigned int        n         = fe.n_dofs_per_cell();
        FEValues<dim>             fe_values = matrix_fe_values(discretization);
        Vector<double>            m_w(n), b_u(n), parent_m_w(n), parent_b_u(n);
        const typename DoFHandler<dim>::cell_iterator parent(*cell,
                                                             &dof_handler);
        for (unsigned int c = 0; c < parent->n_children(); ++c)
          {
            cell_functionals(
              material, fe_values, parent->child(c), w, u_next, m_w, b_u);
            // parent shape function i on child c = sum_j P_ji (child's j)
            const FullMatrix<double> &prolongation =
              fe.get_prolongation_matrix(c, parent->refinement_case());
            prolongation.Tvmult_add(parent_m_w, m_w);
            prolongation.Tvmult_add(parent_b_u, b_u);
          }
        CellFunctionals values(parent_m_w.begin(), parent_m_w.end());
        values.insert(values.end(), parent_b_u.begin(), parent_b_u.end());
        return Utilities::pack(values, /*allow_compression=*/false);
      };
    return tria->register_data_attach(pack,
                                      /*returns_variable_size_data=*/true);
  }

  template <int dim>
  void
  project_transferred_state(const ProblemState<dim>       &state,
                            LinearSolver                  &linear_solver,
                            StepPreconditioner<dim>       &preconditioner,
                            const unsigned int             handle,
                            TrilinosWrappers::MPI::Vector &w,
                            TrilinosWrappers::MPI::Vector &u_next)
  {
    const Discretization<dim>       &discretization   = state.discretization;
    const AffineConstraints<double> &base_constraints = state.base_constraints;
    auto *tria = dynamic_cast<parallel::DistributedTriangulationBase<dim> *>(
      discretization.triangulation.get());
    AssertThrow(tria != nullptr, ExcInternalError());

    std::map<CellId, CellFunctionals> coarsened;
    tria->notify_ready_to_unpack(
      handle,
      [&coarsened](
        const typename Triangulation<dim>::cell_iterator               &cell,
        const TransferStatus<dim>                                       status,
        const boost::iterator_range<std::vector<char>::const_iterator> &data) {
        if (status == children_coarsened<dim>)
          coarsened[cell->id()] =
            Utilities::unpack<CellFunctionals>(data.begin(),
                                               data.end(),
                                               /*allow_compression=*/false);
      });

    // the right-hand sides: on coarsened cells the attached integrals, on
    // all others those of the interpolated fields, exact there as long as
    // the hanging-node values are not yet distributed (a kept cell next to
    // a coarsened one holds the old values on its now hanging nodes)
    TrilinosWrappers::MPI::Vector w_ghosted(state.locally_owned_dofs,
                                            state.locally_relevant_dofs,
                                            state.mpi_communicator);
    TrilinosWrappers::MPI::Vector u_ghosted(w_ghosted);
    w_ghosted = w;
    u_ghosted = u_next;
    TrilinosWrappers::MPI::Vector m_w(state.locally_owned_dofs,
                                      state.mpi_communicator);
    TrilinosWrappers::MPI::Vector b_u(m_w);

    const FiniteElement<dim> &fe        = *discretization.fe;
    const unsigned int        n         = fe.n_dofs_per_cell();
    FEValues<dim>             fe_values = matrix_fe_values(discretization);
    Vector<double>            m_w_cell(n), b_u_cell(n);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto attached = coarsened.find(cell->id());
          if (attached != coarsened.end())
            for (unsigned int i = 0; i < n; ++i)
              {
                m_w_cell[i] = attached->second[i];
                b_u_cell[i] = attached->second[n + i];
              }
          else
            cell_functionals(state.material,
                             fe_values,
                             cell,
                             w_ghosted,
                             u_ghosted,
                             m_w_cell,
                             b_u_cell);
          cell->get_dof_indices(dofs);
          base_constraints.distribute_local_to_global(m_w_cell, dofs, m_w);
          base_constraints.distribute_local_to_global(b_u_cell, dofs, b_u);
        }
    m_w.compress(VectorOperation::add);
    b_u.compress(VectorOperation::add);

    // the interpolated fields are the initial guesses
    linear_solver.solve_mass(state.mass_matrix, w, m_w);
    linear_solver.solve(state.elastic_matrix,
                        preconditioner.amg_of(state.elastic_matrix),
                        u_next,
                        b_u);
    // free the AMG of B: nothing else on this mesh has been built yet
    preconditioner.clear();
  }

#define HEMICONTACT_INSTANTIATE(dim)                                       \
  template unsigned int attach_coarsened_functionals(                      \
    const ProblemState<dim> &,                                             \
    const TrilinosWrappers::MPI::Vector &,                                 \
    const TrilinosWrappers::MPI::Vector &);                                \
  template void project_transferred_state(const ProblemState<dim> &,       \
                                          LinearSolver &,                  \
                                          StepPreconditioner<dim> &,       \
                                          const unsigned int,              \
                                          TrilinosWrappers::MPI::Vector &, \
                                          TrilinosWrappers::MPI::Vector &);

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
