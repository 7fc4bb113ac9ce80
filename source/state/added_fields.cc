#include <deal.II/dofs/dof_tools.h>
#include <deal.II/numerics/vector_tools_interpolate.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/state/added_fields.h>

#include <algorithm>

namespace hemicontact
{
  template <int dim>
  void
  AddedFields<dim>::add(const FieldDefinition<dim>     &definition,
                        const std::vector<std::string> &reserved)
  {
    const std::string &name = definition.name;
    const bool         taken =
      std::find(reserved.begin(), reserved.end(), name) != reserved.end() ||
      std::any_of(entries.begin(), entries.end(), [&](const auto &e) {
        return e->definition.name == name;
      });
    require(!name.empty() && !taken && definition.element != nullptr,
            "state: a field '" + name + "' cannot be added: " +
              (name.empty() ? "it has no name" :
               taken        ? "the state has a field of that name" :
                              "it has no finite element") +
              ".");
    auto entry        = std::make_unique<Entry>();
    entry->definition = definition;
    entries.push_back(std::move(entry));
  }

  template <int dim>
  void
  AddedFields<dim>::reinit(const Triangulation<dim> &mesh, MPI_Comm comm)
  {
    for (const std::unique_ptr<Entry> &e : entries)
      {
        // a new mesh object (a resume builds one), or the same one adapted
        if (!e->dof_handler || &e->dof_handler->get_triangulation() != &mesh)
          e->dof_handler = std::make_unique<DoFHandler<dim>>(mesh);
        e->dof_handler->distribute_dofs(*e->definition.element);
        e->owned    = e->dof_handler->locally_owned_dofs();
        e->relevant = DoFTools::extract_locally_relevant_dofs(*e->dof_handler);
        e->constraints.clear();
        e->constraints.reinit(e->relevant);
        DoFTools::make_hanging_node_constraints(*e->dof_handler,
                                                e->constraints);
        e->constraints.close();
        e->vector.reinit(e->owned, comm);
        e->space = {e->definition.name,
                    e->dof_handler.get(),
                    &e->owned,
                    &e->relevant,
                    &e->constraints};
      }
  }

  template <int dim>
  void
  AddedFields<dim>::initialize(const Mapping<dim> &mapping)
  {
    for (const std::unique_ptr<Entry> &e : entries)
      {
        e->vector = 0;
        if (e->definition.initial_value)
          {
            VectorTools::interpolate(mapping,
                                     *e->dof_handler,
                                     *e->definition.initial_value,
                                     e->vector);
            e->constraints.distribute(e->vector);
          }
      }
  }

  template <int dim>
  void
  AddedFields<dim>::append_to(std::vector<StateField<dim>> &fields)
  {
    for (const std::unique_ptr<Entry> &e : entries)
      {
        const FieldDefinition<dim> &d = e->definition;
        StateField<dim>             f;
        f.name        = d.name;
        f.layout      = d.layout;
        f.space       = &e->space;
        f.vector      = &e->vector;
        f.saved       = d.saved;
        f.transferred = d.transferred;
        f.constrained = true;
        f.written     = d.written;
        fields.push_back(f);
      }
  }

  template <int dim>
  const typename AddedFields<dim>::Entry &
  AddedFields<dim>::find(const std::string &name) const
  {
    const auto it =
      std::find_if(entries.begin(), entries.end(), [&](const auto &e) {
        return e->definition.name == name;
      });
    AssertThrow(it != entries.end(),
                ExcMessage("the state has no added field '" + name + "'"));
    return **it;
  }

  template <int dim>
  TrilinosWrappers::MPI::Vector &
  AddedFields<dim>::vector(const std::string &name)
  {
    return const_cast<Entry &>(find(name)).vector;
  }

  template <int dim>
  const TrilinosWrappers::MPI::Vector &
  AddedFields<dim>::vector(const std::string &name) const
  {
    return find(name).vector;
  }

  template <int dim>
  const FieldSpace<dim> &
  AddedFields<dim>::space(const std::string &name) const
  {
    return find(name).space;
  }

  template <int dim>
  std::size_t
  AddedFields<dim>::memory_consumption() const
  {
    std::size_t bytes = 0;
    for (const std::unique_ptr<Entry> &e : entries)
      bytes += e->vector.memory_consumption();
    return bytes;
  }

  template class AddedFields<2>;
  template class AddedFields<3>;
} // namespace hemicontact
