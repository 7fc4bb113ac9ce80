#pragma once

#include <hemicontact/coupling/coupled_field.h>
#include <hemicontact/thermal/heat_model.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  /**
   * The temperature as a coupled field (doc/theory.md, section 13): the
   * hooks of CoupledField on a HeatModel. Its step is the heat step, after
   * the mechanical step, staggered or iterated ('temperature/coupling');
   * the static class has none (theta is the data 'given temperature').
   */
  template <int dim>
  class HeatField : public CoupledField<dim>
  {
  public:
    /** The field of @p parameters' 'temperature' (the constants of
     *  'data/constants'); @p derived replaces data (a manufactured
     *  solution). */
    HeatField(const TemperatureParameters &parameters,
              const std::string           &constants,
              const bool                   static_class,
              const HeatData<dim>         &derived,
              MPI_Comm                     comm);

    /** Its energy terms (doc/theory.md 13.4), in the checkpoint's order. */
    static const std::vector<EnergyTermSpec> &
    terms();

    FieldDefinition<dim>
    definition(const bool simplex) const override;
    std::string
    subsection() const override;
    std::string
    symbol() const override;
    bool
    has_step() const override;
    FieldCoupling
    coupling() const override;
    std::string
    step_name() const override;
    void
    reinit(const FieldSpace<dim>     &space,
           const MechanicalView<dim> &view) override;
    void
    start(const MechanicalView<dim>     &view,
          LinearSolver                  &solver,
          TrilinosWrappers::MPI::Vector &value,
          const bool                     resumed) override;
    void
    add_mechanical_load(const double                   t,
                        const MechanicalView<dim>     &view,
                        TrilinosWrappers::MPI::Vector &value,
                        TrilinosWrappers::MPI::Vector &load) override;
    FieldStepEnergy
    step(const double                   t,
         const double                   k,
         const MechanicalView<dim>     &view,
         LinearSolver                  &solver,
         TrilinosWrappers::MPI::Vector &value) override;
    const std::vector<EnergyTermSpec> &
    energy_terms() const override;
    std::vector<double>
    stored_energies(const MechanicalView<dim>           &view,
                    const TrilinosWrappers::MPI::Vector &value) const override;
    std::vector<std::pair<std::string, Vector<float>>>
    cell_output(const TrilinosWrappers::MPI::Vector &value) const override;
    std::vector<std::string>
    contact_columns() const override;
    std::vector<std::vector<double>>
    contact_values(const MechanicalView<dim>           &view,
                   const TrilinosWrappers::MPI::Vector &value) const override;
    std::vector<SummaryValue>
    summary() const override;
    StaggeredCoupling
    staggered_coupling() const override;

    /** The heat model (its balance, for tests and studies). */
    const HeatModel<dim> &
    model() const
    {
      return heat;
    }

  private:
    TemperatureParameters parameters;
    bool                  static_class;
    HeatModel<dim>        heat;
  };
} // namespace hemicontact
