#include <deal.II/base/mpi.h>

#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/solver/projected_operator.h>

namespace hemicontact
{
  template <int dim>
  void
  ContactProblem<dim>::resume(StateSource<dim> &source)
  {
    TimerOutput::Scope     t(timer, "setup");
    const CheckpointState &state = source.read(n_steps, time_step);
    last_step_length             = state.last_step_length;

    source.load_mesh(discretization);
    discretization.check_boundary_ids(parameters.boundary);
    setup_on_current_mesh();
    ++state_revision;
    // the state's fields by name, the memory's history sized as recorded
    // (doc/theory.md 11)
    branch_field.reinit(locally_owned_dofs, mpi_communicator);
    amg_branch_field.reinit(locally_owned_dofs, mpi_communicator);
    source.load_fields(state_fields(memory.restore(state.memory_history)));
    branches_from_field(branch_field, contact_nodes);

    step_number = state.step_number;
    energy      = state.energy_balance();
    update_friction_bounds(step_number * time_step);
    check_time_step_stability();
    check_memory_stability();
    check_convexity();

    // the preconditioner as the interrupted run left it (after the checks
    // above, which build AMGs of their own, as at the run's start)
    std::vector<ContactNode<dim>> amg_nodes(contact_nodes);
    branches_from_field(amg_branch_field, amg_nodes);
    ProjectedOperator<dim> op(step_matrix, locally_owned_dofs);
    for (const ContactNode<dim> &node : amg_nodes)
      if (node.locally_owned)
        op.add_node(node.dofs, nodal::free_projector(node), Tensor<2, dim>());
    preconditioner.restore(
      op, static_cast<ConstrainedAmgStatus>(state.constrained_amg));
  }

  template void
  ContactProblem<2>::resume(StateSource<2> &);
  template void
  ContactProblem<3>::resume(StateSource<3> &);
} // namespace hemicontact
