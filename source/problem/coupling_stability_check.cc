#include <deal.II/base/mpi.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/model/time_step_stability.h>
#include <hemicontact/problem/stability.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace hemicontact
{
  template <int dim>
  void
  check_coupling_stability(const ProblemState<dim> &state, TimerOutput &timer)
  {
    // with the left-point rule the coupling is part of 9.6's check
    // (stability.cc), which counts the mass
    if (state.scheme.time_scheme() != TimeScheme::implicit)
      return;
    const StaggeredCoupling coupling =
      state.coupled_fields.staggered_coupling();
    const double ratio = coupling.ratio;
    if (ratio == 0)
      return;
    TimerOutput::Scope              t(timer, "stability check");
    const Parameters               &parameters = state.parameters;
    const KelvinVoigtMaterial<dim> &material   = state.material;
    const double                    limit      = coupling_stable_time_step(dim,
                                                   material.mu_viscous(),
                                                   material.lambda_viscous(),
                                                   material.mu_elastic(),
                                                   material.lambda_elastic(),
                                                   ratio);
    const double                    k          = state.time_step;
    if (k <= limit)
      return;

    const double kappa_v =
      2 * material.mu_viscous() / dim + material.lambda_viscous();
    const double kappa =
      2 * material.mu_elastic() / dim + material.lambda_elastic();
    std::ostringstream message;
    message
      << std::setprecision(4) << "the time step k = " << k
      << " is above the stability limit of the staggered "
      << coupling.coupling_name << ", k <= " << limit
      << " = 2 kappa_A / (c - kappa_B) with the bulk moduli kappa_A = "
      << kappa_v << " and kappa_B = " << kappa
      << " (2 mu/d + lambda) and c = " << coupling.ratio_formula << " = "
      << ratio << " (doc/theory.md 13.2): the mechanical step sees "
      << coupling.lagged_field
      << " of the step before, and the energy of the run would grow without "
         "bound. Choose a time step that divides the end time and is at "
         "most "
      << limit << " (e.g. " << parameters.time.end_time << " / "
      << std::ceil(parameters.time.end_time / limit) << "), "
      << coupling.remedies
      << " 'time/allow unstable time step = true' runs it anyway.";
    if (!parameters.time.allow_unstable_time_step)
      throw InputError(coupling.subsection + ": " + message.str());
    if (Utilities::MPI::this_mpi_process(state.mpi_communicator) == 0)
      std::cerr << "hemicontact: warning: " << message.str() << std::endl;
  }

#define HEMICONTACT_INSTANTIATE(dim)                                \
  template void check_coupling_stability(const ProblemState<dim> &, \
                                         TimerOutput &);

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
