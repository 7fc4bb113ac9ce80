#include <hemicontact/state/field_transfer.h>

#include <algorithm>

namespace hemicontact
{
  template <int dim>
  FieldTransfer<dim>::FieldTransfer(const std::vector<StateField<dim>> &fields)
  {
    for (const auto &[space, names] :
         field_names_by_space(fields, [](const StateField<dim> &f) {
           return f.transferred;
         }))
      {
        Group group;
        group.names = names;
        for (const std::string &name : names)
          {
            const StateField<dim> &f =
              *std::find_if(fields.begin(),
                            fields.end(),
                            [&](const StateField<dim> &g) {
                              return g.name == name;
                            });
            group.dof_handler = f.space->dof_handler;
            group.old_fields.emplace_back(*f.space->owned,
                                          *f.space->relevant,
                                          f.vector->get_mpi_communicator());
            group.old_fields.back() = *f.vector;
          }
        groups.push_back(std::move(group));
      }
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector &
  FieldTransfer<dim>::old_field(const std::string &name)
  {
    for (Group &group : groups)
      for (unsigned int i = 0; i < group.names.size(); ++i)
        if (group.names[i] == name)
          return group.old_fields[i];
    AssertThrow(false, ExcMessage("no transferred field '" + name + "'"));
    return groups[0].old_fields[0];
  }

  template <int dim>
  void
  FieldTransfer<dim>::prepare()
  {
    for (Group &group : groups)
      {
        std::vector<const TrilinosWrappers::MPI::Vector *> old;
        for (const TrilinosWrappers::MPI::Vector &v : group.old_fields)
          old.push_back(&v);
        group.transfer = std::make_unique<Transfer>(*group.dof_handler);
        group.transfer->prepare_for_coarsening_and_refinement(old);
      }
  }

  template <int dim>
  void
  FieldTransfer<dim>::interpolate(const std::vector<StateField<dim>> &fields)
  {
    for (Group &group : groups)
      {
        std::vector<TrilinosWrappers::MPI::Vector *> targets;
        for (const std::string &name : group.names)
          {
            const auto it = std::find_if(fields.begin(),
                                         fields.end(),
                                         [&](const StateField<dim> &f) {
                                           return f.name == name;
                                         });
            AssertThrow(it != fields.end(),
                        ExcMessage("the state on the new mesh has no field '" +
                                   name + "'"));
            targets.push_back(it->vector);
          }
        group.transfer->interpolate(targets);
      }
  }

  template <int dim>
  void
  distribute_constraints(const std::vector<StateField<dim>> &fields)
  {
    for (const StateField<dim> &f : fields)
      if (f.constrained)
        f.space->constraints->distribute(*f.vector);
  }

  template class FieldTransfer<2>;
  template class FieldTransfer<3>;
  template void
  distribute_constraints(const std::vector<StateField<2>> &);
  template void
  distribute_constraints(const std::vector<StateField<3>> &);
} // namespace hemicontact
