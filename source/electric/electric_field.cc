#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/coupling/field_support.h>
#include <hemicontact/electric/electric_field.h>
#include <hemicontact/electric/piezoelectric_tensor.h>
#include <hemicontact/expressions/constants.h>
#include <hemicontact/expressions/expression_function.h>
#include <hemicontact/model/problem_data.h>

#include <cmath>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    /** Into @p error (if still empty): @p entry is @p value at @p p and
     *  time @p t, not a finite number (or negative where @p non_negative). */
    template <int dim>
    void
    check_datum(std::string       &error,
                const double       value,
                const std::string &entry,
                const Point<dim>  &p,
                const double       t,
                const bool         non_negative = false)
    {
      if ((std::isfinite(value) && (!non_negative || value >= 0)) ||
          !error.empty())
        return;
      std::ostringstream message;
      message << "piezoelectricity: '" << entry << "' is " << value << " at (";
      for (unsigned int d = 0; d < dim; ++d)
        message << (d ? ", " : "") << p[d];
      message << "), t = " << t << "; it must be a finite number"
              << (non_negative ? " >= 0" : "") << ".";
      error = message.str();
    }

    /** The displacement's cell of @p cell (same mesh). */
    template <int dim>
    typename DoFHandler<dim>::active_cell_iterator
    same_cell(const typename DoFHandler<dim>::active_cell_iterator &cell,
              const DoFHandler<dim>                                &other)
    {
      return typename DoFHandler<dim>::active_cell_iterator(
        &cell->get_triangulation(), cell->level(), cell->index(), &other);
    }
  } // namespace

  template <int dim>
  ElectricField<dim>::ElectricField(const PiezoelectricParameters &parameters,
                                    const std::string             &constants,
                                    const bool                     static_class,
                                    const bool                     left_point,
                                    MPI_Comm                       comm)
    : parameters(parameters)
    , static_class(static_class)
    , left_point(left_point)
    , mpi_communicator(comm)
    , piezo(piezoelectric_tensor<dim>(parameters.piezoelectric_constants))
  {
    if (parameters.permittivity.size() == 1)
      beta = parameters.permittivity[0] * unit_symmetric_tensor<dim>();
    else
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          beta[i][j] = parameters.permittivity[i * dim + j];
    const auto scalar = [&](const std::string &text, const std::string &name) {
      return std::shared_ptr<Function<dim>>(
        parse_function<dim>(text, 1, constants, "piezoelectricity/" + name));
    };
    volume_charge = scalar(parameters.volume_charge, "volume charge");
    electrode_potential =
      scalar(parameters.electrode_potential, "electrode potential");
    surface_charge = scalar(parameters.surface_charge, "surface charge");
    foundation_potential =
      scalar(parameters.foundation_potential, "foundation potential");
    std::vector<std::string> variables =
      ExpressionFunction<dim>::variable_names();
    variables.push_back("u_nu");
    conductance = std::make_unique<Expression>(parameters.conductance,
                                               variables,
                                               parse_constants(constants),
                                               "piezoelectricity/conductance");
  }

  template <int dim>
  const std::vector<EnergyTermSpec> &
  ElectricField<dim>::terms()
  {
    using R = EnergyRole;
    // (grad phi_n, E eps(u held)); -1/2 (beta grad phi_n, grad phi_n); the
    // work of the charges, the electrodes and the Gamma_3 conduction; the
    // electric stress's work -sum k (grad phi_n, E eps(w_n)), which is in
    // external_work (converted) and cancels there (coupling)
    static const std::vector<EnergyTermSpec> list{
      {"electric_cross", "electric_cross_energy", R::stored},
      {"electric_enthalpy", "electric_enthalpy", R::stored},
      {"electric_supply", "electric_supply", R::supplied},
      {"electric_coupling_work", "", R::coupling},
      {"electric_stress_work", "electric_stress_work", R::converted}};
    return list;
  }

  template <int dim>
  FieldDefinition<dim>
  ElectricField<dim>::definition(const bool simplex) const
  {
    std::shared_ptr<const FiniteElement<dim>> fe;
    if (simplex)
      fe = std::make_shared<FE_SimplexP<dim>>(1);
    else
      fe = std::make_shared<FE_Q<dim>>(1);
    return {field_name, fe, nullptr, FieldLayout::scalar_nodal};
  }

  template <int dim>
  std::string
  ElectricField<dim>::subsection() const
  {
    return "piezoelectricity";
  }

  template <int dim>
  std::string
  ElectricField<dim>::symbol() const
  {
    return "phi_n";
  }

  template <int dim>
  typename CoupledField<dim>::Order
  ElectricField<dim>::order() const
  {
    // phi_n from u_n: known before the step with the left-point rule
    return CoupledField<dim>::Order::before_mechanical_step;
  }

  template <int dim>
  FieldCoupling
  ElectricField<dim>::coupling() const
  {
    // the implicit rule and the static class solve for u_n: alternate to
    // the monolithic answer
    return {static_class || !left_point,
            parameters.coupling_tolerance,
            parameters.coupling_iterations};
  }

  template <int dim>
  std::string
  ElectricField<dim>::step_name() const
  {
    return "electric step";
  }

  template <int dim>
  void
  ElectricField<dim>::make_constraints(const double t)
  {
    for (AffineConstraints<double> *c : {&hanging_constraints, &constraints})
      {
        c->clear();
        c->reinit(*space->relevant);
        DoFTools::make_hanging_node_constraints(*space->dof_handler, *c);
      }
    hanging_constraints.close();
    electrode_potential->set_time(t);
    std::map<types::boundary_id, const Function<dim> *> electrodes;
    for (const unsigned int id : parameters.electrode_ids)
      electrodes[id] = electrode_potential.get();
    VectorTools::interpolate_boundary_values(*discretization->mapping,
                                             *space->dof_handler,
                                             electrodes,
                                             constraints);
    std::string error;
    for (const auto &line : constraints.get_lines())
      if (!std::isfinite(line.inhomogeneity))
        check_datum(
          error, line.inhomogeneity, "electrode potential", Point<dim>(), t);
    throw_first_error(error, mpi_communicator);
    constraints.close();
  }

  template <int dim>
  void
  ElectricField<dim>::reinit(const FieldSpace<dim>     &field_space,
                             const MechanicalView<dim> &view)
  {
    space          = &field_space;
    discretization = &view.discretization;
    discretization->check_boundary_ids(
      "piezoelectricity",
      {{"electrode boundary ids", parameters.electrode_ids},
       {"surface charge boundary ids", parameters.surface_charge_ids}});
    make_constraints(view.time);
    TrilinosWrappers::SparsityPattern sparsity(*space->owned,
                                               *space->owned,
                                               *space->relevant,
                                               mpi_communicator);
    DoFTools::make_sparsity_pattern(*space->dof_handler,
                                    sparsity,
                                    constraints,
                                    false,
                                    Utilities::MPI::this_mpi_process(
                                      mpi_communicator));
    sparsity.compress();
    matrix.reinit(sparsity);
    rhs.reinit(*space->owned, mpi_communicator);
    // the phi dof at the vertex of each contact node
    std::map<types::global_dof_index, types::global_dof_index> phi_of;
    for (const auto &cell : view.dof_handler.active_cell_iterators())
      if (!cell->is_artificial())
        {
          const auto phi_cell = same_cell<dim>(cell, *space->dof_handler);
          for (const unsigned int v : cell->vertex_indices())
            phi_of[cell->vertex_dof_index(v, 0)] =
              phi_cell->vertex_dof_index(v, 0);
        }
    node_dofs.clear();
    for (const ContactNode<dim> &node : view.contact_nodes)
      node_dofs.push_back(phi_of.at(node.dofs[0]));
    // the solves kept for the energy were on the old mesh
    solves.clear();
  }

  template <int dim>
  double
  ElectricField<dim>::conductance_at(const MechanicalView<dim>           &view,
                                     const unsigned int                   i,
                                     const TrilinosWrappers::MPI::Vector &u,
                                     const double t) const
  {
    const ContactNode<dim> &node = view.contact_nodes[i];
    double                  u_nu = 0;
    for (unsigned int c = 0; c < dim; ++c)
      u_nu += u[node.dofs[c]] * node.normal[c];
    std::vector<double> values(node.position.begin_raw(),
                               node.position.end_raw());
    values.push_back(t);
    values.push_back(u_nu);
    return conductance->evaluate(values);
  }

  template <int dim>
  void
  ElectricField<dim>::solve(const double                         t,
                            const MechanicalView<dim>           &view,
                            const TrilinosWrappers::MPI::Vector &u_owned,
                            LinearSolver                        &solver,
                            TrilinosWrappers::MPI::Vector       &value)
  {
    make_constraints(t);
    volume_charge->set_time(t);
    surface_charge->set_time(t);
    foundation_potential->set_time(t);
    const TrilinosWrappers::MPI::Vector u = ghosted(u_owned,
                                                    view.locally_owned_dofs,
                                                    view.locally_relevant_dofs,
                                                    mpi_communicator);
    const Quadrature<dim>     quadrature  = discretization->cell_quadrature(2);
    const Quadrature<dim - 1> face_quadrature =
      discretization->face_quadrature(2);
    const FiniteElement<dim>            &fe = space->dof_handler->get_fe();
    FEValues<dim>                        fe_phi(*discretization->mapping,
                         fe,
                         quadrature,
                         update_values | update_gradients |
                           update_quadrature_points | update_JxW_values);
    FEValues<dim>                        fe_u(*discretization->mapping,
                       *discretization->fe,
                       quadrature,
                       update_gradients);
    FEFaceValues<dim>                    fe_face(*discretization->mapping,
                              fe,
                              face_quadrature,
                              update_values | update_quadrature_points |
                                update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   local_matrix(n, n);
    Vector<double>                       local_rhs(n), local_data(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<SymmetricTensor<2, dim>> eps(quadrature.size());
    std::vector<double> q0(quadrature.size()), qb(face_quadrature.size());
    const FEValuesExtractors::Vector displacement(0);
    // data: (q_0, zeta) - (q_b, zeta)_{Gamma_b} + sum c_i phi_F,i zeta_i,
    // condensed by the hanging nodes only (the energy tests it with
    // phi_n - phi_{n-1})
    Solve record;
    record.data.reinit(*space->owned, mpi_communicator);
    record.conductance.reinit(*space->owned, mpi_communicator);
    matrix = 0;
    rhs    = 0;
    std::string error;
    const auto  on_charge_boundary = [&](const auto &cell, unsigned int f) {
      if (!cell->face(f)->at_boundary())
        return false;
      for (const unsigned int id : parameters.surface_charge_ids)
        if (cell->face(f)->boundary_id() == id)
          return true;
      return false;
    };
    for (const auto &cell : space->dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_phi.reinit(cell);
          fe_u.reinit(same_cell<dim>(cell, view.dof_handler));
          fe_u[displacement].get_function_symmetric_gradients(u, eps);
          volume_charge->value_list(fe_phi.get_quadrature_points(), q0);
          local_matrix = 0;
          local_rhs    = 0;
          local_data   = 0;
          for (const unsigned int q : fe_phi.quadrature_point_indices())
            {
              check_datum(
                error, q0[q], "volume charge", fe_phi.quadrature_point(q), t);
              const Tensor<1, dim> polarization =
                piezoelectric_polarization(piezo, eps[q]);
              const double JxW = fe_phi.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                {
                  const Tensor<1, dim> grad_i      = fe_phi.shape_grad(i, q);
                  const Tensor<1, dim> beta_grad_i = beta * grad_i;
                  for (unsigned int j = 0; j < n; ++j)
                    local_matrix(i, j) +=
                      beta_grad_i * fe_phi.shape_grad(j, q) * JxW;
                  local_rhs(i) +=
                    (polarization * grad_i + q0[q] * fe_phi.shape_value(i, q)) *
                    JxW;
                  local_data(i) += q0[q] * fe_phi.shape_value(i, q) * JxW;
                }
            }
          for (const unsigned int f : cell->face_indices())
            if (on_charge_boundary(cell, f))
              {
                fe_face.reinit(cell, f);
                surface_charge->value_list(fe_face.get_quadrature_points(), qb);
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  {
                    check_datum(error,
                                qb[q],
                                "surface charge",
                                fe_face.quadrature_point(q),
                                t);
                    for (unsigned int i = 0; i < n; ++i)
                      {
                        const double charge =
                          qb[q] * fe_face.shape_value(i, q) * fe_face.JxW(q);
                        local_rhs(i) -= charge;
                        local_data(i) -= charge;
                      }
                  }
              }
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(
            local_matrix, local_rhs, dofs, matrix, rhs);
          hanging_constraints.distribute_local_to_global(local_data,
                                                         dofs,
                                                         record.data);
        }
    // Gamma_3, nodal quadrature where phi is free: c_i = m_i p_e,i
    for (unsigned int i = 0; i < view.contact_nodes.size(); ++i)
      {
        const ContactNode<dim> &node = view.contact_nodes[i];
        const auto              d    = node_dofs[i];
        if (!space->owned->is_element(d) || constraints.is_constrained(d))
          continue;
        const double p_e = conductance_at(view, i, u, t);
        check_datum(error, p_e, "conductance", node.position, t, true);
        const double phi_f = foundation_potential->value(node.position);
        check_datum(error, phi_f, "foundation potential", node.position, t);
        if (!error.empty())
          continue;
        matrix.add(d, d, node.mass * p_e);
        rhs[d] += node.mass * p_e * phi_f;
        record.data[d] += node.mass * p_e * phi_f;
        record.conductance[d] = node.mass * p_e;
      }
    throw_first_error(error, mpi_communicator);
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    record.data.compress(VectorOperation::add);
    record.conductance.compress(VectorOperation::insert);
    TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
    amg_data.elliptic              = true;
    amg_data.higher_order_elements = false;
    amg.initialize(matrix, amg_data);
    iterations = solver.solve(matrix, amg, value, rhs);
    constraints.distribute(value);
    if (!std::isfinite(value.l2_norm()))
      throw SolverFailure("the electric step's phi_n is not a finite number.");

    // the electrodes' charge: the residual of their rows (doc/theory.md
    // 14.3), added to the data functional
    const TrilinosWrappers::MPI::Vector phi =
      ghosted(value, *space->owned, *space->relevant, mpi_communicator);
    TrilinosWrappers::MPI::Vector residual(*space->owned, mpi_communicator);
    std::vector<Tensor<1, dim>>   grad_phi(quadrature.size());
    for (const auto &cell : space->dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_phi.reinit(cell);
          fe_u.reinit(same_cell<dim>(cell, view.dof_handler));
          fe_u[displacement].get_function_symmetric_gradients(u, eps);
          fe_phi.get_function_gradients(phi, grad_phi);
          volume_charge->value_list(fe_phi.get_quadrature_points(), q0);
          local_rhs = 0;
          for (const unsigned int q : fe_phi.quadrature_point_indices())
            {
              const Tensor<1, dim> flux =
                beta * grad_phi[q] - piezoelectric_polarization(piezo, eps[q]);
              for (unsigned int i = 0; i < n; ++i)
                local_rhs(i) += (flux * fe_phi.shape_grad(i, q) -
                                 q0[q] * fe_phi.shape_value(i, q)) *
                                fe_phi.JxW(q);
            }
          for (const unsigned int f : cell->face_indices())
            if (on_charge_boundary(cell, f))
              {
                fe_face.reinit(cell, f);
                surface_charge->value_list(fe_face.get_quadrature_points(), qb);
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  for (unsigned int i = 0; i < n; ++i)
                    local_rhs(i) +=
                      qb[q] * fe_face.shape_value(i, q) * fe_face.JxW(q);
              }
          cell->get_dof_indices(dofs);
          hanging_constraints.distribute_local_to_global(local_rhs,
                                                         dofs,
                                                         residual);
        }
    residual.compress(VectorOperation::add);
    for (const auto i : *space->owned)
      if (constraints.is_constrained(i) &&
          !hanging_constraints.is_constrained(i))
        record.data[i] += residual[i];
    record.data.compress(VectorOperation::insert);
    record.phi = value;
    solves[t]  = record;
    // the last few solves: the energy reads the step's and the one before
    while (solves.size() > 3)
      solves.erase(solves.begin());
  }

  template <int dim>
  void
  ElectricField<dim>::start(const MechanicalView<dim>     &view,
                            LinearSolver                  &solver,
                            TrilinosWrappers::MPI::Vector &value,
                            const bool                     resumed)
  {
    // phi_0 from u_0; a resume keeps the checkpoint's phi and its solve
    // is made again for the energy of the next step
    if (!resumed)
      solve(view.time, view, view.displacement, solver, value);
    else
      {
        TrilinosWrappers::MPI::Vector again(value);
        solve(view.time, view, view.displacement, solver, again);
        solves[view.time].phi = value;
      }
  }

  template <int dim>
  void
  ElectricField<dim>::add_mechanical_load(const double,
                                          const MechanicalView<dim>     &view,
                                          TrilinosWrappers::MPI::Vector &value,
                                          TrilinosWrappers::MPI::Vector &load)
  {
    const TrilinosWrappers::MPI::Vector phi =
      ghosted(value, *space->owned, *space->relevant, mpi_communicator);
    const Quadrature<dim> quadrature = discretization->cell_quadrature(2);
    FEValues<dim>         fe_u(*discretization->mapping,
                       *discretization->fe,
                       quadrature,
                       update_gradients | update_JxW_values);
    FEValues<dim>         fe_phi(*discretization->mapping,
                         space->dof_handler->get_fe(),
                         quadrature,
                         update_gradients);
    const FEValuesExtractors::Vector     v(0);
    const unsigned int                   n = fe_u.dofs_per_cell;
    Vector<double>                       local(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<Tensor<1, dim>>          grad_phi(quadrature.size());
    stress_load.reinit(view.locally_owned_dofs, mpi_communicator);
    for (const auto &cell : view.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_u.reinit(cell);
          fe_phi.reinit(same_cell<dim>(cell, *space->dof_handler));
          fe_phi.get_function_gradients(phi, grad_phi);
          local = 0;
          for (const unsigned int q : fe_u.quadrature_point_indices())
            for (unsigned int i = 0; i < n; ++i)
              local(i) -=
                grad_phi[q] *
                piezoelectric_polarization(piezo,
                                           fe_u[v].symmetric_gradient(i, q)) *
                fe_u.JxW(q);
          cell->get_dof_indices(dofs);
          view.base_constraints.distribute_local_to_global(local,
                                                           dofs,
                                                           stress_load);
        }
    stress_load.compress(VectorOperation::add);
    load += stress_load;
  }

  template <int dim>
  FieldStepEnergy
  ElectricField<dim>::step(const double                   t,
                           const double                   k,
                           const MechanicalView<dim>     &view,
                           LinearSolver                  &solver,
                           TrilinosWrappers::MPI::Vector &value)
  {
    (void)k;
    // u_n: with the left-point rule the displacement before the step, else
    // the mechanical step's last iterate
    solve(t, view, view.displacement, solver, value);
    return {};
  }

  template <int dim>
  std::pair<double, double>
  ElectricField<dim>::cross_and_field_energy(
    const MechanicalView<dim>           &view,
    const TrilinosWrappers::MPI::Vector &phi_owned,
    const TrilinosWrappers::MPI::Vector &u_owned) const
  {
    const TrilinosWrappers::MPI::Vector phi =
      ghosted(phi_owned, *space->owned, *space->relevant, mpi_communicator);
    const TrilinosWrappers::MPI::Vector u  = ghosted(u_owned,
                                                    view.locally_owned_dofs,
                                                    view.locally_relevant_dofs,
                                                    mpi_communicator);
    const Quadrature<dim>       quadrature = discretization->cell_quadrature(2);
    FEValues<dim>               fe_phi(*discretization->mapping,
                         space->dof_handler->get_fe(),
                         quadrature,
                         update_gradients | update_JxW_values);
    FEValues<dim>               fe_u(*discretization->mapping,
                       *discretization->fe,
                       quadrature,
                       update_gradients);
    std::vector<Tensor<1, dim>> grad_phi(quadrature.size());
    std::vector<SymmetricTensor<2, dim>> eps(quadrature.size());
    const FEValuesExtractors::Vector     displacement(0);
    double                               cross = 0, field = 0;
    for (const auto &cell : space->dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_phi.reinit(cell);
          fe_u.reinit(same_cell<dim>(cell, view.dof_handler));
          fe_phi.get_function_gradients(phi, grad_phi);
          fe_u[displacement].get_function_symmetric_gradients(u, eps);
          for (const unsigned int q : fe_phi.quadrature_point_indices())
            {
              cross += grad_phi[q] * piezoelectric_polarization(piezo, eps[q]) *
                       fe_phi.JxW(q);
              field += 0.5 * grad_phi[q] * (beta * grad_phi[q]) * fe_phi.JxW(q);
            }
        }
    return {Utilities::MPI::sum(cross, mpi_communicator),
            Utilities::MPI::sum(field, mpi_communicator)};
  }

  template <int dim>
  void
  ElectricField<dim>::complete_step(const double                         t,
                                    const double                         k,
                                    const MechanicalView<dim>           &view,
                                    const TrilinosWrappers::MPI::Vector &before,
                                    const TrilinosWrappers::MPI::Vector &value,
                                    FieldStepEnergy                     &terms)
  {
    // the static class books the identity of each load value (Clapeyron),
    // in which phi's load is a load
    if (static_class || solves.empty())
      return;
    TrilinosWrappers::MPI::Vector delta(value);
    delta -= before;
    const double field =
      cross_and_field_energy(view, delta, view.displacement).second;
    // the equation whose test with delta closes the identity: at t_n with
    // the left-point rule (u_n known), at t_{n-1} with the implicit rule
    // (doc/theory.md 14.3)
    const double at         = left_point ? t : t - 0.5 * k;
    auto         solve_used = solves.begin();
    for (auto s = solves.begin(); s != solves.end(); ++s)
      if (left_point ?
            std::abs(s->first - at) < std::abs(solve_used->first - at) :
            s->first < at)
        solve_used = s;
    const Solve                  &used = solve_used->second;
    TrilinosWrappers::MPI::Vector conducted(used.conductance);
    conducted.scale(used.phi);
    const double supply = conducted * delta - used.data * delta;
    const double work   = k * (stress_load * view.velocity);
    terms.numerical     = left_point ? -field : field;
    terms.terms[2]      = supply;
    terms.terms[3]      = -work;
    terms.terms[4]      = work;
  }

  template <int dim>
  const std::vector<EnergyTermSpec> &
  ElectricField<dim>::energy_terms() const
  {
    return terms();
  }

  template <int dim>
  std::vector<double>
  ElectricField<dim>::stored_energies(
    const MechanicalView<dim>           &view,
    const TrilinosWrappers::MPI::Vector &value) const
  {
    if (static_class)
      return {};
    // the displacement held after the step: u_{n+1} (left point), u_n
    TrilinosWrappers::MPI::Vector held(view.displacement);
    held.add(view.held_offset, view.velocity);
    const auto [cross, field] = cross_and_field_energy(view, value, held);
    return {cross, -field};
  }

  template <int dim>
  std::vector<std::pair<std::string, Vector<float>>>
  ElectricField<dim>::cell_output(
    const TrilinosWrappers::MPI::Vector &value) const
  {
    const TrilinosWrappers::MPI::Vector phi =
      ghosted(value, *space->owned, *space->relevant, mpi_communicator);
    const unsigned int n_cells =
      space->dof_handler->get_triangulation().n_active_cells();
    std::vector<std::pair<std::string, Vector<float>>> fields;
    const char                                        *xyz[] = {"x", "y", "z"};
    for (unsigned int d = 0; d < dim; ++d)
      fields.emplace_back(std::string("electric_field_") + xyz[d],
                          Vector<float>(n_cells));
    const Quadrature<dim>       quadrature = discretization->cell_quadrature(2);
    FEValues<dim>               fe(*discretization->mapping,
                     space->dof_handler->get_fe(),
                     quadrature,
                     update_gradients | update_JxW_values);
    std::vector<Tensor<1, dim>> grad(quadrature.size());
    for (const auto &cell : space->dof_handler->active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe.reinit(cell);
          fe.get_function_gradients(phi, grad);
          double         volume = 0;
          Tensor<1, dim> e;
          for (const unsigned int q : fe.quadrature_point_indices())
            {
              e -= grad[q] * fe.JxW(q);
              volume += fe.JxW(q);
            }
          for (unsigned int d = 0; d < dim; ++d)
            fields[d].second[cell->active_cell_index()] = e[d] / volume;
        }
    return fields;
  }

  template <int dim>
  std::vector<std::string>
  ElectricField<dim>::contact_columns() const
  {
    return {"electric_potential", "conductance", "current"};
  }

  template <int dim>
  std::vector<std::vector<double>>
  ElectricField<dim>::contact_values(
    const MechanicalView<dim>           &view,
    const TrilinosWrappers::MPI::Vector &value) const
  {
    const TrilinosWrappers::MPI::Vector phi =
      ghosted(value, *space->owned, *space->relevant, mpi_communicator);
    const TrilinosWrappers::MPI::Vector u = ghosted(view.displacement,
                                                    view.locally_owned_dofs,
                                                    view.locally_relevant_dofs,
                                                    mpi_communicator);
    foundation_potential->set_time(view.time);
    std::vector<std::vector<double>> rows(view.contact_nodes.size(),
                                          std::vector<double>(3, 0.));
    for (unsigned int i = 0; i < rows.size(); ++i)
      if (view.contact_nodes[i].locally_owned)
        {
          const double phi_i = phi[node_dofs[i]];
          const double p_e   = conductance_at(view, i, u, view.time);
          const double phi_f =
            foundation_potential->value(view.contact_nodes[i].position);
          // D.nu = p_e (phi - phi_F) where the law holds (phi free)
          const bool free = !constraints.is_constrained(node_dofs[i]);
          rows[i]         = {phi_i, p_e, free ? p_e * (phi_i - phi_f) : 0.};
        }
    return rows;
  }

  template class ElectricField<2>;
  template class ElectricField<3>;
} // namespace hemicontact
