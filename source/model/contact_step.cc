#include <deal.II/base/mpi.h>

#include <hemicontact/model/contact_step.h>

#include <algorithm>
#include <cmath>

namespace hemicontact
{
  template <int dim>
  ContactStep<dim>::ContactStep(const StepSystem<dim> &system,
                                const Parameters      &parameters)
    : system(system)
    , solver_type(parameters.linear_solver.type)
    , linear_relative_tolerance(parameters.linear_solver.relative_tolerance)
    , gradual_normal_branches(parameters.solver_tuning.gradual_normal_branches)
    , w_ghosted(system.locally_owned_dofs,
                system.locally_relevant_dofs,
                system.mpi_communicator)
    , residual_ghosted(w_ghosted)
  {}

  TrilinosWrappers::MPI::Vector
  without_constrained(const TrilinosWrappers::MPI::Vector &v,
                      const AffineConstraints<double>     &constraints)
  {
    TrilinosWrappers::MPI::Vector result(v);
    constraints.set_zero(result);
    return result;
  }

  template <int dim>
  void
  ContactStep<dim>::residual(const VectorType &w, VectorType &residual) const
  {
    TimerOutput::Scope t(system.timer, "active set update");
    // K0 and b are condensed with the base constraints, so R vanishes on
    // constrained rows once constrained entries of w are zero
    system.step_matrix.vmult(residual,
                             without_constrained(w, system.base_constraints));
    residual -= system.step_rhs;
  }

  template <int dim>
  double
  ContactStep<dim>::load_norm() const
  {
    return system.step_rhs.l2_norm();
  }

  template <int dim>
  double
  ContactStep<dim>::operator_norm(const VectorType &residual) const
  {
    VectorType k0_w(residual);
    k0_w += system.step_rhs;
    return k0_w.l2_norm();
  }

  template <int dim>
  unsigned int
  ContactStep<dim>::update_branches(const VectorType  &w,
                                    const VectorType  &residual,
                                    const unsigned int iteration)
  {
    {
      TimerOutput::Scope t(system.timer, "active set update");
      w_ghosted        = w;
      residual_ghosted = residual;
    }
    std::vector<ContactNode<dim>> &nodes = system.contact_nodes;
    node_states.resize(nodes.size());
    unsigned int n_changed = 0;
    for (unsigned int k = 0; k < nodes.size(); ++k)
      {
        ContactNode<dim> &node = nodes[k];
        Tensor<1, dim>    velocity, force;
        for (unsigned int c = 0; c < dim; ++c)
          {
            velocity[c] = w_ghosted[node.dofs[c]];
            force[c]    = -residual_ghosted[node.dofs[c]];
          }
        node_states[k] =
          nodal::state(node, velocity, force, system.law, system.friction);

        const nodal::NormalHold hold =
          nodal::normal_hold(node, node_states[k], system.law);
        NormalBranch nb = hold.branch;
        // held values in w_nu, the hold points in the law's argument
        node.held_value = hold.value + node.law_offset;
        // not in the first iteration: its "current" branches are the
        // previous step's, or the default of a new mesh; not behind a wall
        // at or below zero, where w_nu = 0 is out of bounds
        if (gradual_normal_branches && iteration > 0 &&
            node.upper_limit - node.law_offset > 0)
          nb = nodal::gradual_normal_branch(node.normal_branch, nb, system.law);
        if (nb == NormalBranch::stick)
          node.held_value = node.law_offset;
        const TangentialBranch tb =
          nodal::tangential_branch(node, node_states[k]);
        if (node.locally_owned &&
            (nb != node.normal_branch || tb != node.tangential_branch))
          ++n_changed;
        node.normal_branch     = nb;
        node.tangential_branch = tb;
      }
    return Utilities::MPI::sum(n_changed, system.mpi_communicator);
  }

  template <int dim>
  double
  ContactStep<dim>::nonsmooth_residual(const VectorType &residual) const
  {
    // equilibrium on every free dof that is not at a contact node ...
    VectorType free_part(residual);
    for (const ContactNode<dim> &node : system.contact_nodes)
      if (node.locally_owned)
        for (unsigned int c = 0; c < dim; ++c)
          free_part[node.dofs[c]] = 0;
    free_part.compress(VectorOperation::insert);
    double sum = free_part.norm_sqr();

    // ... plus the node-wise complementarity functions, as nodal forces
    double local = 0;
    for (unsigned int k = 0; k < system.contact_nodes.size(); ++k)
      if (system.contact_nodes[k].locally_owned)
        {
          const ContactNode<dim> &node = system.contact_nodes[k];
          const double            cn =
            nodal::normal_complementarity(node, node_states[k], system.law);
          const Tensor<1, dim> ct =
            nodal::tangential_complementarity(node, node_states[k]);
          local += node.mass * node.mass * (cn * cn + ct.norm_square());
        }
    sum += Utilities::MPI::sum(local, system.mpi_communicator);
    return std::sqrt(sum);
  }

  template <int dim>
  unsigned int
  ContactStep<dim>::solve_linearized(const VectorType &w,
                                     const double      reduction,
                                     const double      absolute_tolerance,
                                     VectorType       &trial)
  {
    // the constrained quadratic problem of this iteration: minimise
    // 1/2 x.K x - g.x over range(Pi), with K = K0 + sum L_i and
    // g = b - (contact force - L_i w) at the nodes
    ProjectedOperator<dim> op(system.step_matrix, system.locally_owned_dofs);
    VectorType             rhs(system.step_rhs);
    {
      TimerOutput::Scope t(system.timer, "active set update");
      for (unsigned int k = 0; k < system.contact_nodes.size(); ++k)
        if (system.contact_nodes[k].locally_owned)
          {
            const ContactNode<dim>      &node = system.contact_nodes[k];
            const NodeLinearization<dim> lin  = nodal::linearize(
              node, node_states[k], system.law, system.friction);
            op.add_node(node.dofs, nodal::free_projector(node), lin.matrix);

            Tensor<1, dim> w_node;
            for (unsigned int c = 0; c < dim; ++c)
              w_node[c] = w_ghosted[node.dofs[c]];
            const Tensor<1, dim> g_node = lin.matrix * w_node - lin.force;
            for (unsigned int c = 0; c < dim; ++c)
              rhs[node.dofs[c]] = system.step_rhs[node.dofs[c]] + g_node[c];
          }
      rhs.compress(VectorOperation::insert);
    }
    // a node held at w_nu = r != 0: the minimiser is x0 + y, y in
    // range(Pi), with Pi K Pi y = Pi (g - K x0); the nodal tangents L_i act
    // in the tangent plane only, so K x0 = K0 x0
    VectorType x0(system.step_rhs);
    const bool inhomogeneous = held_offset(x0);
    // the scale of the Krylov tolerance: the load's part of the right-hand
    // side, not K0 x0, which can dwarf it (stiff K0, many held nodes)
    double rhs_scale = 0;
    if (inhomogeneous)
      {
        VectorType projected(rhs);
        op.project(projected);
        rhs_scale = projected.l2_norm();
        VectorType k_x0(x0);
        system.step_matrix.vmult(k_x0, x0);
        rhs -= k_x0;
      }
    op.project(rhs);
    if (!inhomogeneous)
      rhs_scale = rhs.l2_norm();

    TimerOutput::Scope t(system.timer, "linear solve");
    unsigned int       n_iterations = 1;
    if (solver_type == LinearSolverType::direct)
      {
        TrilinosWrappers::SparseMatrix matrix;
        op.assemble(matrix);
        system.linear_solver.solve_direct(matrix, trial, rhs);
      }
    else
      {
        system.preconditioner.prepare(op);
        trial = w;
        system.base_constraints.set_zero(trial);
        op.project(trial);
        n_iterations = system.linear_solver.solve_cg(
          op,
          system.preconditioner,
          trial,
          rhs,
          reduction,
          std::max(absolute_tolerance, linear_relative_tolerance * rhs_scale));
      }
    if (inhomogeneous)
      trial += x0;
    system.base_constraints.distribute(trial);
    return n_iterations;
  }

  template <int dim>
  bool
  ContactStep<dim>::held_offset(VectorType &x0) const
  {
    x0           = 0;
    bool any_set = false;
    for (const ContactNode<dim> &node : system.contact_nodes)
      if (node.locally_owned && node.held_value != 0 &&
          (node.normal_branch == NormalBranch::stick ||
           node.normal_branch == NormalBranch::breakpoint ||
           node.normal_branch == NormalBranch::wall))
        {
          for (unsigned int c = 0; c < dim; ++c)
            x0[node.dofs[c]] = node.held_value * node.normal[c];
          any_set = true;
        }
    x0.compress(VectorOperation::insert);
    return Utilities::MPI::logical_or(any_set, system.mpi_communicator);
  }

  template <int dim>
  void
  ContactStep<dim>::make_feasible(VectorType &w) const
  {
    bool any_wall = false;
    for (const ContactNode<dim> &node : system.contact_nodes)
      any_wall = any_wall || std::isfinite(node.upper_limit);
    if (!Utilities::MPI::logical_or(any_wall, system.mpi_communicator))
      return;
    for (const ContactNode<dim> &node : system.contact_nodes)
      if (node.locally_owned && std::isfinite(node.upper_limit))
        {
          const Tensor<1, dim> v      = nodal_vector(node, w);
          const double         excess = v * node.normal - node.upper_limit;
          if (excess > 0)
            for (unsigned int c = 0; c < dim; ++c)
              w[node.dofs[c]] = v[c] - excess * node.normal[c];
        }
    w.compress(VectorOperation::insert);
  }

  template <int dim>
  void
  ContactStep<dim>::apply_quadratic(const VectorType &d, VectorType &k_d) const
  {
    system.step_matrix.vmult(k_d,
                             without_constrained(d, system.base_constraints));
  }

  template <int dim>
  double
  ContactStep<dim>::nodal_energy(const VectorType &w) const
  {
    double local = 0;
    for (const ContactNode<dim> &node : system.contact_nodes)
      if (node.locally_owned)
        {
          Tensor<1, dim> v;
          for (unsigned int c = 0; c < dim; ++c)
            v[c] = w[node.dofs[c]];
          local += nodal::energy(node, v, system.law, system.friction);
        }
    return Utilities::MPI::sum(local, system.mpi_communicator);
  }

  ActiveSetNewton::Settings
  newton_settings(const Parameters &parameters)
  {
    const SolverTuning       &tuning = parameters.solver_tuning;
    ActiveSetNewton::Settings settings;
    settings.tolerance           = parameters.nonlinear_solver.tolerance;
    settings.roundoff_tolerance  = tuning.roundoff_tolerance;
    settings.max_iterations      = parameters.nonlinear_solver.max_iterations;
    settings.line_search         = parameters.nonlinear_solver.line_search;
    settings.minimum_step_length = tuning.minimum_step_length;
    settings.eisenstat_walker =
      parameters.linear_solver.forcing_term == ForcingTerm::eisenstat_walker;
    settings.maximum_forcing_term     = tuning.maximum_forcing_term;
    settings.exact_solve_when_settled = tuning.exact_solve_when_settled;
    settings.krylov_floor_fraction    = tuning.krylov_floor_fraction;
    settings.linear_relative_tolerance =
      parameters.linear_solver.relative_tolerance;
    return settings;
  }

  template class ContactStep<2>;
  template class ContactStep<3>;
} // namespace hemicontact
