#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/mesh/discretization.h>
#include <hemicontact/model/contact_node.h>
#include <hemicontact/state/added_fields.h>

#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * What a coupled field reads of the mechanical step (doc/extending.md,
   * "A coupled field"): the mesh, w_n and u_n on the displacement's
   * DoFHandler, the contact nodes with the nodal traction -sigma nu, the
   * time, and the state's added fields, where a field finds the others by
   * name.
   */
  template <int dim>
  struct MechanicalView
  {
    const Discretization<dim> &discretization;
    const DoFHandler<dim>     &dof_handler;
    const IndexSet            &locally_owned_dofs;
    const IndexSet            &locally_relevant_dofs;
    /** Hanging nodes and u = 0 on Gamma_1. */
    const AffineConstraints<double>     &base_constraints;
    const TrilinosWrappers::MPI::Vector &velocity;     ///< w_n
    const TrilinosWrappers::MPI::Vector &displacement; ///< u_n
    /** -(K w - b)_i / m_i = xi_nu nu + xi_tau at owned contact node dofs */
    const TrilinosWrappers::MPI::Vector &contact_traction;
    const std::vector<ContactNode<dim>> &contact_nodes;
    double                               time; ///< t_n
    /** The displacement held after the step is u + held_offset w
     *  (StepScheme::held_displacement_offset()). */
    double held_offset;
    /** Whether the run is of the static class (no velocity, no steps of
     *  the fields' own). */
    bool static_class;
    /** The fields added to the state, the coupled fields among them. */
    const AddedFields<dim> &fields;
  };
} // namespace hemicontact
