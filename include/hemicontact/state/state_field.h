#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /** How the values of a field of the state sit on its degrees of freedom. */
  enum class FieldLayout
  {
    /** dim components at every node, as w and u (FE_Q(1)^dim). */
    displacement_like,
    /** one value at every node (FE_Q(1) or FE_SimplexP(1)). */
    scalar_nodal,
    /**
     * values at the contact nodes only, in the displacement's layout (a
     * node's value at its first component, or its vector at its dim
     * components), zero elsewhere.
     */
    contact_node
  };

  /**
   * A finite element space of the state: a DoFHandler with its owned and
   * relevant index sets and its hanging-node constraints (distributed
   * after a mesh transfer for the fields that ask for it).
   */
  template <int dim>
  struct FieldSpace
  {
    /** The name a checkpoint records ("displacement" for w and u's). */
    std::string                      name;
    const DoFHandler<dim>           *dof_handler = nullptr;
    const IndexSet                  *owned       = nullptr;
    const IndexSet                  *relevant    = nullptr;
    const AffineConstraints<double> *constraints = nullptr;
  };

  /**
   * One named field of the state (doc/extending.md, "The state"): its
   * vector (owned entries) on a FieldSpace, and which consumers take it.
   */
  template <int dim>
  struct StateField
  {
    /** The name a checkpoint stores it by and the output writes it as. */
    std::string                    name;
    FieldLayout                    layout = FieldLayout::displacement_like;
    const FieldSpace<dim>         *space  = nullptr;
    TrilinosWrappers::MPI::Vector *vector = nullptr;
    /** Stored in a checkpoint and read back on resume. */
    bool saved = true;
    /** Moved to an adapted mesh by interpolation. */
    bool transferred = true;
    /** Hanging-node constraints distributed after a transfer. */
    bool constrained = false;
    /** Written to the solution and nodal output (as a nodal field). */
    bool written = false;
  };

  /**
   * The names of the fields of @p fields that @p keep selects, grouped
   * by space in the order of first appearance: the layout a checkpoint
   * records.
   */
  template <int dim, typename Predicate>
  std::vector<std::pair<std::string, std::vector<std::string>>>
  field_names_by_space(const std::vector<StateField<dim>> &fields,
                       const Predicate                    &keep)
  {
    std::vector<std::pair<std::string, std::vector<std::string>>> spaces;
    for (const StateField<dim> &f : fields)
      if (keep(f))
        {
          auto it = spaces.begin();
          while (it != spaces.end() && it->first != f.space->name)
            ++it;
          if (it == spaces.end())
            it = spaces.insert(spaces.end(), {f.space->name, {}});
          it->second.push_back(f.name);
        }
    return spaces;
  }
} // namespace hemicontact
