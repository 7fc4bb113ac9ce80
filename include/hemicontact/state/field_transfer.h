#pragma once

#include <deal.II/distributed/solution_transfer.h>

#include <hemicontact/state/state_field.h>

#include <memory>
#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * The fields of the state that move to an adapted mesh (those marked
   * 'transferred'), one parallel::distributed::SolutionTransfer per space:
   * ghosted copies on the old mesh, interpolated into the fields of the
   * same names once the spaces are set up on the new one. Collective.
   */
  template <int dim>
  class FieldTransfer
  {
  public:
    /** Ghosted copies of the transferred fields of @p fields. */
    explicit FieldTransfer(const std::vector<StateField<dim>> &fields);

    /**
     * The ghosted copy of @p name on the old mesh: what is interpolated
     * (a caller may replace it before prepare(), as the projection does).
     */
    TrilinosWrappers::MPI::Vector &
    old_field(const std::string &name);

    /**
     * Register the copies with the mesh, after its
     * prepare_coarsening_and_refinement() and before
     * execute_coarsening_and_refinement().
     */
    void
    prepare();

    /**
     * Interpolate into the fields of @p fields (the list of the state on
     * the new mesh, its spaces set up) that have the names of the copies;
     * constraints are not distributed.
     */
    void
    interpolate(const std::vector<StateField<dim>> &fields);

  private:
    using Transfer =
      parallel::distributed::SolutionTransfer<dim,
                                              TrilinosWrappers::MPI::Vector>;
    struct Group
    {
      const DoFHandler<dim>                     *dof_handler;
      std::vector<std::string>                   names;
      std::vector<TrilinosWrappers::MPI::Vector> old_fields;
      std::unique_ptr<Transfer>                  transfer;
    };
    std::vector<Group> groups;
  };

  /**
   * Distribute the hanging-node (and boundary) constraints of their space
   * into the fields of @p fields marked 'constrained'.
   */
  template <int dim>
  void
  distribute_constraints(const std::vector<StateField<dim>> &fields);
} // namespace hemicontact
