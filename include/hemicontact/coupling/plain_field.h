#pragma once

#include <hemicontact/base/exceptions.h>
#include <hemicontact/coupling/coupled_field.h>

#include <memory>
#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * A field of the state with no physics (doc/extending.md, "The state"):
   * saved, resumed, transferred and written as its definition says, with no
   * step, no load and no energy terms.
   */
  template <int dim>
  class PlainField : public CoupledField<dim>
  {
  public:
    explicit PlainField(const FieldDefinition<dim> &definition)
      : field(definition)
    {}

    FieldDefinition<dim>
    definition(const bool) const override
    {
      return field;
    }
    std::string
    subsection() const override
    {
      return field.name;
    }
    std::string
    symbol() const override
    {
      return field.name;
    }
    bool
    has_step() const override
    {
      return false;
    }
    std::string
    step_name() const override
    {
      return field.name;
    }
    void
    reinit(const FieldSpace<dim> &, const MechanicalView<dim> &) override
    {}
    void
    add_mechanical_load(const double,
                        const MechanicalView<dim> &,
                        TrilinosWrappers::MPI::Vector &,
                        TrilinosWrappers::MPI::Vector &) override
    {}
    FieldStepEnergy
    step(const double,
         const double,
         const MechanicalView<dim> &,
         LinearSolver &,
         TrilinosWrappers::MPI::Vector &) override
    {
      return {};
    }
    const std::vector<EnergyTermSpec> &
    energy_terms() const override
    {
      static const std::vector<EnergyTermSpec> none;
      return none;
    }

  private:
    FieldDefinition<dim> field;
  };

  /** A PlainField of @p definition. */
  template <int dim>
  std::unique_ptr<CoupledField<dim>>
  plain_field(const FieldDefinition<dim> &definition)
  {
    return std::make_unique<PlainField<dim>>(definition);
  }
} // namespace hemicontact
