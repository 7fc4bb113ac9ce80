#include <deal.II/base/mpi.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/model/contact_wall.h>
#include <hemicontact/problem/wall_admissibility.h>

#include <cmath>
#include <sstream>

namespace hemicontact
{
  template <int dim>
  void
  require_admissible_initial_state(const ProblemState<dim> &state)
  {
    const StepScheme &scheme = state.scheme;
    const double      g      = state.normal_law.penetration_limit();
    if (!std::isfinite(g) || scheme.is_static())
      return;
    // the displacement of the first step without a solve: u_0 + k w_0 in
    // the left-point rule of the dynamic class (the quasistatic w_0 solves
    // the step problem with the wall)
    const double k = scheme.has_inertia() ?
                       scheme.held_displacement_offset(state.time_step) :
                       0.;
    std::string  error;
    for (const ContactNode<dim> &node : state.contact_nodes)
      if (node.locally_owned && error.empty())
        {
          const double u_nu =
            nodal_vector(node, state.displacement) * node.normal;
          const double w_nu = nodal_vector(node, state.velocity) * node.normal;
          // round-off of the nodal values, relative to their own scale
          const double slack =
            1e-12 * std::max(std::abs(g), std::abs(u_nu) + k * std::abs(w_nu));
          std::ostringstream message;
          message.precision(6);
          if (u_nu > g + slack)
            message << "data: the initial displacement starts beyond the "
                       "wall of the normal law at the contact node "
                    << node.position << ": u_nu = " << u_nu << " > g = " << g
                    << " ('penetration limit'); the law forbids that "
                       "state. Change 'data/initial displacement' so that "
                       "u_nu <= g on the contact boundary (doc/theory.md "
                       "10.2).";
          else if (u_nu + k * w_nu > g + slack)
            message << "data: the initial velocity carries the contact node "
                    << node.position
                    << " beyond the wall of the normal law in the first "
                       "step: the left-point rule moves it to u_nu + k w_nu = "
                    << u_nu + k * w_nu << " > g = " << g
                    << " ('penetration limit') without a solve (u_1 = u_0 + "
                       "k w_0). Reduce 'data/initial velocity' or "
                       "'time/time step' (k = "
                    << k
                    << "), or use 'problem/time scheme = implicit', whose "
                       "first step is bounded by the wall (doc/theory.md "
                       "10.2).";
          error = message.str();
        }
    for (const std::string &message :
         Utilities::MPI::all_gather(state.mpi_communicator, error))
      if (!message.empty())
        throw InputError(message);
  }

  template <int dim>
  std::pair<unsigned int, double>
  move_state_onto_wall(const ProblemState<dim>       &state,
                       TrilinosWrappers::MPI::Vector &displacement)
  {
    const double g = state.normal_law.penetration_limit();
    if (!std::isfinite(g) || state.scheme.is_static())
      return {0, 0.};
    const double offset =
      state.scheme.held_displacement_offset(state.time_step);
    // the worn wall, g + omega (owned nodes only: the owned entries do)
    const ContactMemory<dim> &contact = state.memory.contact_memory();
    const TrilinosWrappers::MPI::Vector *wear =
      contact.wear_active() ? &contact.wear() : nullptr;
    unsigned int n_moved = 0;
    double       largest = 0;
    for (const ContactNode<dim> &node : state.contact_nodes)
      if (node.locally_owned &&
          !state.base_constraints.is_constrained(node.dofs[0]))
        {
          const double excess =
            nodal_vector(node, displacement) * node.normal +
            offset * nodal_vector(node, state.velocity) * node.normal -
            wall_position(g, node, wear);
          if (excess > 0)
            {
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const double u_c           = displacement[node.dofs[c]];
                  displacement[node.dofs[c]] = u_c - excess * node.normal[c];
                }
              ++n_moved;
              largest = std::max(largest, excess);
            }
        }
    displacement.compress(VectorOperation::insert);
    state.base_constraints.distribute(displacement);
    return {Utilities::MPI::sum(n_moved, state.mpi_communicator),
            Utilities::MPI::max(largest, state.mpi_communicator)};
  }

#define HEMICONTACT_INSTANTIATE(dim)                                         \
  template void require_admissible_initial_state(const ProblemState<dim> &); \
  template std::pair<unsigned int, double> move_state_onto_wall(             \
    const ProblemState<dim> &, TrilinosWrappers::MPI::Vector &);

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
