/**
 * The registry of coupled fields (doc/extending.md, "A coupled field"):
 * one line per kind, its energy terms and its factory. The order is the
 * order of the fields' steps of one kind, of their energy terms in
 * EnergyBalance::coupled, the checkpoint and steps.csv: a kind is added at
 * the end.
 */
#include <hemicontact/electric/electric_field.h>
#include <hemicontact/fields/coupled_field_registry.h>
#include <hemicontact/thermal/heat_field.h>

#include <functional>
#include <memory>

namespace hemicontact
{
  namespace
  {
    template <int dim>
    using Factory = std::function<std::unique_ptr<CoupledField<dim>>(
      const CoupledFieldContext<dim> &)>;

    /** A kind of coupled field: its energy terms and its factory (nullptr
     *  where the parameters do not enable it). */
    template <int dim>
    struct Kind
    {
      const std::vector<EnergyTermSpec> &(*terms)();
      Factory<dim> create;
    };

    template <int dim>
    std::unique_ptr<CoupledField<dim>>
    temperature(const CoupledFieldContext<dim> &c)
    {
      if (!c.parameters.temperature.enabled)
        return nullptr;
      return std::make_unique<HeatField<dim>>(c.parameters.temperature,
                                              c.parameters.data.constants,
                                              c.static_class,
                                              c.data.heat,
                                              c.comm);
    }

    template <int dim>
    std::unique_ptr<CoupledField<dim>>
    piezoelectricity(const CoupledFieldContext<dim> &c)
    {
      if (!c.parameters.piezoelectricity.enabled)
        return nullptr;
      return std::make_unique<ElectricField<dim>>(
        c.parameters.piezoelectricity,
        c.parameters.data.constants,
        c.static_class,
        c.parameters.problem.time_scheme == TimeScheme::left_point,
        c.comm);
    }

    template <int dim>
    const std::vector<Kind<dim>> &
    kinds()
    {
      static const std::vector<Kind<dim>> list{
        {&HeatField<dim>::terms, &temperature<dim>},
        {&ElectricField<dim>::terms, &piezoelectricity<dim>}};
      return list;
    }
  } // namespace

  const std::vector<EnergyTermSpec> &
  coupled_energy_terms()
  {
    static const std::vector<EnergyTermSpec> terms = []() {
      std::vector<EnergyTermSpec> all;
      for (const Kind<2> &kind : kinds<2>())
        for (const EnergyTermSpec &term : kind.terms())
          all.push_back(term);
      return all;
    }();
    return terms;
  }

  template <int dim>
  void
  create_coupled_fields(const CoupledFieldContext<dim> &context,
                        const bool                      simplex,
                        AddedFields<dim>               &fields,
                        const std::vector<std::string> &reserved,
                        CoupledFields<dim>             &coupled)
  {
    std::size_t offset = 0;
    for (const Kind<dim> &kind : kinds<dim>())
      {
        if (auto field = kind.create(context))
          coupled.add(std::move(field), offset, simplex, fields, reserved);
        offset += kind.terms().size();
      }
  }

  template void
  create_coupled_fields(const CoupledFieldContext<2> &,
                        const bool,
                        AddedFields<2> &,
                        const std::vector<std::string> &,
                        CoupledFields<2> &);
  template void
  create_coupled_fields(const CoupledFieldContext<3> &,
                        const bool,
                        AddedFields<3> &,
                        const std::vector<std::string> &,
                        CoupledFields<3> &);
} // namespace hemicontact
