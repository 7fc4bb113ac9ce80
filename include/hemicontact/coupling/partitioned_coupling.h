#pragma once

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/coupling/coupled_fields.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * One time step of the mechanical step with the coupled fields
   * (doc/theory.md 13.2), a partitioned coupling over the list of fields:
   *
   * - the fields ordered before the mechanical step take their step;
   * - @p mechanical_step() solves the mechanical step (it reads the fields'
   *   loads), and the fields ordered after it take theirs;
   * - if a field is iterated ('coupling = iterated'), the pass is repeated
   *   over the iterated fields and the mechanical step (@p
   *   undo_mechanical_step() and @p mechanical_step() again, each iterated
   *   field's step again from its value at t_{n-1}), until the relative
   *   change of w_n (@p velocity) and of every iterated field between two
   *   passes is at most the smallest 'coupling tolerance' of them; the
   *   passes are at most the largest 'coupling iterations'.
   *
   * @p view() gives the MechanicalView of the state as it is. Returns each
   * field's step terms (in the order of @p coupled; empty for a field with
   * no step) and the number of passes in @p passes. A field's or the
   * mechanical step's SolverFailure, or passes that do not converge (a
   * SolverFailure naming the numbers), leave every field at its value at
   * t_{n-1} and, where the mechanical step had been solved, undo it: the
   * step is retried with k/2 as after a Newton failure.
   */
  template <int dim, class View, class MechanicalStep, class UndoMechanicalStep>
  std::vector<FieldStepEnergy>
  couple_step(const CoupledFields<dim>      &coupled,
              AddedFields<dim>              &fields,
              const double                   t,
              const double                   k,
              LinearSolver                  &solver,
              TimerOutput                   &timer,
              TrilinosWrappers::MPI::Vector &velocity,
              View                           view,
              MechanicalStep                 mechanical_step,
              UndoMechanicalStep             undo_mechanical_step,
              unsigned int                  &passes)
  {
    using Field                                        = CoupledField<dim>;
    const auto                                &entries = coupled.list();
    std::vector<FieldStepEnergy>               terms(entries.size());
    std::vector<TrilinosWrappers::MPI::Vector> before(entries.size());
    for (std::size_t f = 0; f < entries.size(); ++f)
      if (entries[f].field->has_step())
        before[f] = fields.vector(entries[f].name);
    const auto restore = [&]() {
      for (std::size_t f = 0; f < entries.size(); ++f)
        if (entries[f].field->has_step())
          fields.vector(entries[f].name) = before[f];
    };
    bool mechanical_solved = false;
    // a failure anywhere leaves the step as it found it
    const auto guarded = [&](auto action) {
      try
        {
          action();
        }
      catch (const SolverFailure &)
        {
          restore();
          if (mechanical_solved)
            undo_mechanical_step();
          throw;
        }
    };
    const auto field_step = [&](const std::size_t f) {
      const Field       &field = *entries[f].field;
      TimerOutput::Scope scope(timer, field.step_name());
      terms[f] = entries[f].field->step(
        t, k, view(), solver, fields.vector(entries[f].name));
    };
    // the fields of @p order, all or only the iterated ones, from t_{n-1}
    const auto steps_of = [&](const typename Field::Order order,
                              const bool                  only_iterated) {
      for (std::size_t f = 0; f < entries.size(); ++f)
        {
          const Field &field = *entries[f].field;
          if (field.has_step() && field.order() == order &&
              (!only_iterated || field.coupling().iterated))
            {
              fields.vector(entries[f].name) = before[f];
              field_step(f);
            }
        }
    };

    passes = 1;
    guarded([&]() {
      steps_of(Field::Order::before_mechanical_step, false);
      mechanical_step();
      mechanical_solved = true;
      steps_of(Field::Order::after_mechanical_step, false);
    });

    // the iterated fields' settings: the strictest tolerance, the most
    // passes; the first names them in a message
    const Field *first      = nullptr;
    double       tolerance  = 0;
    unsigned int iterations = 1;
    std::string  symbols;
    for (const auto &e : entries)
      if (e.field->has_step() && e.field->coupling().iterated)
        {
          const FieldCoupling c = e.field->coupling();
          tolerance =
            first == nullptr ? c.tolerance : std::min(tolerance, c.tolerance);
          iterations = std::max(iterations, c.iterations);
          first      = first == nullptr ? e.field.get() : first;
          symbols += ", " + e.field->symbol();
        }
    // what a field books from the step's final state
    const auto complete = [&]() {
      for (std::size_t f = 0; f < entries.size(); ++f)
        if (entries[f].field->has_step())
          {
            terms[f].terms.resize(entries[f].field->energy_terms().size(), 0.);
            entries[f].field->complete_step(t,
                                            k,
                                            view(),
                                            before[f],
                                            fields.vector(entries[f].name),
                                            terms[f]);
          }
      return terms;
    };
    if (first == nullptr)
      return complete();

    // |a - b| / |a|, 0 where both vanish
    const auto change = [](const TrilinosWrappers::MPI::Vector &a,
                           TrilinosWrappers::MPI::Vector        b) {
      b -= a;
      const double size = a.l2_norm();
      return size > 0 ? b.l2_norm() / size : b.l2_norm();
    };
    double last_change = 0;
    while (passes < iterations)
      {
        const TrilinosWrappers::MPI::Vector        velocity_before(velocity);
        std::vector<TrilinosWrappers::MPI::Vector> last(entries.size());
        for (std::size_t f = 0; f < entries.size(); ++f)
          if (entries[f].field->has_step() &&
              entries[f].field->coupling().iterated)
            last[f] = fields.vector(entries[f].name);
        guarded([&]() {
          // the fields before the mechanical step read its last iterate
          steps_of(Field::Order::before_mechanical_step, true);
          mechanical_solved = false;
          undo_mechanical_step();
          mechanical_step();
          mechanical_solved = true;
          steps_of(Field::Order::after_mechanical_step, true);
        });
        ++passes;
        last_change = change(velocity, velocity_before);
        for (std::size_t f = 0; f < entries.size(); ++f)
          if (last[f].size() > 0)
            last_change =
              std::max(last_change,
                       change(fields.vector(entries[f].name), last[f]));
        if (last_change <= tolerance)
          return complete();
      }
    restore();
    undo_mechanical_step();
    std::ostringstream message;
    message << first->subsection()
            << ": the iterated coupling did not converge in " << passes
            << " passes ('" << first->subsection()
            << "/coupling iterations'; the relative change of (w_n" << symbols
            << ") is " << last_change
            << " > 'coupling tolerance' = " << tolerance << ").";
    throw SolverFailure(message.str());
  }
} // namespace hemicontact
