#pragma once

#include <deal.II/base/timer.h>

#include <hemicontact/coupling/coupled_field.h>
#include <hemicontact/model/energy_balance.h>

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  /**
   * The coupled fields of a run (doc/extending.md, "A coupled field"),
   * in the registry's order, each with the position of its energy terms
   * in EnergyBalance::coupled; every hook of CoupledField is called here in
   * a loop. The values live in the state's added fields (by each field's
   * name). The partitioned coupling of a time step is couple_step()
   * (partitioned_coupling.h).
   */
  template <int dim>
  class CoupledFields
  {
  public:
    /** A field and the offset of its terms in coupled_energy_terms(). */
    struct Entry
    {
      std::unique_ptr<CoupledField<dim>> field;
      std::size_t                        energy_offset;
      std::string                        name;
    };

    void
    add(std::unique_ptr<CoupledField<dim>> field,
        const std::size_t                  energy_offset,
        const bool                         simplex,
        AddedFields<dim>                  &fields,
        const std::vector<std::string>    &reserved)
    {
      const FieldDefinition<dim> definition = field->definition(simplex);
      fields.add(definition, reserved);
      entries.push_back({std::move(field), energy_offset, definition.name});
    }

    bool
    empty() const
    {
      return entries.empty();
    }

    const std::vector<Entry> &
    list() const
    {
      return entries;
    }

    /** Whether a field has a step of its own in this run. */
    bool
    have_steps() const
    {
      for (const Entry &e : entries)
        if (e.field->has_step())
          return true;
      return false;
    }

    /** On a new mesh. */
    void
    reinit(const AddedFields<dim> &fields, const MechanicalView<dim> &view)
    {
      for (const Entry &e : entries)
        e.field->reinit(fields.space(e.name), view);
    }

    /** The start of a run (@p resumed false) or a resume. */
    void
    start(const MechanicalView<dim> &view,
          LinearSolver              &solver,
          AddedFields<dim>          &fields,
          const bool                 resumed)
    {
      for (const Entry &e : entries)
        e.field->start(view, solver, fields.vector(e.name), resumed);
    }

    /** Every field's load on the mechanical step at @p t. */
    void
    add_mechanical_loads(const double                   t,
                         const MechanicalView<dim>     &view,
                         AddedFields<dim>              &fields,
                         TrilinosWrappers::MPI::Vector &load)
    {
      for (const Entry &e : entries)
        e.field->add_mechanical_load(t, view, fields.vector(e.name), load);
    }

    /** The stored energies into @p coupled (EnergyBalance::coupled's
     *  layout), in the velocity classes' steps. */
    void
    stored_energies(const MechanicalView<dim> &view,
                    const AddedFields<dim>    &fields,
                    std::vector<double>       &coupled) const
    {
      for (const Entry &e : entries)
        if (e.field->has_step())
          {
            const std::vector<EnergyTermSpec> &terms = e.field->energy_terms();
            const std::vector<double>          stored =
              e.field->stored_energies(view, fields.vector(e.name));
            for (std::size_t j = 0; j < stored.size(); ++j)
              if (terms[j].role == EnergyRole::stored)
                coupled[e.energy_offset + j] = stored[j];
          }
    }

    /** Add the fields' step terms @p steps (one per field, empty where
     *  none was taken) to @p energy. */
    void
    book(EnergyBalance &energy, const std::vector<FieldStepEnergy> &steps) const
    {
      for (std::size_t f = 0; f < steps.size(); ++f)
        {
          energy.numerical_dissipation += steps[f].numerical;
          const std::vector<EnergyTermSpec> &terms =
            entries[f].field->energy_terms();
          for (std::size_t j = 0; j < steps[f].terms.size(); ++j)
            if (terms[j].role != EnergyRole::stored)
              energy.coupled[entries[f].energy_offset + j] += steps[f].terms[j];
        }
    }

    /** The cell data of every field for the solution files. */
    std::vector<std::pair<std::string, Vector<float>>>
    cell_output(const AddedFields<dim> &fields) const
    {
      std::vector<std::pair<std::string, Vector<float>>> data;
      for (const Entry &e : entries)
        for (auto &d : e.field->cell_output(fields.vector(e.name)))
          data.push_back(std::move(d));
      return data;
    }

    /** The contact CSV's columns of every field. */
    std::vector<std::string>
    contact_columns() const
    {
      std::vector<std::string> names;
      for (const Entry &e : entries)
        for (const std::string &name : e.field->contact_columns())
          names.push_back(name);
      return names;
    }

    /** Their values: per contact node, the columns of every field. */
    std::vector<std::vector<double>>
    contact_values(const MechanicalView<dim> &view,
                   const AddedFields<dim>    &fields) const
    {
      std::vector<std::vector<double>> rows(view.contact_nodes.size());
      for (const Entry &e : entries)
        {
          const auto values =
            e.field->contact_values(view, fields.vector(e.name));
          for (std::size_t i = 0; i < values.size(); ++i)
            rows[i].insert(rows[i].end(), values[i].begin(), values[i].end());
        }
      return rows;
    }

    /** The numbers of the progress lines. */
    std::vector<SummaryValue>
    summary() const
    {
      std::vector<SummaryValue> values;
      for (const Entry &e : entries)
        for (const SummaryValue &v : e.field->summary())
          values.push_back(v);
      return values;
    }

    /**
     * The staggered couplings together (collective): the sum of their
     * ratios (each lagged field adds its term to the explicit elastic
     * part), named as the strongest (ratio 0: none).
     */
    StaggeredCoupling
    staggered_coupling() const
    {
      StaggeredCoupling strongest;
      double            sum = 0;
      for (const Entry &e : entries)
        {
          const StaggeredCoupling c = e.field->staggered_coupling();
          sum += c.ratio;
          if (c.ratio > strongest.ratio)
            strongest = c;
        }
      strongest.ratio = sum;
      return strongest;
    }

  private:
    std::vector<Entry> entries;
  };
} // namespace hemicontact
