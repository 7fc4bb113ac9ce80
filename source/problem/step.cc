#include <deal.II/base/array_view.h>
#include <deal.II/base/mpi.h>

#include <hemicontact/model/contact_step.h>
#include <hemicontact/model/contact_wall.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/solver/active_set_newton.h>
#include <hemicontact/solver/friction_bound_iteration.h>


namespace hemicontact
{
  namespace
  {
    /** The branches of the owned nodes of @p contact_nodes, summed over the
     *  ranks, into @p stats. */
    template <int dim>
    void
    count_branches(const std::vector<ContactNode<dim>> &contact_nodes,
                   MPI_Comm                             mpi_communicator,
                   StepStatistics                      &stats)
    {
      // one count per branch, summed over the ranks in one reduction
      unsigned int counts[7] = {0, 0, 0, 0, 0, 0, 0};
      for (const ContactNode<dim> &node : contact_nodes)
        if (node.locally_owned)
          {
            counts[0] += node.normal_branch == NormalBranch::separating;
            counts[1] += node.normal_branch == NormalBranch::stick;
            counts[2] += node.normal_branch == NormalBranch::damped;
            counts[3] += node.tangential_branch == TangentialBranch::stick;
            counts[4] += node.tangential_branch == TangentialBranch::slip;
            counts[5] += node.normal_branch == NormalBranch::breakpoint;
            counts[6] += node.normal_branch == NormalBranch::wall;
          }
      Utilities::MPI::sum(ArrayView<const unsigned int>(counts, 7),
                          mpi_communicator,
                          ArrayView<unsigned int>(counts, 7));
      stats.n_separating    = counts[0];
      stats.n_normal_stick  = counts[1];
      stats.n_damped        = counts[2];
      stats.n_stick         = counts[3];
      stats.n_slip          = counts[4];
      stats.n_at_breakpoint = counts[5];
      stats.n_at_wall       = counts[6];
    }
  } // namespace

  template <int dim>
  StepStatistics
  ContactProblem<dim>::solve_step(const double wall_length)
  {
    // the wall in the step's unknown (doc/theory.md section 10), moved by
    // the wear depth (section 11.12)
    TrilinosWrappers::MPI::Vector wear;
    if (memory.contact_memory().wear_active())
      {
        wear.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
        wear = memory.contact_memory().wear();
      }
    const TrilinosWrappers::MPI::Vector *wear_depth =
      memory.contact_memory().wear_active() ? &wear : nullptr;
    if (std::isfinite(law->penetration_limit()) && !scheme.is_static())
      {
        TrilinosWrappers::MPI::Vector u(locally_owned_dofs,
                                        locally_relevant_dofs,
                                        mpi_communicator);
        u = displacement;
        set_wall_limits(contact_nodes, *law, &u, wall_length, wear_depth);
      }
    else
      // the velocity classes without a wall: the law on w_nu does not see
      // the wear
      set_wall_limits(contact_nodes,
                      *law,
                      nullptr,
                      wall_length,
                      scheme.is_static() ? wear_depth : nullptr);
    ContactStep<dim>      step({step_matrix,
                                step_rhs,
                                base_constraints,
                                locally_owned_dofs,
                                locally_relevant_dofs,
                                contact_nodes,
                                *law,
                                *friction,
                                linear_solver,
                                preconditioner,
                                timer,
                                mpi_communicator},
                          parameters);
    const ActiveSetNewton newton(newton_settings(parameters), &timer);

    TrilinosWrappers::MPI::Vector w(velocity);
    TrilinosWrappers::MPI::Vector residual(locally_owned_dofs,
                                           mpi_communicator);
    const ActiveSetNewton::Report report = newton.solve(step, w, residual);

    velocity = w;
    // the nodal contact traction -(K0 w - b)_i / m_i
    for (const ContactNode<dim> &node : contact_nodes)
      if (node.locally_owned)
        for (unsigned int c = 0; c < dim; ++c)
          contact_traction[node.dofs[c]] = -residual[node.dofs[c]] / node.mass;
    contact_traction.compress(VectorOperation::insert);
    // -sigma nu: the memory pressure N_i nu_i besides (doc/theory.md 11.9)
    memory.add_pressure(contact_traction);

    StepStatistics stats;
    stats.newton_iterations      = report.newton_iterations;
    stats.linear_iterations      = report.linear_iterations;
    stats.line_search_reductions = report.line_search_reductions;
    stats.residual               = report.relative_residual;
    count_branches(contact_nodes, mpi_communicator, stats);
    return stats;
  }

  template <int dim>
  StepStatistics
  ContactProblem<dim>::solve_with_bound(
    const double                         t,
    const TrilinosWrappers::MPI::Vector *pressure,
    const double                         wall_length,
    const bool                           initial)
  {
    StepStatistics            stats = solve_step(wall_length);
    const FrictionBound<dim> &bound = *data.friction_bound;
    // whether the bound reads the step's own unknown (doc/theory.md,
    // sections 9.8 and 9.9): in the static class u_nu and p_nu; in a step
    // of the velocity classes w_nu (p_nu is the step before's); at w_0 of
    // the quasistatic class p_nu, which no step before could give
    const bool reads_own_unknown =
      scheme.is_static() ?
        bound.uses_normal_displacement() || bound.uses_contact_pressure() :
      initial ? bound.uses_contact_pressure() :
                bound.uses_normal_velocity();
    if (reads_own_unknown)
      iterate_friction_bound(
        [&]() { return update_friction_bounds(t, pressure); },
        [&]() {
          if (!initial)
            if (const auto context = convexity_recheck(state(), t))
              check_convexity(*context);
          return solve_step(wall_length);
        },
        parameters.nonlinear_solver,
        stats);
    return stats;
  }

  template StepStatistics
  ContactProblem<2>::solve_step(const double);
  template StepStatistics
  ContactProblem<3>::solve_step(const double);
  template StepStatistics
  ContactProblem<2>::solve_with_bound(const double,
                                      const TrilinosWrappers::MPI::Vector *,
                                      const double,
                                      const bool);
  template StepStatistics
  ContactProblem<3>::solve_with_bound(const double,
                                      const TrilinosWrappers::MPI::Vector *,
                                      const double,
                                      const bool);
} // namespace hemicontact
