#include <deal.II/base/mpi.h>

#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/problem/stability.h>
#include <hemicontact/solver/projected_operator.h>

#include <cmath>

namespace hemicontact
{
  namespace
  {
    /** The branches of @p nodes from a field of the list ("branches"). */
    template <int dim>
    void
    branches_from_field(const ProblemState<dim>             &state,
                        const TrilinosWrappers::MPI::Vector &field,
                        std::vector<ContactNode<dim>>       &nodes)
    {
      TrilinosWrappers::MPI::Vector ghosted(state.locally_owned_dofs,
                                            state.locally_relevant_dofs,
                                            state.mpi_communicator);
      ghosted = field;
      for (ContactNode<dim> &node : nodes)
        {
          node.normal_branch =
            static_cast<NormalBranch>(std::lround(ghosted[node.dofs[0]]));
          node.tangential_branch =
            static_cast<TangentialBranch>(std::lround(ghosted[node.dofs[1]]));
        }
    }
  } // namespace

  template <int dim>
  void
  ContactProblem<dim>::resume(StateSource<dim> &source)
  {
    TimerOutput::Scope     t(timer, "setup");
    const CheckpointState &saved = source.read(n_steps, time_step);
    last_step_length             = saved.last_step_length;

    source.load_mesh(discretization);
    discretization.check_boundary_ids(parameters.boundary);
    setup_on_current_mesh();
    ++state_revision;
    // the state's fields by name, the memory's history sized as recorded
    // (doc/theory.md 11)
    branch_field.reinit(locally_owned_dofs, mpi_communicator);
    amg_branch_field.reinit(locally_owned_dofs, mpi_communicator);
    source.load_fields(state_fields(memory.restore(saved.memory_history)));
    branches_from_field(state(), branch_field, contact_nodes);

    step_number = saved.step_number;
    energy      = saved.energy_balance();
    update_friction_bounds(step_number * time_step);
    memory_rule_unstable =
      check_time_step_limits(state(), preconditioner, timer);
    check_convexity();
    coupled_fields.start(mechanical_view(state()),
                         linear_solver,
                         added_fields,
                         true);

    // the preconditioner as the interrupted run left it (after the checks
    // above, which build AMGs of their own, as at the run's start)
    std::vector<ContactNode<dim>> amg_nodes(contact_nodes);
    branches_from_field(state(), amg_branch_field, amg_nodes);
    ProjectedOperator<dim> op(step_matrix, locally_owned_dofs);
    for (const ContactNode<dim> &node : amg_nodes)
      if (node.locally_owned)
        op.add_node(node.dofs, nodal::free_projector(node), Tensor<2, dim>());
    preconditioner.restore(
      op, static_cast<ConstrainedAmgStatus>(saved.constrained_amg));
  }

  template void
  ContactProblem<2>::resume(StateSource<2> &);
  template void
  ContactProblem<3>::resume(StateSource<3> &);
} // namespace hemicontact
