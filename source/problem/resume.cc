#include <deal.II/base/mpi.h>

#include <hemicontact/output/checkpointer.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/solver/projected_operator.h>

#include <cmath>

namespace hemicontact
{
  namespace
  {
    /** The branches of every node of @p nodes from branches_to_field(). */
    template <int dim>
    void
    branches_from_field(const TrilinosWrappers::MPI::Vector &field,
                        const IndexSet                      &owned,
                        const IndexSet                      &relevant,
                        std::vector<ContactNode<dim>>       &nodes)
    {
      TrilinosWrappers::MPI::Vector ghosted(owned,
                                            relevant,
                                            field.get_mpi_communicator());
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
  ContactProblem<dim>::resume(Checkpointer<dim> &checkpointer)
  {
    TimerOutput::Scope     t(timer, "setup");
    const CheckpointState &state = checkpointer.read(n_steps, time_step);
    last_step_length             = state.last_step_length;

    checkpointer.load_mesh(discretization);
    discretization.check_boundary_ids(parameters.boundary);
    setup_on_current_mesh();
    TrilinosWrappers::MPI::Vector branches(locally_owned_dofs,
                                           mpi_communicator);
    TrilinosWrappers::MPI::Vector amg_branches(locally_owned_dofs,
                                               mpi_communicator);
    std::vector<TrilinosWrappers::MPI::Vector *> fields{&velocity,
                                                        &displacement,
                                                        &branches,
                                                        &old_velocity,
                                                        &amg_branches,
                                                        &contact_traction};
    // the memory's history, its vectors after those (doc/theory.md 11)
    for (TrilinosWrappers::MPI::Vector *v :
         memory.restore(state.memory_history))
      fields.push_back(v);
    checkpointer.load_fields(dof_handler, locally_owned_dofs, fields);
    branches_from_field(branches,
                        locally_owned_dofs,
                        locally_relevant_dofs,
                        contact_nodes);

    step_number = state.step_number;
    energy      = state.energy_balance();
    update_friction_bounds(step_number * time_step);
    check_time_step_stability();
    check_memory_stability();
    check_convexity();

    // the preconditioner as the interrupted run left it (after the checks
    // above, which build AMGs of their own, as at the run's start)
    std::vector<ContactNode<dim>> amg_nodes(contact_nodes);
    branches_from_field(amg_branches,
                        locally_owned_dofs,
                        locally_relevant_dofs,
                        amg_nodes);
    ProjectedOperator<dim> op(step_matrix, locally_owned_dofs);
    for (const ContactNode<dim> &node : amg_nodes)
      if (node.locally_owned)
        op.add_node(node.dofs, nodal::free_projector(node), Tensor<2, dim>());
    preconditioner.restore(
      op, static_cast<ConstrainedAmgStatus>(state.constrained_amg));
  }

  template void
  ContactProblem<2>::resume(Checkpointer<2> &);
  template void
  ContactProblem<3>::resume(Checkpointer<3> &);
} // namespace hemicontact
