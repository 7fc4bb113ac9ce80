#include <deal.II/base/mpi.h>

#include <hemicontact/backtracking.h>
#include <hemicontact/contact_problem.h>
#include <hemicontact/input_error.h>

#include <cmath>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    /**
     * The penalty (times the diagonal of K0) on the constrained directions
     * in the matrix of a constrained AMG: large enough for the AMG to treat
     * them as Dirichlet conditions. With a new AMG in every Newton iteration
     * over the first 15 steps of 3D r4, 1, 10 and 100 gave 6.9, 5.6 and 5.5
     * Krylov iterations per solve; 1e3 is a decade beyond where that levels
     * off.
     */
    constexpr double constraint_penalty = 1e3;

    /**
     * The share of contact nodes with a free direction that the constrained
     * AMG treats as constrained beyond which it is given up for the AMG of
     * K0: the nodal inverse that covers such directions is poor for the
     * weakly damped normal direction that stuck nodes free when they start
     * to sink in.
     */
    constexpr double constrained_amg_mismatch_limit = 0.05;

    /**
     * The Krylov solves of a Newton iteration never go below this fraction
     * of the Newton tolerance's absolute target: the margin that lets a
     * settled iteration's accurate solve end the step. Convergence is
     * always decided on the nonsmooth residual of the new iterate, so the
     * factor changes the cost, not the result. At 3D r3 / r4 and 2D r5 / r6
     * (k = 0.01), 0.5 took 6-9% fewer Krylov iterations than 0.1 with the
     * same Newton counts; 0.9 added Newton iterations at 3D r3.
     */
    constexpr double krylov_floor_fraction = 0.5;

    std::string
    format_number(const double x)
    {
      std::ostringstream s;
      s.precision(3);
      s << std::scientific << x;
      return s.str();
    }
  } // namespace

  template <int dim>
  void
  ContactProblem<dim>::compute_residual(const TrilinosWrappers::MPI::Vector &w,
                                        TrilinosWrappers::MPI::Vector &residual) const
  {
    // R = K0 w - b; K0 and b are condensed with the base constraints, so R
    // vanishes on constrained rows once constrained entries of w are zero
    step_matrix.vmult(residual, without_constrained(w));
    residual -= step_rhs;
  }

  template <int dim>
  std::vector<NodeMultipliers<dim>>
  ContactProblem<dim>::node_multipliers(
    const TrilinosWrappers::MPI::Vector &w_ghosted,
    const TrilinosWrappers::MPI::Vector &residual_ghosted) const
  {
    std::vector<NodeMultipliers<dim>> result(contact_nodes.size());
    for (unsigned int k = 0; k < contact_nodes.size(); ++k)
      {
        Tensor<1, dim> w, force;
        for (unsigned int c = 0; c < dim; ++c)
          {
            w[c]     = w_ghosted[contact_nodes[k].dofs[c]];
            force[c] = -residual_ghosted[contact_nodes[k].dofs[c]];
          }
        result[k] = NodeContact::multipliers(contact_nodes[k], w, force, *law,
                                             *friction);
      }
    return result;
  }

  template <int dim>
  double
  ContactProblem<dim>::nonsmooth_residual(
    const TrilinosWrappers::MPI::Vector &    residual,
    const std::vector<NodeMultipliers<dim>> &mult) const
  {
    // equilibrium on every free dof that is not at a contact node ...
    TrilinosWrappers::MPI::Vector free_part(residual);
    for (const ContactNode<dim> &node : contact_nodes)
      if (node.locally_owned)
        for (unsigned int c = 0; c < dim; ++c)
          free_part[node.dofs[c]] = 0;
    free_part.compress(VectorOperation::insert);
    double sum = free_part.norm_sqr();

    // ... plus the node-wise complementarity functions, as nodal forces
    double local = 0;
    for (unsigned int k = 0; k < contact_nodes.size(); ++k)
      if (contact_nodes[k].locally_owned)
        {
          const ContactNode<dim> &node = contact_nodes[k];
          const double cn =
            NodeContact::normal_complementarity(node, mult[k], *law);
          const Tensor<1, dim> ct =
            NodeContact::tangential_complementarity(node, mult[k]);
          local += node.mass * node.mass * (cn * cn + ct.norm_square());
        }
    sum += Utilities::MPI::sum(local, mpi_communicator);
    return std::sqrt(sum);
  }

  template <int dim>
  void
  ContactProblem<dim>::build_newton_constraints()
  {
    newton_constraints.clear();
    newton_constraints.reinit(locally_relevant_dofs);
    for (const ContactNode<dim> &node : contact_nodes)
      for (const auto &line :
           NodeContact::eliminate(NodeContact::constrained_directions(node)))
        {
          newton_constraints.add_line(node.dofs[line.first]);
          for (const auto &entry : line.second)
            newton_constraints.add_entry(node.dofs[line.first],
                                         node.dofs[entry.first],
                                         entry.second);
        }
    newton_constraints.merge(
      base_constraints,
      AffineConstraints<double>::MergeConflictBehavior::no_conflicts_allowed);
    newton_constraints.close();
  }

  template <int dim>
  double
  ContactProblem<dim>::nodal_energy(const TrilinosWrappers::MPI::Vector &w) const
  {
    double local = 0;
    for (const ContactNode<dim> &node : contact_nodes)
      if (node.locally_owned)
        {
          Tensor<1, dim> v;
          for (unsigned int c = 0; c < dim; ++c)
            v[c] = w[node.dofs[c]];
          local += NodeContact::energy(node, v, *law, *friction);
        }
    return Utilities::MPI::sum(local, mpi_communicator);
  }

  template <int dim>
  double
  ContactProblem<dim>::line_search(TrilinosWrappers::MPI::Vector &      w,
                                   const TrilinosWrappers::MPI::Vector &trial,
                                   TrilinosWrappers::MPI::Vector &residual,
                                   unsigned int &n_reductions)
  {
    TrilinosWrappers::MPI::Vector direction(trial);
    direction -= w;
    if (!parameters.nonlinear_solver.line_search)
      {
        w = trial;
        compute_residual(w, residual);
        return 1.;
      }

    // J_n(w + theta d) - J_n(w) = theta d.R + theta^2/2 d.K0 d + (nodal part)
    const TrilinosWrappers::MPI::Vector d = without_constrained(direction);
    TrilinosWrappers::MPI::Vector        k_d(d);
    step_matrix.vmult(k_d, d);
    const double slope     = d * residual;
    const double curvature = d * k_d;
    const double nodal_0   = nodal_energy(w);
    const double scale =
      std::abs(slope) + std::abs(curvature) + std::abs(nodal_0) + 1e-300;

    TrilinosWrappers::MPI::Vector candidate(w);
    const double theta = backtracking_step_length(
      [&](const double t) {
        candidate = w;
        candidate.add(t, direction);
        return t * slope + 0.5 * t * t * curvature + nodal_energy(candidate) -
               nodal_0;
      },
      scale, parameters.nonlinear_solver.min_step_length, n_reductions);
    w.add(theta, direction);
    // K0 is linear: R(w + theta d) = R(w) + theta K0 d
    residual.add(theta, k_d);
    return theta;
  }

  template <int dim>
  unsigned int
  ContactProblem<dim>::solve_newton_system(
    const TrilinosWrappers::MPI::Vector &    w,
    const TrilinosWrappers::MPI::Vector &    w_ghosted,
    const std::vector<NodeMultipliers<dim>> &mult,
    const double                             reduction,
    const double                             absolute_tolerance,
    TrilinosWrappers::MPI::Vector &          trial)
  {
    if (!assembles_newton_matrix())
      return solve_projected_system(w, w_ghosted, mult, reduction,
                                    absolute_tolerance, trial);

    // assembled: eliminate the contact constraints and rebuild the matrix
    {
      TimerOutput::Scope t(timer, "active set update");
      build_newton_constraints();
    }
    assemble_newton_system(w_ghosted, mult);
    TimerOutput::Scope t(timer, "linear solve");
    trial = w;
    newton_constraints.set_zero(trial);
    const unsigned int n_iterations =
      linear_solver.solve(newton_matrix, trial, newton_rhs);
    newton_constraints.distribute(trial);
    return n_iterations;
  }

  template <int dim>
  double
  ContactProblem<dim>::constrained_amg_mismatch() const
  {
    AssertDimension(amg_constrained_directions.size(), contact_nodes.size());
    unsigned int counts[2] = {0, 0}; // mismatched, all
    for (unsigned int k = 0; k < contact_nodes.size(); ++k)
      if (contact_nodes[k].locally_owned)
        {
          const Tensor<2, dim> free =
            NodeContact::free_projector(contact_nodes[k]);
          ++counts[1];
          if ((free * amg_constrained_directions[k] * free).norm() > 0.5)
            ++counts[0];
        }
    Utilities::MPI::sum(counts, mpi_communicator, counts);
    return counts[0] / std::max(1., static_cast<double>(counts[1]));
  }

  template <int dim>
  unsigned int
  ContactProblem<dim>::solve_projected_system(
    const TrilinosWrappers::MPI::Vector &    w,
    const TrilinosWrappers::MPI::Vector &    w_ghosted,
    const std::vector<NodeMultipliers<dim>> &mult,
    const double                             reduction,
    const double                             absolute_tolerance,
    TrilinosWrappers::MPI::Vector &          trial)
  {
    // the constrained quadratic problem of this iteration: minimise
    // 1/2 x.K x - g.x over range(Pi), with K = K0 + sum L_i and
    // g = b - (contact force - L_i w) at the nodes
    ProjectedOperator<dim>        op(step_matrix, locally_owned_dofs,
                              parameters.linear_solver.stiff_contact_threshold);
    TrilinosWrappers::MPI::Vector rhs(step_rhs);
    // a constrained AMG sees the constraints of the iteration it was built
    // in; free directions it treats as constrained are split off node by
    // node until too many nodes have them
    const bool rebuild = linear_solver.contact_preconditioner_is_stale();
    if (!rebuild && linear_solver.has_contact_preconditioner() &&
        constrained_amg_mismatch() > constrained_amg_mismatch_limit)
      {
        linear_solver.retire_contact_preconditioner();
        newton_matrix.clear(); // its penalised copy of K0 is not needed now
      }
    const bool amg_sees_constraints =
      !rebuild && linear_solver.has_contact_preconditioner();
    {
      TimerOutput::Scope t(timer, "active set update");
      for (unsigned int k = 0; k < contact_nodes.size(); ++k)
        if (contact_nodes[k].locally_owned)
          {
            const ContactNode<dim> &     node = contact_nodes[k];
            const NodeLinearization<dim> lin =
              NodeContact::linearize(node, mult[k], *law, *friction);
            op.add_node(node.dofs, NodeContact::free_projector(node),
                        lin.matrix,
                        amg_sees_constraints ? amg_constrained_directions[k] :
                                               Tensor<2, dim>());

            Tensor<1, dim> w_node;
            for (unsigned int c = 0; c < dim; ++c)
              w_node[c] = w_ghosted[node.dofs[c]];
            const Tensor<1, dim> g_node = lin.matrix * w_node - lin.force;
            for (unsigned int c = 0; c < dim; ++c)
              rhs[node.dofs[c]] = step_rhs[node.dofs[c]] + g_node[c];
          }
      rhs.compress(VectorOperation::insert);
      op.project(rhs);
    }

    TimerOutput::Scope t(timer, "linear solve");
    if (rebuild)
      {
        // K0 plus a penalty on the constrained directions: a copy of the
        // values and diagonal additions, no cell loop
        newton_matrix.copy_from(step_matrix);
        op.add_constraint_penalty_to(newton_matrix, constraint_penalty);
        newton_matrix.compress(VectorOperation::add);
        linear_solver.rebuild_contact_preconditioner(
          newton_matrix, [&](std::vector<double> &modes, unsigned int n) {
            op.project_out_preconditioner_constraints(modes, n);
          });
        amg_constrained_directions.assign(contact_nodes.size(),
                                          Tensor<2, dim>());
        unsigned int block = 0;
        for (unsigned int k = 0; k < contact_nodes.size(); ++k)
          if (contact_nodes[k].locally_owned)
            amg_constrained_directions[k] =
              op.preconditioner_constraints(block++);
      }
    trial = w;
    base_constraints.set_zero(trial);
    op.project(trial);
    const unsigned int n_iterations = linear_solver.solve_projected(
      op, step_matrix, trial, rhs, reduction,
      std::max(absolute_tolerance,
               parameters.linear_solver.relative_tolerance * rhs.l2_norm()));
    base_constraints.distribute(trial);
    return n_iterations;
  }

  template <int dim>
  void
  ContactProblem<dim>::count_branches(StepStatistics &stats) const
  {
    unsigned int counts[5] = {0, 0, 0, 0, 0};
    for (const ContactNode<dim> &node : contact_nodes)
      if (node.locally_owned)
        {
          ++counts[static_cast<unsigned int>(node.normal_branch)];
          ++counts[3 + static_cast<unsigned int>(node.tangential_branch)];
        }
    for (unsigned int &c : counts)
      c = Utilities::MPI::sum(c, mpi_communicator);
    stats.n_separating   = counts[0];
    stats.n_normal_stick = counts[1];
    stats.n_damped       = counts[2];
    stats.n_stick        = counts[3];
    stats.n_slip         = counts[4];
  }

  template <int dim>
  StepStatistics
  ContactProblem<dim>::solve_step()
  {
    StepStatistics stats;
    const NonlinearSolverParameters &settings = parameters.nonlinear_solver;

    TrilinosWrappers::MPI::Vector w(velocity), residual(locally_owned_dofs,
                                                        mpi_communicator);
    TrilinosWrappers::MPI::Vector w_ghosted(locally_owned_dofs,
                                            locally_relevant_dofs,
                                            mpi_communicator);
    TrilinosWrappers::MPI::Vector residual_ghosted(w_ghosted);
    TrilinosWrappers::MPI::Vector trial(w);

    const LinearSolverParameters &lin_settings = parameters.linear_solver;
    double forcing = lin_settings.maximum_forcing_term, previous_res = 0;

    const double load_norm = step_rhs.l2_norm();
    const double target =
      settings.tolerance * load_norm + settings.absolute_tolerance;

    {
      TimerOutput::Scope t(timer, "active set update");
      compute_residual(w, residual); // then kept up to date by line_search()
    }
    for (unsigned int iteration = 0;; ++iteration)
      {
        {
          TimerOutput::Scope t(timer, "active set update");
          w_ghosted        = w;
          residual_ghosted = residual;
        }
        const std::vector<NodeMultipliers<dim>> mult =
          node_multipliers(w_ghosted, residual_ghosted);

        unsigned int n_changed = 0;
        for (unsigned int k = 0; k < contact_nodes.size(); ++k)
          {
            ContactNode<dim> &node = contact_nodes[k];
            NormalBranch nb = NodeContact::normal_branch(node, mult[k], *law);
            // not in the first iteration: its "current" branches are the
            // previous step's, or the default of a new mesh
            if (settings.gradual_normal_branches && iteration > 0)
              nb = NodeContact::gradual_normal_branch(node.normal_branch, nb,
                                                      *law);
            const TangentialBranch tb =
              NodeContact::tangential_branch(node, mult[k]);
            if (node.locally_owned &&
                (nb != node.normal_branch || tb != node.tangential_branch))
              ++n_changed;
            node.normal_branch     = nb;
            node.tangential_branch = tb;
          }
        n_changed = Utilities::MPI::sum(n_changed, mpi_communicator);

        const double res = nonsmooth_residual(residual, mult);
        stats.residual   = res / std::max(load_norm, 1e-300);
        if (!std::isfinite(res))
          throw SolverFailure("the nonsmooth residual is not a finite number "
                              "(NaN or Inf) in Newton iteration " +
                              std::to_string(iteration) + ".");

        // converged: no branch changed and the real residual is small; a
        // residual far below the tolerance is accepted even if a node at a
        // branch boundary flipped its label
        if ((n_changed == 0 && res <= target) || res <= 1e-2 * target)
          {
            velocity = w;
            for (unsigned int k = 0; k < contact_nodes.size(); ++k)
              if (contact_nodes[k].locally_owned)
                for (unsigned int c = 0; c < dim; ++c)
                  contact_traction[contact_nodes[k].dofs[c]] =
                    -residual[contact_nodes[k].dofs[c]] /
                    contact_nodes[k].mass;
            contact_traction.compress(VectorOperation::insert);
            count_branches(stats);
            return stats;
          }
        if (iteration == settings.max_iterations)
          throw SolverFailure(
            "Newton did not converge in " +
            std::to_string(settings.max_iterations) +
            " iterations: relative nonsmooth residual " +
            format_number(stats.residual) + " (tolerance " +
            format_number(settings.tolerance) + "), " +
            (n_changed > 0 ?
               std::to_string(n_changed) +
                 " nodes still changing branch. Reduce the time step, raise "
                 "'nonlinear solver/max iterations', or check the convexity "
                 "warning at start-up." :
               std::string(
                 "with no node changing branch: the iteration stalled on "
                 "fixed branches, where it is a linear solve, so the "
                 "residual is limited by the accuracy of the linear solves "
                 "('linear solver/relative tolerance' = ") +
                 format_number(lin_settings.relative_tolerance) +
                 ") or by the convexity of the step. Loosen the Newton "
                 "tolerance, tighten the linear solver's, or reduce the "
                 "time step."));

        // inexact Newton: the Krylov tolerance follows the decrease of the
        // nonsmooth residual (Eisenstat-Walker, choice 2), but never asks for
        // more than the Newton tolerance needs; once no node changes branch
        // the step is smooth and is solved to the tolerance at once
        if (iteration > 0)
          {
            const double previous_forcing = forcing;
            forcing = 0.9 * std::pow(res / previous_res, 2);
            if (0.9 * previous_forcing * previous_forcing > 0.1)
              forcing = std::max(forcing,
                                 0.9 * previous_forcing * previous_forcing);
            forcing = std::min(forcing, lin_settings.maximum_forcing_term);
          }
        previous_res = res;
        const bool inexact = lin_settings.forcing_term == "eisenstat-walker";
        const bool settled =
          lin_settings.exact_solve_when_settled && n_changed == 0;
        stats.linear_iterations += solve_newton_system(
          w, w_ghosted, mult, inexact && !settled ? forcing : 0.,
          inexact ? krylov_floor_fraction * target : 0., trial);
        {
          TimerOutput::Scope t(timer, "line search");
          line_search(w, trial, residual, stats.n_damped_steps);
        }
        ++stats.newton_iterations;
      }
  }

#define HEMICONTACT_INSTANTIATE(dim)                                           \
  template void ContactProblem<dim>::compute_residual(                        \
    const TrilinosWrappers::MPI::Vector &, TrilinosWrappers::MPI::Vector &)    \
    const;                                                                     \
  template std::vector<NodeMultipliers<dim>>                                   \
  ContactProblem<dim>::node_multipliers(const TrilinosWrappers::MPI::Vector &, \
                                        const TrilinosWrappers::MPI::Vector &) \
    const;                                                                     \
  template double ContactProblem<dim>::nonsmooth_residual(                    \
    const TrilinosWrappers::MPI::Vector &,                                     \
    const std::vector<NodeMultipliers<dim>> &) const;                          \
  template void   ContactProblem<dim>::build_newton_constraints();            \
  template double ContactProblem<dim>::nodal_energy(                          \
    const TrilinosWrappers::MPI::Vector &) const;                              \
  template double ContactProblem<dim>::line_search(                           \
    TrilinosWrappers::MPI::Vector &, const TrilinosWrappers::MPI::Vector &,    \
    TrilinosWrappers::MPI::Vector &, unsigned int &);                    \
  template void           ContactProblem<dim>::count_branches(StepStatistics &) \
    const;                                                                     \
  template StepStatistics ContactProblem<dim>::solve_step();                   \
  template unsigned int   ContactProblem<dim>::solve_newton_system(           \
    const TrilinosWrappers::MPI::Vector &,                                     \
    const TrilinosWrappers::MPI::Vector &,                                     \
    const std::vector<NodeMultipliers<dim>> &, const double, const double,     \
    TrilinosWrappers::MPI::Vector &);                                          \
  template unsigned int ContactProblem<dim>::solve_projected_system(          \
    const TrilinosWrappers::MPI::Vector &,                                     \
    const TrilinosWrappers::MPI::Vector &,                                     \
    const std::vector<NodeMultipliers<dim>> &, const double, const double,     \
    TrilinosWrappers::MPI::Vector &);                                          \
  template double ContactProblem<dim>::constrained_amg_mismatch() const;

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
