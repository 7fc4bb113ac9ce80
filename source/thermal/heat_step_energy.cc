#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <hemicontact/thermal/heat_model.h>

namespace hemicontact
{
  template <int dim>
  void
  HeatModel<dim>::assemble_energy_matrices()
  {
    TrilinosWrappers::SparsityPattern sparsity;
    make_sparsity(hanging_constraints, sparsity);
    capacity_matrix.reinit(sparsity);
    conductivity_matrix.reinit(sparsity);

    // the Gauss rule and the coefficients of the heat step's matrix
    const Quadrature<dim> quadrature = discretization->cell_quadrature(2);
    FEValues<dim>         fe(*discretization->mapping,
                     space->dof_handler->get_fe(),
                     quadrature,
                     update_values | update_gradients | update_JxW_values);
    const unsigned int    n   = fe.dofs_per_cell;
    const unsigned int    n_q = quadrature.size();
    FullMatrix<double>    capacity(n, n), conduction(n, n);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : space->dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe.reinit(cell);
          const std::size_t first   = cell->active_cell_index() * n_q;
          const double     *c_theta = &coefficients.c_theta[first];
          const double     *kappa   = &coefficients.kappa[first];
          capacity                  = 0;
          conduction                = 0;
          for (const unsigned int q : fe.quadrature_point_indices())
            {
              const Tensor<2, dim> K = conductivity_at(kappa[q]);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  {
                    capacity(i, j) += c_theta[q] * fe.shape_value(i, q) *
                                      fe.shape_value(j, q) * fe.JxW(q);
                    conduction(i, j) += (K * fe.shape_grad(i, q)) *
                                        fe.shape_grad(j, q) * fe.JxW(q);
                  }
            }
          cell->get_dof_indices(dofs);
          hanging_constraints.distribute_local_to_global(capacity,
                                                         dofs,
                                                         capacity_matrix);
          hanging_constraints.distribute_local_to_global(conduction,
                                                         dofs,
                                                         conductivity_matrix);
        }
    capacity_matrix.compress(VectorOperation::add);
    conductivity_matrix.compress(VectorOperation::add);
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector
  HeatModel<dim>::without_hanging(
    const TrilinosWrappers::MPI::Vector &theta) const
  {
    TrilinosWrappers::MPI::Vector v(*space->owned, mpi_communicator);
    v = theta;
    for (const auto i : *space->owned)
      if (hanging_constraints.is_constrained(i))
        v[i] = 0;
    return v;
  }

  template <int dim>
  double
  HeatModel<dim>::stored_heat(const TrilinosWrappers::MPI::Vector &theta) const
  {
    const TrilinosWrappers::MPI::Vector v = without_hanging(theta);
    TrilinosWrappers::MPI::Vector       Cv(*space->owned, mpi_communicator);
    capacity_matrix.vmult(Cv, v);
    return 0.5 * (v * Cv);
  }

  template <int dim>
  HeatStepEnergy
  HeatModel<dim>::step_energy(const double                         t,
                              const double                         k,
                              const MechanicalView<dim>           &state,
                              const TrilinosWrappers::MPI::Vector &theta_old,
                              const TrilinosWrappers::MPI::Vector &theta_new,
                              const std::vector<NodeHeat>         &nodes) const
  {
    const TrilinosWrappers::MPI::Vector theta = without_hanging(theta_new);
    TrilinosWrappers::MPI::Vector       change(theta);
    change -= without_hanging(theta_old);
    TrilinosWrappers::MPI::Vector C_change(*space->owned, mpi_communicator),
      K_theta(*space->owned, mpi_communicator);
    capacity_matrix.vmult(C_change, change);
    conductivity_matrix.vmult(K_theta, theta);

    HeatStepEnergy e;
    e.numerical   = 0.5 * (change * C_change);
    e.dissipation = k * (theta * K_theta);
    e.supply      = k * (source_load * theta);
    e.coupling    = k * (coupling_load * theta);
    e.stress_work = k * (stress_load * state.velocity);

    // Gamma_3 by nodal quadrature, where the heat step has the law's terms
    double on_contact = 0, frictional = 0, exchanged = 0;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const auto d = node_dofs[i];
        if (!space->owned->is_element(d) || !nodes[i].booked)
          continue;
        const ContactNode<dim> &node = state.contact_nodes[i];
        const double            into = nodes[i].exchange_coefficient *
                            (nodes[i].foundation_temperature - theta[d]);
        double source = into + nodes[i].frictional_power;
        if (contact_heat_source)
          source += contact_heat_source(node.position, node.normal, t);
        on_contact += k * node.mass * source * theta[d];
        frictional += k * node.mass * nodes[i].frictional_power;
        exchanged += k * node.mass * into;
      }
    // the rows where theta_n = theta_D: their residual k r = C (theta_n -
    // theta_{n-1}) + k K theta_n - k (loads), the heat the prescribed
    // temperature puts in, tested with theta_n (the other rows' residual
    // is the solver's)
    TrilinosWrappers::MPI::Vector residual(C_change);
    residual.add(k, K_theta, -k, source_load);
    residual.add(-k, coupling_load);
    double prescribed = 0;
    for (const auto i : *space->owned)
      if (constraints.is_constrained(i) &&
          !hanging_constraints.is_constrained(i))
        prescribed += residual[i] * theta[i];

    e.supply += Utilities::MPI::sum(on_contact + prescribed, mpi_communicator);
    e.frictional_heat = Utilities::MPI::sum(frictional, mpi_communicator);
    e.exchanged_heat  = Utilities::MPI::sum(exchanged, mpi_communicator);
    return e;
  }

#define HEMICONTACT_INSTANTIATE(dim)                                      \
  template void   HeatModel<dim>::assemble_energy_matrices();             \
  template double HeatModel<dim>::stored_heat(                            \
    const TrilinosWrappers::MPI::Vector &) const;                         \
  template TrilinosWrappers::MPI::Vector HeatModel<dim>::without_hanging( \
    const TrilinosWrappers::MPI::Vector &) const;                         \
  template HeatStepEnergy HeatModel<dim>::step_energy(                    \
    const double,                                                         \
    const double,                                                         \
    const MechanicalView<dim> &,                                          \
    const TrilinosWrappers::MPI::Vector &,                                \
    const TrilinosWrappers::MPI::Vector &,                                \
    const std::vector<NodeHeat> &) const;
  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
