#pragma once

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/coupling/mechanical_view.h>
#include <hemicontact/model/energy_term.h>
#include <hemicontact/solver/linear_solver.h>
#include <hemicontact/state/added_fields.h>

#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /** What a coupled field's step books (doc/theory.md 13.4). */
  struct FieldStepEnergy
  {
    /** The step's numerical dissipation (into numerical_dissipation). */
    double numerical = 0;
    /** The step's share of each of the field's energy_terms(), in their
     *  order (a stored term's entry is not read). */
    std::vector<double> terms;
  };

  /** How a field's step is coupled with the mechanical step. */
  struct FieldCoupling
  {
    /** Solved to the monolithic answer with the mechanical step (true),
     *  or once per step with the other side known (false). */
    bool iterated = false;
    /** The relative change of the iterates that ends the passes. */
    double tolerance = 0;
    /** The largest number of passes. */
    unsigned int iterations = 1;
  };

  /**
   * The staggered coupling's strength for the time-step limit (doc/theory.md
   * 13.2): the mechanical step reads the field of the step before.
   */
  struct StaggeredCoupling
  {
    /** The coupling's c (0: not staggered, no limit). */
    double ratio = 0;
    /** How the message names the coupling ("thermal coupling"), c
     *  ("max c_e^2/c_theta") and the lagged field ("the temperature"). */
    std::string coupling_name, ratio_formula, lagged_field;
    /** The remedies the field offers, one or more sentences. */
    std::string remedies;
    /** The field's parameter subsection (the message's first word). */
    std::string subsection;
  };

  /** A number the run's progress lines print for a field. */
  struct SummaryValue
  {
    std::string long_label, short_label;
    double      value;
  };

  /**
   * A field coupled with the mechanical step (doc/extending.md, "A coupled
   * field"): a field of the state with a step of its own, a load on the
   * mechanical step, energy terms and output. ContactProblem holds a list of
   * them (CoupledFields) and calls every hook in a loop; the registry
   * (fields/coupled_field_registry.cc) creates the fields a run enables, one
   * line per kind.
   */
  template <int dim>
  class CoupledField
  {
  public:
    /** When a field's step is solved within a time step. */
    enum class Order
    {
      /** Before the mechanical step, from its known state. */
      before_mechanical_step,
      /** After the mechanical step, from its solution. */
      after_mechanical_step
    };

    virtual ~CoupledField() = default;

    /** The field of the state: its name, element, initial value. */
    virtual FieldDefinition<dim>
    definition(const bool simplex) const = 0;

    /** The parameter subsection that defines it (in messages). */
    virtual std::string
    subsection() const = 0;

    /** The symbol of its value at t_n in messages ("theta_n"). */
    virtual std::string
    symbol() const = 0;

    virtual Order
    order() const
    {
      return Order::after_mechanical_step;
    }

    /** Whether the field has a step of its own in this run's class. */
    virtual bool
    has_step() const
    {
      return true;
    }

    virtual FieldCoupling
    coupling() const
    {
      return {};
    }

    /** The timer section of its step. */
    virtual std::string
    step_name() const = 0;

    /** On a new mesh: the field's space and the mechanical view. */
    virtual void
    reinit(const FieldSpace<dim> &space, const MechanicalView<dim> &view) = 0;

    /**
     * The start of a run (before the initial solves, @p resumed false:
     * the field may solve its @p value at t = 0 from u_0) or a resume
     * (@p resumed true: @p value is the checkpoint's).
     */
    virtual void
    start(const MechanicalView<dim>     &view,
          LinearSolver                  &solver,
          TrilinosWrappers::MPI::Vector &value,
          const bool                     resumed)
    {
      (void)view;
      (void)solver;
      (void)value;
      (void)resumed;
    }

    /** Add the field's load on the mechanical step at time @p t to
     *  @p load (the displacement's space); @p value may be updated first
     *  where the field is data (the static class). */
    virtual void
    add_mechanical_load(const double                   t,
                        const MechanicalView<dim>     &view,
                        TrilinosWrappers::MPI::Vector &value,
                        TrilinosWrappers::MPI::Vector &load) = 0;

    /** The field's step at @p t of length @p k: @p value holds the value
     *  at t_{n-1} on entry and at t_n on return. */
    virtual FieldStepEnergy
    step(const double                   t,
         const double                   k,
         const MechanicalView<dim>     &view,
         LinearSolver                  &solver,
         TrilinosWrappers::MPI::Vector &value) = 0;

    /**
     * After the coupled step has converged: add to @p terms (sized to
     * energy_terms()) what needs the step's final state, from the value
     * @p before at t_{n-1} to @p value at t_n = @p t, with step length
     * @p k.
     */
    virtual void
    complete_step(const double                         t,
                  const double                         k,
                  const MechanicalView<dim>           &view,
                  const TrilinosWrappers::MPI::Vector &before,
                  const TrilinosWrappers::MPI::Vector &value,
                  FieldStepEnergy                     &terms)
    {
      (void)t;
      (void)k;
      (void)view;
      (void)before;
      (void)value;
      (void)terms;
    }

    /** Its energy terms (a static list: coupled_energy_terms() is made of
     *  them). */
    virtual const std::vector<EnergyTermSpec> &
    energy_terms() const = 0;

    /** The energies the field stores with @p value and the state of
     *  @p view, one per entry of energy_terms() (only the stored ones are
     *  read; empty: none). */
    virtual std::vector<double>
    stored_energies(const MechanicalView<dim>           &view,
                    const TrilinosWrappers::MPI::Vector &value) const
    {
      (void)view;
      (void)value;
      return {};
    }

    /** Cell data for the solution files. */
    virtual std::vector<std::pair<std::string, Vector<float>>>
    cell_output(const TrilinosWrappers::MPI::Vector &value) const
    {
      (void)value;
      return {};
    }

    /** The columns the field adds to the contact CSV. */
    virtual std::vector<std::string>
    contact_columns() const
    {
      return {};
    }

    /** The values of contact_columns() at each contact node of @p view
     *  (all of them, in their order; read at owned nodes). */
    virtual std::vector<std::vector<double>>
    contact_values(const MechanicalView<dim>           &view,
                   const TrilinosWrappers::MPI::Vector &value) const
    {
      (void)view;
      (void)value;
      return {};
    }

    /** The numbers the progress lines print. */
    virtual std::vector<SummaryValue>
    summary() const
    {
      return {};
    }

    /** The staggered coupling's strength on the current mesh (collective). */
    virtual StaggeredCoupling
    staggered_coupling() const
    {
      return {};
    }
  };
} // namespace hemicontact
