#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/coupling/partitioned_coupling.h>
#include <hemicontact/problem/error_indicators.h>

#include <algorithm>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <tuple>

namespace hemicontact
{
  template <int dim>
  StepStatistics
  ContactProblem<dim>::advance()
  {
    Timer wall;
    ++step_number;
    const double time = step_number * time_step;

    // w_{n-1} for the time indicator of the velocity classes (old_velocity
    // holds the start of the last sub-step after a halving)
    const bool time_indicated =
      parameters.output.error_estimate && !scheme.is_static();
    TrilinosWrappers::MPI::Vector velocity_before;
    if (time_indicated)
      velocity_before = velocity;

    StepStatistics stats;
    try
      {
        stats = advance_interval(time - time_step, time_step, 0, time_step);
      }
    catch (const SolverFailure &failure)
      {
        --step_number;
        std::ostringstream message;
        message << "step " << step_number + 1 << " (t = " << time
                << ") failed: " << failure.what();
        throw SolverFailure(message.str());
      }
    stats.step         = step_number;
    stats.time         = time;
    stats.wall_seconds = wall.wall_time();
    stats.n_cells      = discretization.triangulation->n_global_active_cells();
    stats.n_dofs       = dof_handler.n_dofs();
    ++state_revision;
    solved_revision = state_revision;
    if (parameters.output.error_estimate)
      {
        TimerOutput::Scope   t(timer, "error estimate");
        const ErrorEstimate &e  = error_estimate();
        stats.estimated         = true;
        stats.estimate          = e.total();
        stats.estimate_interior = e.part(e.interior_sum);
        stats.estimate_jumps    = e.part(e.jumps_sum);
        stats.estimate_neumann  = e.part(e.neumann_sum);
        stats.estimate_contact  = e.part(e.contact_sum);
        if (time_indicated)
          {
            // its own share of the section 'error estimate'
            TimerOutput::Scope t_time(timer, "time indicator");
            stats.time_estimated = true;
            stats.estimate_time  = time_indicator(state(), velocity_before);
          }
      }
    return stats;
  }

  template <int dim>
  StepStatistics
  ContactProblem<dim>::advance_interval(const double       start,
                                        const double       k,
                                        const unsigned int depth,
                                        const double       following_k)
  {
    const double wall_length = scheme.wall_step_length(k, following_k);
    // u_n = u_{n-1} + k w_{n-1} (left-point rule; the implicit rule adds
    // k w_n after the step, StepScheme), then solve for w_n,
    // starting from the linear extrapolation of w_{n-2}, w_{n-1}; the trend
    // is zero after the start, an adaptation or a resume (old_velocity =
    // velocity there)
    const bool extrapolate =
      parameters.nonlinear_solver.initial_guess == InitialGuess::extrapolated &&
      last_step_length > 0;
    TrilinosWrappers::MPI::Vector trend;
    if (extrapolate)
      {
        trend = velocity;
        trend -= old_velocity;
      }
    old_velocity = velocity;
    // the memory of the states up to t_{n-1} = start, u_{n-1} the last
    // (doc/theory.md, section 11)
    if (memory.active())
      {
        TimerOutput::Scope t(timer, "memory");
        memory.prepare_step(start, k, displacement);
      }
    scheme.displacement_before_step(displacement, old_velocity, k);
    if (extrapolate)
      {
        velocity.add(k / last_step_length, trend);
        base_constraints.distribute(velocity);
      }
    // the contact pressure p_nu of the bound: in the velocity classes the
    // step before's throughout the step, in the static class the last
    // solve's (doc/theory.md, section 9.9)
    const TrilinosWrappers::MPI::Vector traction_before(contact_traction);
    // the branches of the last converged state: a failed step's iterates
    // change them, and the state written after a failure carries its own
    // (a retry with halved steps starts from the failed iterate's)
    const std::vector<ContactNode<dim>>  nodes_before(contact_nodes);
    const TrilinosWrappers::MPI::Vector *pressure =
      scheme.is_static() ? &contact_traction : &traction_before;
    update_friction_bounds(start + k, pressure);
    if (const auto context = convexity_recheck(state(), start + k))
      check_convexity(*context);
    try
      {
        // the mechanical step with the coupled fields' steps before and
        // after it, staggered or iterated (doc/theory.md 13.2)
        StepStatistics stats;
        bool           first_solve     = true;
        const auto     mechanical_step = [&]() {
          assemble_load(start + k);
          assemble_step_rhs();
          const StepStatistics solved =
            solve_with_bound(start + k, pressure, wall_length, false);
          scheme.displacement_after_step(displacement, velocity, k);
          // a repeated solve (an iterated coupling) adds its iterations
          const unsigned int newton = first_solve ? 0 : stats.newton_iterations,
                             linear = first_solve ? 0 : stats.linear_iterations,
                             bound = first_solve ? 0 : stats.bound_iterations;
          stats                    = solved;
          stats.newton_iterations += newton;
          stats.linear_iterations += linear;
          stats.bound_iterations += bound;
          first_solve = false;
        };
        const auto undo_mechanical_step = [&]() {
          scheme.undo_displacement_after_step(displacement, velocity, k);
        };
        unsigned int                       passes      = 1;
        const std::vector<FieldStepEnergy> field_terms = couple_step(
          coupled_fields,
          added_fields,
          start + k,
          k,
          linear_solver,
          timer,
          velocity,
          [this]() { return mechanical_view(state()); },
          mechanical_step,
          undo_mechanical_step,
          passes);
        if (coupled_fields.have_steps())
          stats.coupling_passes = passes;
        if (memory.active())
          memory.commit_step(&velocity, &contact_traction);
        update_energy_balance(/*initial=*/false);
        coupled_fields.book(energy, field_terms);
        last_step_length = k;
        return stats;
      }
    catch (const SolverFailure &failure)
      {
        // back to the last converged state (w_{n-1}, u_{n-1})
        scheme.undo_displacement_before_step(displacement, old_velocity, k);
        velocity         = old_velocity;
        contact_traction = traction_before;
        if (depth >= parameters.nonlinear_solver.time_step_halvings)
          {
            contact_nodes = nodes_before;
            if (depth == 0)
              throw;
            std::string what = failure.what();
            if (!what.empty() && what.back() == '.')
              what.pop_back();
            std::ostringstream message;
            message << what << "; with the step halved " << depth
                    << " times as well (down to k = " << k
                    << ", 'nonlinear solver/time step halvings' = "
                    << parameters.nonlinear_solver.time_step_halvings << ").";
            throw SolverFailure(message.str());
          }
      }

    // retry the interval as two steps of k/2 (and so on, recursively)
    pcout << "  Newton failed with k = " << k << " on [" << start << ", "
          << start + k << "]: two steps of k/2" << std::endl;
    set_time_step(k / 2);
    StepStatistics first, second;
    try
      {
        first  = advance_interval(start, k / 2, depth + 1, k / 2);
        second = advance_interval(start + k / 2, k / 2, depth + 1, following_k);
      }
    catch (const SolverFailure &)
      {
        set_time_step(k);
        throw;
      }
    set_time_step(k);
    second.newton_iterations += first.newton_iterations;
    second.linear_iterations += first.linear_iterations;
    second.line_search_reductions += first.line_search_reductions;
    second.time_step_halvings += 1 + first.time_step_halvings;
    second.bound_iterations += first.bound_iterations;
    second.coupling_passes += first.coupling_passes;
    return second;
  }

  template <int dim>
  void
  ContactProblem<dim>::set_time_step(const double k)
  {
    // everything that depends on k: the step matrix rho/k M + A, its AMG
    // and the stored energy, whose elastic part is that of u_n + k w_n: the
    // change of k changes E_n by itself, booked like a mesh transfer
    const StoredEnergy before = stored_energy(state());
    time_step                 = k;
    assemble_constant_matrices(scheme.step_matrix(time_step));
    preconditioner.clear();
    const StoredEnergy after = stored_energy(state());
    energy.kinetic           = after.kinetic;
    energy.elastic           = after.elastic;
    energy.transfer_change += after.change_from(before);
  }

#define HEMICONTACT_INSTANTIATE(dim)                               \
  template StepStatistics ContactProblem<dim>::advance();          \
  template StepStatistics ContactProblem<dim>::advance_interval(   \
    const double, const double, const unsigned int, const double); \
  template void ContactProblem<dim>::set_time_step(const double);

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
