#pragma once

#include <deal.II/base/function.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>

#include <hemicontact/state/state_field.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * A field that a model or a test adds to the state in one entry
   * (doc/extending.md, "The state"): its name, its finite element (a space
   * of its own, beside w and u's) and which consumers take it.
   */
  template <int dim>
  struct FieldDefinition
  {
    std::string                               name;
    std::shared_ptr<const FiniteElement<dim>> element;
    /** Its value at t = 0, interpolated (nullptr: zero). */
    std::shared_ptr<const Function<dim>> initial_value;
    FieldLayout                          layout = FieldLayout::scalar_nodal;
    bool                                 saved  = true;
    bool                                 transferred = true;
    bool                                 written     = true;
  };

  /**
   * The added fields of the state, each on a DoFHandler of its own: the
   * space is set up on the problem's mesh with it (dofs, index sets,
   * hanging-node constraints), the vector starts at zero, and the
   * StateField entries join the state's list, so that checkpoints,
   * resume, adaptation and the output take them as they take w and u.
   */
  template <int dim>
  class AddedFields
  {
  public:
    /**
     * Add @p definition; throws InputError if its name is taken (by
     * @p reserved, the built-in fields' names, or an added field).
     */
    void
    add(const FieldDefinition<dim>     &definition,
        const std::vector<std::string> &reserved);

    /** Dofs, index sets, constraints on @p mesh; every vector zero. */
    void
    reinit(const Triangulation<dim> &mesh, MPI_Comm comm);

    /** Every vector its initial value (the start of a run, t = 0). */
    void
    initialize(const Mapping<dim> &mapping);

    /** Append the entries of the added fields to @p fields. */
    void
    append_to(std::vector<StateField<dim>> &fields);

    /** The vector (owned entries) of the added field @p name. */
    TrilinosWrappers::MPI::Vector &
    vector(const std::string &name);
    const TrilinosWrappers::MPI::Vector &
    vector(const std::string &name) const;

    /** The space of the added field @p name. */
    const FieldSpace<dim> &
    space(const std::string &name) const;

    /** Bytes held by the vectors. */
    std::size_t
    memory_consumption() const;

  private:
    struct Entry
    {
      FieldDefinition<dim>             definition;
      std::unique_ptr<DoFHandler<dim>> dof_handler;
      IndexSet                         owned;
      IndexSet                         relevant;
      AffineConstraints<double>        constraints;
      TrilinosWrappers::MPI::Vector    vector;
      FieldSpace<dim>                  space;
    };

    const Entry &
    find(const std::string &name) const;

    std::vector<std::unique_ptr<Entry>> entries;
  };
} // namespace hemicontact
