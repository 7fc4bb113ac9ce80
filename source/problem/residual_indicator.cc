#include <hemicontact/problem/equilibrated_estimate.h>
#include <hemicontact/problem/error_indicators.h>

namespace hemicontact
{
  template <int dim>
  const ErrorEstimate &
  ContactProblem<dim>::error_estimate() const
  {
    if (estimate_revision == state_revision)
      return cached_estimate;
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
    if (parameters.output.error_estimate_equilibrated)
      {
        cached_estimate   = equilibrated_estimate(state(),
                                                data,
                                                ghosted(displacement),
                                                ghosted(xi_owned));
        estimate_revision = state_revision;
        return cached_estimate;
      }
    const ErrorEstimator<dim> estimator(
      discretization, dof_handler, material, scheme, data, parameters.boundary);
    cached_estimate   = estimator.estimate(ghosted(velocity),
                                         ghosted(old_velocity),
                                         ghosted(displacement),
                                         ghosted(xi_owned),
                                         time_step,
                                         mpi_communicator);
    estimate_revision = state_revision;
    return cached_estimate;
  }

  template <int dim>
  Vector<float>
  residual_indicators(const ContactProblem<dim> &problem)
  {
    return problem.error_estimate().cell_values(
      problem.state().parameters.adaptivity.contact_weight,
      /*in_energy_norm=*/false);
  }

  template const ErrorEstimate &
  ContactProblem<2>::error_estimate() const;
  template const ErrorEstimate &
  ContactProblem<3>::error_estimate() const;
  template Vector<float>
  residual_indicators(const ContactProblem<2> &);
  template Vector<float>
  residual_indicators(const ContactProblem<3> &);
} // namespace hemicontact
