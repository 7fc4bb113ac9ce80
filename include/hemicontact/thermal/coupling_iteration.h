#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/parameters.h>

#include <algorithm>
#include <sstream>
#include <string>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The coupling of the mechanical and the heat step at one time step
   * (doc/theory.md 13.2), after the mechanical step with theta_{n-1} has
   * been solved: the heat step from theta_{n-1} (@p heat_step(), which
   * takes @p theta from theta_{n-1} to theta_n and returns its energy
   * terms). With 'coupling = staggered' that is all. With 'iterated' the
   * mechanical step is solved again with the last theta_n in its load
   * (@p redo_mechanical_step(), which reads @p theta) and the heat step
   * again from theta_{n-1}, until the relative change of w_n
   * (@p velocity) and of theta_n between two passes is at most 'coupling
   * tolerance'. Returns the heat step's terms of the last pass and the
   * number of passes in @p passes. If 'coupling iterations' passes do
   * not get there, theta is theta_{n-1} again, @p undo_mechanical_step()
   * takes the step's displacement update back, and a SolverFailure is
   * thrown (the step is retried with k/2, as after a Newton failure); a
   * heat step's or a repeated mechanical step's SolverFailure leaves
   * theta and the displacement as before the step as well.
   */
  template <class HeatStep, class RedoMechanicalStep, class UndoMechanicalStep>
  auto
  couple_heat_step(const TemperatureParameters   &parameters,
                   TrilinosWrappers::MPI::Vector &velocity,
                   TrilinosWrappers::MPI::Vector &theta,
                   HeatStep                       heat_step,
                   RedoMechanicalStep             redo_mechanical_step,
                   UndoMechanicalStep             undo_mechanical_step,
                   unsigned int                  &passes)
  {
    const TrilinosWrappers::MPI::Vector theta_before(theta);
    // a heat step that fails (its CG) leaves the step as it found it
    const auto heat_step_or_undo = [&]() {
      try
        {
          return heat_step();
        }
      catch (const SolverFailure &)
        {
          theta = theta_before;
          undo_mechanical_step();
          throw;
        }
    };
    auto terms = heat_step_or_undo();
    passes     = 1;
    if (parameters.coupling != TemperatureCoupling::iterated)
      return terms;
    // |a - b| / |a|, 0 where both vanish
    const auto change = [](const TrilinosWrappers::MPI::Vector &a,
                           TrilinosWrappers::MPI::Vector        b) {
      b -= a;
      const double size = a.l2_norm();
      return size > 0 ? b.l2_norm() / size : b.l2_norm();
    };
    double last_change = 0;
    while (passes < parameters.coupling_iterations)
      {
        const TrilinosWrappers::MPI::Vector velocity_before(velocity),
          theta_last(theta);
        try
          {
            redo_mechanical_step();
          }
        catch (const SolverFailure &)
          {
            // the step is retried from theta_{n-1}
            theta = theta_before;
            throw;
          }
        theta = theta_before;
        terms = heat_step_or_undo();
        ++passes;
        last_change = std::max(change(velocity, velocity_before),
                               change(theta, theta_last));
        if (last_change <= parameters.coupling_tolerance)
          return terms;
      }
    theta = theta_before;
    undo_mechanical_step();
    std::ostringstream message;
    message << "temperature: the iterated coupling did not converge in "
            << passes << " passes ('temperature/coupling iterations'; the "
            << "relative change of (w_n, theta_n) is " << last_change
            << " > 'coupling tolerance' = " << parameters.coupling_tolerance
            << ").";
    throw SolverFailure(message.str());
  }
} // namespace hemicontact
