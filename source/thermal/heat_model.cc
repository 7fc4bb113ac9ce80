#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/expressions/expression_function.h>
#include <hemicontact/model/problem_data.h>
#include <hemicontact/thermal/heat_model.h>
#include <hemicontact/thermal/heat_step_values.h>

#include <cmath>
#include <map>
#include <optional>
#include <sstream>

#include "heat_data_check.h"

namespace hemicontact
{
  using namespace heat_data_check;

  namespace
  {
    /** "'temperature/ENTRY' = 'TEXT'" refused for reading t. */
    template <int dim>
    void
    require_without_t(const std::string &text,
                      const std::string &constants,
                      const std::string &entry)
    {
      const Expression e(text,
                         ExpressionFunction<dim>::variable_names(),
                         parse_constants(constants),
                         "temperature/" + entry);
      require(!e.uses_variable(dim),
              "temperature: '" + entry + "' = " + quoted_expression(text) +
                " reads t, but the coefficient is evaluated once, at t = 0, "
                "and kept: it may depend on x, y" +
                std::string(dim == 3 ? ", z" : "") + " only.");
    }
  } // namespace

  template <int dim>
  HeatModel<dim>::HeatModel(const TemperatureParameters &parameters,
                            const std::string           &constants,
                            const bool                   static_class,
                            const HeatData<dim>         &derived,
                            MPI_Comm                     comm)
    : parameters(parameters)
    , static_class(static_class)
    , mpi_communicator(comm)
  {
    const auto scalar = [&](const std::string &text, const std::string &name) {
      return std::shared_ptr<Function<dim>>(
        parse_function<dim>(text, 1, constants, "temperature/" + name));
    };
    // the coefficients are evaluated once per mesh (cache_coefficients())
    require_without_t<dim>(parameters.heat_capacity,
                           constants,
                           "heat capacity");
    require_without_t<dim>(parameters.thermal_stress_coefficient,
                           constants,
                           "thermal stress coefficient");
    if (!parameters.anisotropic())
      require_without_t<dim>(parameters.conductivity[0],
                             constants,
                             "conductivity");
    heat_capacity = scalar(parameters.heat_capacity, "heat capacity");
    thermal_stress_coefficient = scalar(parameters.thermal_stress_coefficient,
                                        "thermal stress coefficient");
    if (parameters.anisotropic())
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          conductivity_tensor[i][j] =
            std::stod(parameters.conductivity[i * dim + j]);
    else
      conductivity = scalar(parameters.conductivity[0], "conductivity");
    initial_temperature =
      scalar(parameters.initial_temperature, "initial temperature");
    heat_source = scalar(parameters.heat_source, "heat source");
    prescribed_temperature =
      scalar(parameters.prescribed_temperature, "prescribed temperature");
    heat_flux = scalar(parameters.heat_flux, "heat flux");
    foundation_temperature =
      scalar(parameters.foundation_temperature, "foundation temperature");
    if (static_class)
      given_temperature =
        scalar(parameters.given_temperature, "given temperature");
    std::vector<std::string> variables =
      ExpressionFunction<dim>::variable_names();
    variables.push_back("u_nu");
    exchange_coefficient =
      std::make_unique<Expression>(parameters.exchange_coefficient,
                                   variables,
                                   parse_constants(constants),
                                   "temperature/exchange coefficient");
    if (derived.initial_temperature)
      initial_temperature = derived.initial_temperature;
    if (derived.heat_source)
      heat_source = derived.heat_source;
    if (derived.prescribed_temperature)
      prescribed_temperature = derived.prescribed_temperature;
    normal_heat_flux    = derived.heat_flux;
    contact_heat_source = derived.contact_heat_source;
    const auto name     = [](const std::string &entry,
                         const bool         is_derived) -> std::string {
      if (is_derived)
        return "the " + entry +
               " derived from 'manufactured solution/exact temperature'";
      return "'" + entry + "'";
    };
    names.initial_temperature =
      name(static_class ? "given temperature" : "initial temperature",
           derived.initial_temperature != nullptr);
    names.heat_source = name("heat source", derived.heat_source != nullptr);
    names.prescribed_temperature =
      name("prescribed temperature", derived.prescribed_temperature != nullptr);
    names.heat_flux = name("heat flux", static_cast<bool>(normal_heat_flux));
    names.contact_heat_source = name("heat source on Gamma_3", true);
  }

  template <int dim>
  FieldDefinition<dim>
  HeatModel<dim>::field(const bool simplex) const
  {
    FieldDefinition<dim> definition;
    definition.name = field_name;
    if (simplex)
      definition.element = std::make_shared<FE_SimplexP<dim>>(1);
    else
      definition.element = std::make_shared<FE_Q<dim>>(1);
    if (static_class)
      {
        given_temperature->set_time(0);
        definition.initial_value = given_temperature;
      }
    else
      definition.initial_value = initial_temperature;
    definition.layout      = FieldLayout::scalar_nodal;
    definition.saved       = true;
    definition.transferred = true;
    definition.written     = true;
    return definition;
  }

  template <int dim>
  void
  HeatModel<dim>::make_constraints(const double t)
  {
    // each made anew: a closed AffineConstraints takes no more lines
    for (AffineConstraints<double> *c : {&hanging_constraints, &constraints})
      {
        c->clear();
        c->reinit(*space->relevant);
        DoFTools::make_hanging_node_constraints(*space->dof_handler, *c);
      }
    hanging_constraints.close();
    prescribed_temperature->set_time(t);
    std::map<types::boundary_id, const Function<dim> *> prescribed;
    for (const unsigned int id : parameters.prescribed_ids)
      prescribed[id] = prescribed_temperature.get();
    VectorTools::interpolate_boundary_values(*discretization->mapping,
                                             *space->dof_handler,
                                             prescribed,
                                             constraints);
    std::string error;
    for (const auto &line : constraints.get_lines())
      if (!std::isfinite(line.inhomogeneity))
        check_datum(error,
                    line.inhomogeneity,
                    names.prescribed_temperature,
                    node_of(line.index),
                    std::optional<double>(t));
    throw_first_error(error, mpi_communicator);
    constraints.close();
  }

  template <int dim>
  Point<dim>
  HeatModel<dim>::node_of(const types::global_dof_index dof) const
  {
    for (const auto &cell : space->dof_handler->active_cell_iterators())
      if (!cell->is_artificial())
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex_dof_index(v, 0) == dof)
            return cell->vertex(v);
    return Point<dim>();
  }

  template <int dim>
  void
  HeatModel<dim>::check_nodal_values(std::string                         &error,
                                     const TrilinosWrappers::MPI::Vector &theta,
                                     const std::string                   &entry,
                                     const double t) const
  {
    for (const auto i : *space->owned)
      if (!std::isfinite(theta[i]))
        {
          check_datum(error, theta[i], entry, node_of(i), std::optional(t));
          return;
        }
  }

  template <int dim>
  void
  HeatModel<dim>::make_sparsity(
    const AffineConstraints<double>   &with,
    TrilinosWrappers::SparsityPattern &sparsity) const
  {
    sparsity.reinit(*space->owned,
                    *space->owned,
                    *space->relevant,
                    mpi_communicator);
    DoFTools::make_sparsity_pattern(*space->dof_handler,
                                    sparsity,
                                    with,
                                    /*keep_constrained_dofs=*/false,
                                    Utilities::MPI::this_mpi_process(
                                      mpi_communicator));
    sparsity.compress();
  }

  template <int dim>
  void
  HeatModel<dim>::reinit(const FieldSpace<dim>     &theta_space,
                         const MechanicalView<dim> &state)
  {
    space          = &theta_space;
    discretization = &state.discretization;
    discretization->check_boundary_ids(
      "temperature",
      {{"prescribed temperature boundary ids", parameters.prescribed_ids},
       {"heat flux boundary ids", parameters.flux_ids}});
    make_constraints(state.time);
    TrilinosWrappers::SparsityPattern sparsity;
    make_sparsity(constraints, sparsity);
    operator_matrix.reinit(sparsity);
    matrix.reinit(sparsity);
    operator_step_length = 0;
    rhs.reinit(*space->owned, mpi_communicator);
    source_load.reinit(*space->owned, mpi_communicator);
    coupling_load.reinit(*space->owned, mpi_communicator);

    // the theta dof at the vertex of each contact node
    std::map<types::global_dof_index, types::global_dof_index> theta_of;
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          const typename DoFHandler<dim>::active_cell_iterator theta_cell(
            &cell->get_triangulation(),
            cell->level(),
            cell->index(),
            space->dof_handler);
          for (const unsigned int v : cell->vertex_indices())
            theta_of[cell->vertex_dof_index(v, 0)] =
              theta_cell->vertex_dof_index(v, 0);
        }
    node_dofs.clear();
    for (const ContactNode<dim> &node : state.contact_nodes)
      node_dofs.push_back(theta_of.at(node.dofs[0]));
    cache_coefficients();
    if (!static_class)
      assemble_energy_matrices();
  }

  template <int dim>
  void
  HeatModel<dim>::cache_coefficients()
  {
    const Quadrature<dim> quadrature = discretization->cell_quadrature(2);
    const unsigned int    n_q        = quadrature.size();
    const unsigned int    n_cells =
      space->dof_handler->get_triangulation().n_active_cells();
    FEValues<dim> fe(*discretization->mapping,
                     space->dof_handler->get_fe(),
                     quadrature,
                     update_values | update_quadrature_points |
                       update_JxW_values);
    coefficients.c_theta.assign(n_cells * n_q, 0.);
    coefficients.c_e.assign(n_cells * n_q, 0.);
    coefficients.kappa.assign(n_cells * n_q, 0.);
    // summed over the owned cells' dofs by compress(), as a load is
    TrilinosWrappers::MPI::Vector weights(*space->owned, mpi_communicator);
    std::vector<double>           c_theta(n_q), c_e(n_q), kappa(n_q);
    const unsigned int            n = fe.dofs_per_cell;
    Vector<double>                local(n);
    std::vector<types::global_dof_index> dofs(n);
    std::string                          error;
    for (const auto &cell : space->dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe.reinit(cell);
          const std::vector<Point<dim>> &points = fe.get_quadrature_points();
          heat_capacity->value_list(points, c_theta);
          thermal_stress_coefficient->value_list(points, c_e);
          if (conductivity)
            conductivity->value_list(points, kappa);
          const std::size_t first = cell->active_cell_index() * n_q;
          local                   = 0;
          for (const unsigned int q : fe.quadrature_point_indices())
            {
              const std::optional<double> no_time;
              check_datum(error,
                          c_theta[q],
                          "'heat capacity'",
                          points[q],
                          no_time,
                          Sign::positive);
              check_datum(error,
                          c_e[q],
                          "'thermal stress coefficient'",
                          points[q],
                          no_time,
                          Sign::non_negative);
              if (conductivity)
                check_datum(error,
                            kappa[q],
                            "'conductivity'",
                            points[q],
                            no_time,
                            Sign::positive);
              coefficients.c_theta[first + q] = c_theta[q];
              coefficients.c_e[first + q]     = c_e[q];
              coefficients.kappa[first + q]   = kappa[q];
              for (unsigned int i = 0; i < n; ++i)
                local(i) += c_theta[q] * fe.shape_value(i, q) * fe.JxW(q);
            }
          // every dof its share, hanging ones included, so that
          // sum_j weight_j theta_j = int c_theta theta for a theta that
          // meets the constraints
          cell->get_dof_indices(dofs);
          weights.add(dofs, local);
        }
    weights.compress(VectorOperation::add);
    capacity_weights.reinit(*space->owned, mpi_communicator);
    capacity_weights = weights;
    throw_first_error(error, mpi_communicator);
  }

  template <int dim>
  void
  HeatModel<dim>::add_thermal_stress(const double                   t,
                                     const MechanicalView<dim>     &state,
                                     TrilinosWrappers::MPI::Vector &theta,
                                     TrilinosWrappers::MPI::Vector &load)
  {
    if (static_class)
      {
        given_temperature->set_time(t);
        VectorTools::interpolate(*discretization->mapping,
                                 *space->dof_handler,
                                 *given_temperature,
                                 theta);
        space->constraints->distribute(theta);
        heat.heat_content = heat_content(theta);
      }
    // the given theta at t; in the velocity classes theta_{n-1}, finite
    // after every heat step, so that a value that is not is theta_0's
    std::string error;
    check_nodal_values(error,
                       theta,
                       names.initial_temperature,
                       static_class ? t : 0.);
    throw_first_error(error, mpi_communicator);
    const TrilinosWrappers::MPI::Vector theta_g =
      ghosted(theta, *space->owned, *space->relevant, mpi_communicator);
    const Quadrature<dim> quadrature = discretization->cell_quadrature(2);
    FEValues<dim>         fe_u(*discretization->mapping,
                       *discretization->fe,
                       quadrature,
                       update_gradients | update_quadrature_points |
                         update_JxW_values);
    FEValues<dim>         fe_theta(*discretization->mapping,
                           space->dof_handler->get_fe(),
                           quadrature,
                           update_values);
    const FEValuesExtractors::Vector     v(0);
    const unsigned int                   n = fe_u.dofs_per_cell;
    Vector<double>                       local(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<double>                  theta_q(quadrature.size());
    stress_load.reinit(state.locally_owned_dofs, mpi_communicator);
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_u.reinit(cell);
          fe_theta.reinit(typename DoFHandler<dim>::active_cell_iterator(
            &cell->get_triangulation(),
            cell->level(),
            cell->index(),
            space->dof_handler));
          fe_theta.get_function_values(theta_g, theta_q);
          const double *c_e =
            &coefficients.c_e[cell->active_cell_index() * quadrature.size()];
          local = 0;
          for (const unsigned int q : fe_u.quadrature_point_indices())
            for (unsigned int i = 0; i < n; ++i)
              local(i) +=
                c_e[q] * theta_q[q] * fe_u[v].divergence(i, q) * fe_u.JxW(q);
          cell->get_dof_indices(dofs);
          state.base_constraints.distribute_local_to_global(local,
                                                            dofs,
                                                            stress_load);
        }
    stress_load.compress(VectorOperation::add);
    load += stress_load;
  }

  template <int dim>
  double
  HeatModel<dim>::heat_content(const TrilinosWrappers::MPI::Vector &theta) const
  {
    return capacity_weights * theta;
  }

  template <int dim>
  std::vector<NodeHeat>
  HeatModel<dim>::contact_heat(const double                         t,
                               const MechanicalView<dim>           &state,
                               const TrilinosWrappers::MPI::Vector &theta) const
  {
    const TrilinosWrappers::MPI::Vector w = ghosted(state.velocity,
                                                    state.locally_owned_dofs,
                                                    state.locally_relevant_dofs,
                                                    mpi_communicator);
    const TrilinosWrappers::MPI::Vector u = ghosted(state.displacement,
                                                    state.locally_owned_dofs,
                                                    state.locally_relevant_dofs,
                                                    mpi_communicator);
    const TrilinosWrappers::MPI::Vector traction =
      ghosted(state.contact_traction,
              state.locally_owned_dofs,
              state.locally_relevant_dofs,
              mpi_communicator);
    const TrilinosWrappers::MPI::Vector theta_g =
      ghosted(theta, *space->owned, *space->relevant, mpi_communicator);
    foundation_temperature->set_time(t);
    std::vector<NodeHeat> nodes(state.contact_nodes.size());
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const ContactNode<dim> &node = state.contact_nodes[i];
        if (!space->relevant->is_element(node_dofs[i]))
          continue;
        Tensor<1, dim> w_i, u_i, t_i;
        for (unsigned int c = 0; c < dim; ++c)
          {
            w_i[c] = w[node.dofs[c]];
            u_i[c] = u[node.dofs[c]];
            t_i[c] = traction[node.dofs[c]];
          }
        std::vector<double> values(node.position.begin_raw(),
                                   node.position.end_raw());
        values.push_back(t);
        values.push_back(u_i * node.normal);
        const Tensor<1, dim> t_tau = t_i - (t_i * node.normal) * node.normal;
        const Tensor<1, dim> w_tau = w_i - (w_i * node.normal) * node.normal;
        nodes[i].booked            = !constraints.is_constrained(node_dofs[i]);
        nodes[i].temperature       = theta_g[node_dofs[i]];
        nodes[i].exchange_coefficient = exchange_coefficient->evaluate(values);
        nodes[i].foundation_temperature =
          foundation_temperature->value(node.position);
        nodes[i].frictional_power =
          parameters.frictional_heat_fraction * std::abs(t_tau * w_tau);
      }
    return nodes;
  }

  template <int dim>
  std::vector<std::pair<std::string, Vector<float>>>
  HeatModel<dim>::cell_output(const TrilinosWrappers::MPI::Vector &theta) const
  {
    const TrilinosWrappers::MPI::Vector theta_g =
      ghosted(theta, *space->owned, *space->relevant, mpi_communicator);
    const unsigned int n_cells =
      space->dof_handler->get_triangulation().n_active_cells();
    std::vector<std::pair<std::string, Vector<float>>> fields;
    fields.emplace_back("thermal_stress", Vector<float>(n_cells));
    const char *xyz[] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      fields.emplace_back(std::string("heat_flux_") + xyz[d],
                          Vector<float>(n_cells));
    const Quadrature<dim> quadrature = discretization->cell_quadrature(2);
    FEValues<dim>         fe(*discretization->mapping,
                     space->dof_handler->get_fe(),
                     quadrature,
                     update_values | update_gradients |
                       update_quadrature_points | update_JxW_values);
    std::vector<double>   theta_q(quadrature.size()), c_e(quadrature.size()),
      kappa(quadrature.size());
    std::vector<Tensor<1, dim>> grad_q(quadrature.size());
    for (const auto &cell : space->dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe.reinit(cell);
          fe.get_function_values(theta_g, theta_q);
          fe.get_function_gradients(theta_g, grad_q);
          thermal_stress_coefficient->value_list(fe.get_quadrature_points(),
                                                 c_e);
          if (conductivity)
            conductivity->value_list(fe.get_quadrature_points(), kappa);
          double         volume = 0, stress = 0;
          Tensor<1, dim> flux;
          for (const unsigned int q : fe.quadrature_point_indices())
            {
              const Tensor<2, dim> K = conductivity_at(kappa[q]);
              stress -= c_e[q] * theta_q[q] * fe.JxW(q);
              flux -= K * grad_q[q] * fe.JxW(q);
              volume += fe.JxW(q);
            }
          const unsigned int index = cell->active_cell_index();
          fields[0].second[index]  = stress / volume;
          for (unsigned int d = 0; d < dim; ++d)
            fields[1 + d].second[index] = flux[d] / volume;
        }
    return fields;
  }

  template <int dim>
  void
  HeatModel<dim>::start(const TrilinosWrappers::MPI::Vector &theta)
  {
    std::string error;
    check_nodal_values(error, theta, names.initial_temperature, 0.);
    throw_first_error(error, mpi_communicator);
    heat                      = HeatBalance();
    heat.initial_heat_content = heat_content(theta);
    heat.heat_content         = heat.initial_heat_content;
  }

  template <int dim>
  HeatStepEnergy
  HeatModel<dim>::heat_step(const double                   t,
                            const double                   k,
                            const MechanicalView<dim>     &state,
                            LinearSolver                  &solver,
                            TrilinosWrappers::MPI::Vector &theta)
  {
    make_constraints(t);
    heat_source->set_time(t);
    heat_flux->set_time(t);
    foundation_temperature->set_time(t);
    const IndexSet                     &owned    = state.locally_owned_dofs;
    const IndexSet                     &relevant = state.locally_relevant_dofs;
    const TrilinosWrappers::MPI::Vector theta_old =
      ghosted(theta, *space->owned, *space->relevant, mpi_communicator);
    const TrilinosWrappers::MPI::Vector w =
      ghosted(state.velocity, owned, relevant, mpi_communicator);

    // the operator c_theta/k M + K and its AMG: once per mesh and step
    // length (the contact's k_e term is added to a copy each step)
    const bool new_operator = (k != operator_step_length);
    if (new_operator)
      operator_matrix = 0;
    rhs                           = 0;
    source_load                   = 0;
    coupling_load                 = 0;
    const FiniteElement<dim>  &fe = space->dof_handler->get_fe();
    HeatStepValues<dim>        values(*discretization, fe);
    FEValues<dim>             &fe_theta = values.theta;
    FEFaceValues<dim>         &fe_face  = values.face;
    const std::vector<double> &div_w    = values.div_w;
    const unsigned int         n        = fe.n_dofs_per_cell();
    FullMatrix<double>         local_matrix(n, n);
    Vector<double>             local_rhs(n);
    // the parts of the right-hand side the energy identity tests alone
    Vector<double>                       local_source(n), local_coupling(n);
    std::vector<types::global_dof_index> dofs(n);
    const unsigned int                   n_q = values.quadrature.size();
    std::vector<double>                  theta_q(n_q), q_src(n_q),
      q_n(values.face_quadrature.size());
    std::string error;
    for (const auto &cell : space->dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          values.reinit(cell, state.dof_handler, w);
          fe_theta.get_function_values(theta_old, theta_q);
          const std::vector<Point<dim>> &points =
            fe_theta.get_quadrature_points();
          const std::size_t first   = cell->active_cell_index() * n_q;
          const double     *c_theta = &coefficients.c_theta[first];
          const double     *c_e     = &coefficients.c_e[first];
          const double     *kappa   = &coefficients.kappa[first];
          heat_source->value_list(points, q_src);
          cell->get_dof_indices(dofs);
          // the cell matrix: for the operator, or for the inhomogeneity of
          // theta_D on this cell
          bool with_matrix = new_operator;
          for (const auto dof : dofs)
            with_matrix =
              with_matrix || constraints.is_inhomogeneously_constrained(dof);
          local_matrix   = 0;
          local_rhs      = 0;
          local_source   = 0;
          local_coupling = 0;
          for (const unsigned int q : fe_theta.quadrature_point_indices())
            {
              check_datum(error,
                          q_src[q],
                          names.heat_source,
                          points[q],
                          std::optional(t));
              const Tensor<2, dim> K   = conductivity_at(kappa[q]);
              const double         JxW = fe_theta.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const double phi_i = fe_theta.shape_value(i, q);
                  if (with_matrix)
                    {
                      const Tensor<1, dim> Kgrad_i =
                        K * fe_theta.shape_grad(i, q);
                      for (unsigned int j = 0; j < n; ++j)
                        local_matrix(i, j) +=
                          (c_theta[q] / k * phi_i * fe_theta.shape_value(j, q) +
                           Kgrad_i * fe_theta.shape_grad(j, q)) *
                          JxW;
                    }
                  local_rhs(i) += (c_theta[q] / k * theta_q[q] -
                                   c_e[q] * div_w[q] + q_src[q]) *
                                  phi_i * JxW;
                  local_source(i) += q_src[q] * phi_i * JxW;
                  local_coupling(i) -= c_e[q] * div_w[q] * phi_i * JxW;
                }
            }
          for (const unsigned int f : cell->face_indices())
            if (on_flux_boundary(cell, f))
              {
                fe_face.reinit(cell, f);
                boundary_heat_flux(fe_face, t, q_n);
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  check_datum(error,
                              q_n[q],
                              names.heat_flux,
                              fe_face.quadrature_point(q),
                              std::optional(t));
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const double flux =
                        q_n[q] * fe_face.shape_value(i, q) * fe_face.JxW(q);
                      local_rhs(i) += flux;
                      local_source(i) += flux;
                    }
              }
          if (new_operator)
            constraints.distribute_local_to_global(local_matrix,
                                                   dofs,
                                                   operator_matrix);
          constraints.distribute_local_to_global(local_rhs,
                                                 dofs,
                                                 rhs,
                                                 local_matrix);
          hanging_constraints.distribute_local_to_global(local_source,
                                                         dofs,
                                                         source_load);
          hanging_constraints.distribute_local_to_global(local_coupling,
                                                         dofs,
                                                         coupling_load);
        }
    if (new_operator)
      {
        operator_matrix.compress(VectorOperation::add);
        TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
        amg_data.elliptic              = true;
        amg_data.higher_order_elements = false;
        amg.initialize(operator_matrix, amg_data);
        operator_step_length = k;
      }
    matrix.copy_from(operator_matrix);

    // Gamma_3, nodal quadrature: k_e theta_n on the left, k_e theta_F and
    // the frictional heat on the right (not where theta is prescribed)
    const std::vector<NodeHeat> nodes = contact_heat(t, state, theta);
    for (unsigned int i = 0; i < nodes.size(); ++i)
      {
        const ContactNode<dim> &node = state.contact_nodes[i];
        const auto              d    = node_dofs[i];
        if (!space->owned->is_element(d) || !nodes[i].booked)
          continue;
        check_datum(error,
                    nodes[i].exchange_coefficient,
                    "'exchange coefficient'",
                    node.position,
                    std::optional(t),
                    Sign::non_negative);
        check_datum(error,
                    nodes[i].foundation_temperature,
                    "'foundation temperature'",
                    node.position,
                    std::optional(t));
        matrix.add(d, d, node.mass * nodes[i].exchange_coefficient);
        rhs[d] += node.mass * (nodes[i].exchange_coefficient *
                                 nodes[i].foundation_temperature +
                               nodes[i].frictional_power);
        if (contact_heat_source)
          {
            const double g_3 =
              contact_heat_source(node.position, node.normal, t);
            check_datum(error,
                        g_3,
                        names.contact_heat_source,
                        node.position,
                        std::optional(t));
            rhs[d] += node.mass * g_3;
          }
      }
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    source_load.compress(VectorOperation::add);
    coupling_load.compress(VectorOperation::add);
    throw_first_error(error, mpi_communicator);
    // the data are finite: what is not comes from the mechanical step's
    // w_n or traction (or a solver), and fails the step
    if (!all_finite(rhs, mpi_communicator))
      throw SolverFailure("the heat step's right-hand side is not a finite "
                          "number (the data are, so w_n or the contact "
                          "traction of the mechanical step is not).");

    const TrilinosWrappers::MPI::Vector theta_before(theta);
    heat.linear_iterations = solver.solve(matrix, amg, theta, rhs);
    constraints.distribute(theta);
    if (!all_finite(theta, mpi_communicator))
      throw SolverFailure("the heat step's theta_n is not a finite number.");
    heat.heat_content = heat_content(theta);
    return step_energy(t, k, state, theta_before, theta, nodes);
  }

  template <int dim>
  void
  HeatModel<dim>::boundary_heat_flux(const FEFaceValues<dim> &fe_face,
                                     const double             t,
                                     std::vector<double>     &q_n) const
  {
    heat_flux->value_list(fe_face.get_quadrature_points(), q_n);
    if (normal_heat_flux)
      for (const unsigned int q : fe_face.quadrature_point_indices())
        q_n[q] = normal_heat_flux(fe_face.quadrature_point(q),
                                  fe_face.normal_vector(q),
                                  t);
  }

  template class HeatModel<2>;
  template class HeatModel<3>;
} // namespace hemicontact
