#include <deal.II/base/mpi.h>

#include <hemicontact/solver/active_set_newton.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/model/contact_step.h>

namespace hemicontact
{
  template <int dim>
  void
  ContactProblem<dim>::count_branches(StepStatistics &stats) const
  {
    // one count per branch, summed over the ranks
    auto count = [&](const auto branch, const auto node_branch) {
      unsigned int n = 0;
      for (const ContactNode<dim> &node : contact_nodes)
        if (node.locally_owned && node_branch(node) == branch)
          ++n;
      return Utilities::MPI::sum(n, mpi_communicator);
    };
    const auto normal = [](const ContactNode<dim> &node) {
      return node.normal_branch;
    };
    const auto tangential = [](const ContactNode<dim> &node) {
      return node.tangential_branch;
    };
    stats.n_separating   = count(NormalBranch::separating, normal);
    stats.n_normal_stick = count(NormalBranch::stick, normal);
    stats.n_damped       = count(NormalBranch::damped, normal);
    stats.n_stick        = count(TangentialBranch::stick, tangential);
    stats.n_slip         = count(TangentialBranch::slip, tangential);
  }

  template <int dim>
  StepStatistics
  ContactProblem<dim>::solve_step()
  {
    ContactStep<dim> step({step_matrix, step_rhs, base_constraints,
                           locally_owned_dofs, locally_relevant_dofs,
                           contact_nodes, *law, *friction, linear_solver,
                           preconditioner, timer, mpi_communicator},
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

    StepStatistics stats;
    stats.newton_iterations      = report.newton_iterations;
    stats.linear_iterations      = report.linear_iterations;
    stats.line_search_reductions = report.line_search_reductions;
    stats.residual               = report.relative_residual;
    count_branches(stats);
    return stats;
  }

  template void ContactProblem<2>::count_branches(StepStatistics &) const;
  template void ContactProblem<3>::count_branches(StepStatistics &) const;
  template StepStatistics ContactProblem<2>::solve_step();
  template StepStatistics ContactProblem<3>::solve_step();
} // namespace hemicontact
