#include <hemicontact/thermal/heat_field.h>

namespace hemicontact
{
  template <int dim>
  HeatField<dim>::HeatField(const TemperatureParameters &parameters,
                            const std::string           &constants,
                            const bool                   static_class,
                            const HeatData<dim>         &derived,
                            MPI_Comm                     comm)
    : parameters(parameters)
    , static_class(static_class)
    , heat(parameters, constants, static_class, derived, comm)
  {}

  template <int dim>
  const std::vector<EnergyTermSpec> &
  HeatField<dim>::terms()
  {
    using R = EnergyRole;
    // 1/2 c_theta |theta_n|^2; sum k (K grad theta_n, grad theta_n); the
    // heat sources' sum k (q, theta_n) with the boundaries'; -sum k (c_e
    // div w_n, theta_n); the contact heat booked (parts of the supply);
    // sum k (c_e theta, div w_n), the thermal stress's share of
    // external_work
    static const std::vector<EnergyTermSpec> list{
      {"thermal", "thermal_energy", R::stored},
      {"thermal_dissipation", "thermal_dissipation", R::dissipated},
      {"heat_supply", "heat_supply", R::supplied},
      {"thermal_coupling_work", "thermal_coupling_work", R::coupling},
      {"frictional_heat", "frictional_heat", R::reported},
      {"exchanged_heat", "exchanged_heat", R::reported},
      {"thermal_stress_work", "", R::converted}};
    return list;
  }

  template <int dim>
  FieldDefinition<dim>
  HeatField<dim>::definition(const bool simplex) const
  {
    return heat.field(simplex);
  }

  template <int dim>
  std::string
  HeatField<dim>::subsection() const
  {
    return "temperature";
  }

  template <int dim>
  std::string
  HeatField<dim>::symbol() const
  {
    return "theta_n";
  }

  template <int dim>
  bool
  HeatField<dim>::has_step() const
  {
    // the static class takes theta as data
    return !static_class;
  }

  template <int dim>
  FieldCoupling
  HeatField<dim>::coupling() const
  {
    return {parameters.coupling == TemperatureCoupling::iterated,
            parameters.coupling_tolerance,
            parameters.coupling_iterations};
  }

  template <int dim>
  std::string
  HeatField<dim>::step_name() const
  {
    return "heat step";
  }

  template <int dim>
  void
  HeatField<dim>::reinit(const FieldSpace<dim>     &space,
                         const MechanicalView<dim> &view)
  {
    heat.reinit(space, view);
  }

  template <int dim>
  void
  HeatField<dim>::start(const MechanicalView<dim> &,
                        LinearSolver &,
                        TrilinosWrappers::MPI::Vector &value,
                        const bool)
  {
    heat.start(value);
  }

  template <int dim>
  void
  HeatField<dim>::add_mechanical_load(const double                   t,
                                      const MechanicalView<dim>     &view,
                                      TrilinosWrappers::MPI::Vector &value,
                                      TrilinosWrappers::MPI::Vector &load)
  {
    heat.add_thermal_stress(t, view, value, load);
  }

  template <int dim>
  FieldStepEnergy
  HeatField<dim>::step(const double                   t,
                       const double                   k,
                       const MechanicalView<dim>     &view,
                       LinearSolver                  &solver,
                       TrilinosWrappers::MPI::Vector &value)
  {
    const HeatStepEnergy e = heat.heat_step(t, k, view, solver, value);
    // in the order of terms()
    return {e.numerical,
            {0.,
             e.dissipation,
             e.supply,
             e.coupling,
             e.frictional_heat,
             e.exchanged_heat,
             e.stress_work}};
  }

  template <int dim>
  const std::vector<EnergyTermSpec> &
  HeatField<dim>::energy_terms() const
  {
    return terms();
  }

  template <int dim>
  std::vector<double>
  HeatField<dim>::stored_energies(
    const MechanicalView<dim> &,
    const TrilinosWrappers::MPI::Vector &value) const
  {
    // the first of terms(), 1/2 c_theta |theta_n|^2
    return {heat.stored_heat(value)};
  }

  template <int dim>
  std::vector<std::pair<std::string, Vector<float>>>
  HeatField<dim>::cell_output(const TrilinosWrappers::MPI::Vector &value) const
  {
    return heat.cell_output(value);
  }

  template <int dim>
  std::vector<std::string>
  HeatField<dim>::contact_columns() const
  {
    // theta, and in the velocity classes the heat the heat step booked:
    // the exchanged k_e (theta_F - theta) and the frictional gamma
    // |sigma_tau . w_tau| (0 where theta is prescribed); the static class
    // has no contact heat law (theta is data)
    if (static_class)
      return {"temperature"};
    return {"temperature", "exchanged_heat", "frictional_heat"};
  }

  template <int dim>
  std::vector<std::vector<double>>
  HeatField<dim>::contact_values(
    const MechanicalView<dim>           &view,
    const TrilinosWrappers::MPI::Vector &value) const
  {
    const std::vector<NodeHeat> nodes =
      heat.contact_heat(view.time, view, value);
    std::vector<std::vector<double>> rows;
    rows.reserve(nodes.size());
    for (const NodeHeat &node : nodes)
      if (static_class)
        rows.push_back({node.temperature});
      else
        rows.push_back({node.temperature, node.exchanged(), node.frictional()});
    return rows;
  }

  template <int dim>
  std::vector<SummaryValue>
  HeatField<dim>::summary() const
  {
    return {{"heat content", "heat", heat.balance().heat_content}};
  }

  template <int dim>
  StaggeredCoupling
  HeatField<dim>::staggered_coupling() const
  {
    // the static class has no heat step; the iterated coupling solves the
    // monolithic step (doc/theory.md 13.2)
    if (static_class || parameters.coupling != TemperatureCoupling::staggered)
      return {};
    return {heat.largest_coupling_ratio(),
            "thermal coupling",
            "max c_e^2/c_theta",
            "the temperature",
            "a smaller 'temperature/thermal stress coefficient', a larger "
            "heat capacity or viscosity. 'temperature/coupling = iterated' "
            "solves the monolithic step, but its passes converge only below "
            "about half this limit.",
            subsection()};
  }

  template class HeatField<2>;
  template class HeatField<3>;
} // namespace hemicontact
