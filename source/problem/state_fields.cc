/**
 * The state of the problem as one list of named fields (doc/extending.md,
 * "The state"): what checkpoints store, a resume reads, an adaptation
 * moves and the output writes.
 */
#include <hemicontact/problem/contact_problem.h>

#include <cmath>

namespace hemicontact
{
  namespace
  {
    /**
     * The branches of the owned nodes of @p nodes as a field: the normal
     * branch at a node's first dof, the tangential at its second.
     */
    template <int dim>
    void
    branches_to_field(const std::vector<ContactNode<dim>> &nodes,
                      TrilinosWrappers::MPI::Vector       &field)
    {
      for (const ContactNode<dim> &node : nodes)
        if (node.locally_owned)
          {
            field[node.dofs[0]] = static_cast<double>(node.normal_branch);
            field[node.dofs[1]] = static_cast<double>(node.tangential_branch);
          }
      field.compress(VectorOperation::insert);
    }

    /**
     * @p nodes with, at the owned ones, the branches whose constrained
     * directions the constrained AMG of @p preconditioner was built for
     * (its operators' nodes are the owned nodes in this order); unchanged
     * if it has none.
     */
    template <int dim>
    std::vector<ContactNode<dim>>
    constrained_amg_branches(const std::vector<ContactNode<dim>> &nodes,
                             const StepPreconditioner<dim> &preconditioner)
    {
      std::vector<ContactNode<dim>>      result(nodes);
      const std::vector<Tensor<2, dim>> &directions =
        preconditioner.constrained_directions();
      if (directions.empty())
        return result;
      unsigned int i = 0;
      for (ContactNode<dim> &node : result)
        if (node.locally_owned)
          {
            AssertIndexRange(i, directions.size());
            // sum e e over nodal::constrained_directions(): nu nu for normal
            // stick, the tangent plane's projector for tangential stick
            const double normal_part =
              node.normal * (directions[i] * node.normal);
            node.normal_branch     = normal_part > 0.5 ? NormalBranch::stick :
                                                         NormalBranch::separating;
            node.tangential_branch = trace(directions[i]) - normal_part > 0.5 ?
                                       TangentialBranch::stick :
                                       TangentialBranch::slip;
            ++i;
          }
      AssertDimension(i, directions.size());
      return result;
    }
  } // namespace

  template <int dim>
  std::vector<StateField<dim>>
  ContactProblem<dim>::state_fields(
    const std::vector<TrilinosWrappers::MPI::Vector *> &history)
  {
    using L                      = FieldLayout;
    const FieldSpace<dim> *u     = &displacement_space;
    const auto             entry = [u](const std::string             &name,
                           const L                        layout,
                           TrilinosWrappers::MPI::Vector *vector,
                           const bool                     transferred,
                           const bool                     constrained,
                           const bool                     written) {
      StateField<dim> f;
      f.name        = name;
      f.layout      = layout;
      f.space       = u;
      f.vector      = vector;
      f.transferred = transferred;
      f.constrained = constrained;
      f.written     = written;
      return f;
    };
    // name, layout, vector, transferred, constrained, written: every field
    // is saved; w_{n-1} is w_n after a transfer (the trend restarts), the
    // branches are recomputed in the first Newton iteration on a new mesh
    std::vector<StateField<dim>> fields{
      entry("velocity", L::displacement_like, &velocity, true, true, true),
      entry(
        "displacement", L::displacement_like, &displacement, true, true, true),
      // p_nu of a friction bound in the next step
      entry("contact_traction",
            L::contact_node,
            &contact_traction,
            true,
            false,
            true),
      entry("old_velocity",
            L::displacement_like,
            &old_velocity,
            false,
            false,
            false),
      // the active set of the last converged state, and the one the
      // constrained AMG was built for
      entry("branches", L::contact_node, &branch_field, false, false, false),
      entry("amg_branches",
            L::contact_node,
            &amg_branch_field,
            false,
            false,
            false)};
    // the memory's history (doc/theory.md 11): its vectors in its order
    for (unsigned int i = 0; i < history.size(); ++i)
      fields.push_back(entry("memory/" + std::to_string(i),
                             L::displacement_like,
                             history[i],
                             true,
                             false,
                             false));
    added_fields.append_to(fields);
    return fields;
  }

  template <int dim>
  std::vector<StateField<dim>>
  ContactProblem<dim>::fields() const
  {
    // the branches into their fields (scratch vectors, as they are saved)
    branch_field.reinit(locally_owned_dofs, mpi_communicator);
    amg_branch_field.reinit(locally_owned_dofs, mpi_communicator);
    branches_to_field(contact_nodes, branch_field);
    branches_to_field(constrained_amg_branches(contact_nodes, preconditioner),
                      amg_branch_field);
    std::vector<TrilinosWrappers::MPI::Vector *> history;
    for (const TrilinosWrappers::MPI::Vector *v : memory.saved_fields())
      history.push_back(const_cast<TrilinosWrappers::MPI::Vector *>(v));
    // the list is one: a const view of it (the fields are only read)
    return const_cast<ContactProblem<dim> *>(this)->state_fields(history);
  }

  template <int dim>
  void
  ContactProblem<dim>::add_field(std::unique_ptr<CoupledField<dim>> field)
  {
    AssertThrow(field->energy_terms().empty(),
                ExcMessage("A coupled field with energy terms is a kind of "
                           "the registry (fields/coupled_field_registry.cc)."));
    std::vector<std::string> taken;
    for (const StateField<dim> &f : state_fields({}))
      taken.push_back(f.name);
    coupled_fields.add(std::move(field),
                       coupled_energy_terms().size(),
                       discretization.is_simplex(),
                       added_fields,
                       taken);
  }

#define HEMICONTACT_INSTANTIATE(dim)                                         \
  template std::vector<StateField<dim>> ContactProblem<dim>::state_fields(   \
    const std::vector<TrilinosWrappers::MPI::Vector *> &);                   \
  template std::vector<StateField<dim>> ContactProblem<dim>::fields() const; \
  template void                         ContactProblem<dim>::add_field(      \
    std::unique_ptr<CoupledField<dim>>);
  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
