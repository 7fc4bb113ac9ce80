#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/thermal/heat_model.h>
#include <hemicontact/thermal/heat_step_values.h>

#include <algorithm>

namespace hemicontact
{
  template <int dim>
  HeatStepEnergy
  HeatModel<dim>::step_energy(const double                         t,
                              const double                         k,
                              const ProblemState<dim>             &state,
                              const TrilinosWrappers::MPI::Vector &w,
                              const TrilinosWrappers::MPI::Vector &theta_old,
                              const TrilinosWrappers::MPI::Vector &theta_new,
                              const std::vector<NodeHeat>         &nodes) const
  {
    // the dofs where theta_n = theta_D: their rows' residual is the heat
    // that the prescribed temperature puts in, tested with theta_n
    const auto prescribed = [&](const types::global_dof_index i) {
      return constraints.is_constrained(i) &&
             !hanging_constraints.is_constrained(i);
    };
    const FiniteElement<dim>  &fe = space->dof_handler->get_fe();
    HeatStepValues<dim>        values(*discretization, fe);
    FEValues<dim>             &fe_theta = values.theta;
    FEFaceValues<dim>         &fe_face  = values.face;
    const std::vector<double> &div_w    = values.div_w;
    const unsigned int         n        = fe.n_dofs_per_cell();
    const unsigned int         n_q      = values.quadrature.size();
    std::vector<double>        theta_n(n_q), theta_o(n_q), q_src(n_q),
      q_n(values.face_quadrature.size()),
      theta_face(values.face_quadrature.size());
    std::vector<Tensor<1, dim>>          grad_theta(n_q);
    std::vector<types::global_dof_index> dofs(n);
    Vector<double>                       local_residual(n);
    TrilinosWrappers::MPI::Vector residual(*space->owned, mpi_communicator);

    HeatStepEnergy e;
    for (const auto &cell : space->dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell, state.dof_handler, w);
          fe_theta.get_function_values(theta_new, theta_n);
          fe_theta.get_function_values(theta_old, theta_o);
          fe_theta.get_function_gradients(theta_new, grad_theta);
          heat_source->value_list(fe_theta.get_quadrature_points(), q_src);
          cell->get_dof_indices(dofs);
          // the residual reaches a prescribed row from a cell with a
          // prescribed dof or a hanging one (through its masters)
          const bool with_residual =
            std::any_of(dofs.begin(), dofs.end(), [&](const auto i) {
              return constraints.is_constrained(i);
            });
          const std::size_t first   = cell->active_cell_index() * n_q;
          const double     *c_theta = &coefficients.c_theta[first];
          const double     *c_e     = &coefficients.c_e[first];
          const double     *kappa   = &coefficients.kappa[first];
          local_residual            = 0;
          for (const unsigned int q : fe_theta.quadrature_point_indices())
            {
              const Tensor<1, dim> K_grad =
                (conductivity ? kappa[q] * unit_symmetric_tensor<dim>() :
                                conductivity_tensor) *
                grad_theta[q];
              const double JxW = fe_theta.JxW(q);
              const double rate =
                c_theta[q] * (theta_n[q] - theta_o[q]) / k; // c_theta dtheta
              e.numerical += 0.5 * k * rate * (theta_n[q] - theta_o[q]) * JxW;
              e.dissipation += k * (K_grad * grad_theta[q]) * JxW;
              e.coupling -= k * c_e[q] * div_w[q] * theta_n[q] * JxW;
              e.supply += k * q_src[q] * theta_n[q] * JxW;
              if (with_residual)
                for (unsigned int i = 0; i < n; ++i)
                  local_residual(i) += ((rate + c_e[q] * div_w[q] - q_src[q]) *
                                          fe_theta.shape_value(i, q) +
                                        K_grad * fe_theta.shape_grad(i, q)) *
                                       JxW;
            }
          for (const unsigned int f : cell->face_indices())
            if (on_flux_boundary(cell, f))
              {
                fe_face.reinit(cell, f);
                boundary_heat_flux(fe_face, t, q_n);
                fe_face.get_function_values(theta_new, theta_face);
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  {
                    e.supply += k * q_n[q] * theta_face[q] * fe_face.JxW(q);
                    if (with_residual)
                      for (unsigned int i = 0; i < n; ++i)
                        local_residual(i) -=
                          q_n[q] * fe_face.shape_value(i, q) * fe_face.JxW(q);
                  }
              }
          if (with_residual)
            hanging_constraints.distribute_local_to_global(local_residual,
                                                           dofs,
                                                           residual);
        }
    residual.compress(VectorOperation::add);

    // Gamma_3 by nodal quadrature, where the heat step has the law's terms
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const auto d = node_dofs[i];
        if (!space->owned->is_element(d) || constraints.is_constrained(d))
          continue;
        const ContactNode<dim> &node      = state.contact_nodes[i];
        const double            theta_i   = theta_new[d];
        const double            exchanged = nodes[i].exchange_coefficient *
                                 (nodes[i].foundation_temperature - theta_i);
        double source = exchanged + nodes[i].frictional_power;
        if (contact_heat_source)
          source += contact_heat_source(node.position, node.normal, t);
        e.supply += k * node.mass * source * theta_i;
        e.frictional_heat += k * node.mass * nodes[i].frictional_power;
        e.exchanged_heat += k * node.mass * exchanged;
      }
    for (const auto i : *space->owned)
      if (prescribed(i))
        e.supply += k * residual[i] * theta_new[i];

    const auto sum = [&](double &x) {
      x = Utilities::MPI::sum(x, mpi_communicator);
    };
    for (double *x : {&e.numerical,
                      &e.dissipation,
                      &e.supply,
                      &e.coupling,
                      &e.frictional_heat,
                      &e.exchanged_heat})
      sum(*x);
    return e;
  }

#define HEMICONTACT_INSTANTIATE(dim)                   \
  template HeatStepEnergy HeatModel<dim>::step_energy( \
    const double,                                      \
    const double,                                      \
    const ProblemState<dim> &,                         \
    const TrilinosWrappers::MPI::Vector &,             \
    const TrilinosWrappers::MPI::Vector &,             \
    const TrilinosWrappers::MPI::Vector &,             \
    const std::vector<NodeHeat> &) const;
  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
