#include <hemicontact/problem/contact_problem.h>

namespace hemicontact
{
  template <int dim>
  ErrorEstimate
  ContactProblem<dim>::estimate_error() const
  {
    // the state of the step just solved, ghosted; the nodal traction also
    // at hanging nodes on Gamma_3 (interpolated from the face's nodes)
    const auto ghosted = [&](const TrilinosWrappers::MPI::Vector &v) {
      TrilinosWrappers::MPI::Vector g(locally_owned_dofs,
                                      locally_relevant_dofs,
                                      mpi_communicator);
      g = v;
      return g;
    };
    TrilinosWrappers::MPI::Vector xi_owned(contact_traction);
    base_constraints.distribute(xi_owned);
    const ErrorEstimator<dim> estimator(
      discretization, dof_handler, material, scheme, data, parameters.boundary);
    return estimator.estimate(ghosted(velocity),
                              ghosted(old_velocity),
                              ghosted(displacement),
                              ghosted(xi_owned),
                              time_step,
                              mpi_communicator);
  }

  template <int dim>
  const ErrorEstimate &
  ContactProblem<dim>::error_estimate() const
  {
    if (estimate_revision != state_revision)
      {
        cached_estimate   = estimate_error();
        estimate_revision = state_revision;
      }
    return cached_estimate;
  }

  template <int dim>
  Vector<float>
  ContactProblem<dim>::residual_indicators() const
  {
    return error_estimate().cell_values(parameters.adaptivity.contact_weight,
                                        /*in_energy_norm=*/false);
  }

  template ErrorEstimate
  ContactProblem<2>::estimate_error() const;
  template ErrorEstimate
  ContactProblem<3>::estimate_error() const;
  template const ErrorEstimate &
  ContactProblem<2>::error_estimate() const;
  template const ErrorEstimate &
  ContactProblem<3>::error_estimate() const;
  template Vector<float>
  ContactProblem<2>::residual_indicators() const;
  template Vector<float>
  ContactProblem<3>::residual_indicators() const;
} // namespace hemicontact
