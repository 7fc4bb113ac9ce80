#include <deal.II/base/mpi.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/model/time_step_stability.h>
#include <hemicontact/problem/stability.h>
#include <hemicontact/solver/constrained_operator.h>
#include <hemicontact/solver/generalized_eigenvalue.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    /** Like the convexity estimate: the eigenvalue to about 1e-8. */
    constexpr double       stability_residual_tolerance = 1e-4;
    constexpr unsigned int stability_max_iterations     = 300;
    /** Rounds of (eigenvector at k) -> (stable k of that vector). */
    constexpr unsigned int limit_refinements = 4;

    /**
     * The largest stable time step of the left-point rule on the state's
     * mesh, from the estimate at @p k (infinite if k is stable), with B
     * scaled by @p elastic_scale (the staggered thermal coupling's share,
     * doc/theory.md 13.2; 1 without it).
     */
    template <int dim>
    double
    largest_stable_time_step(const ProblemState<dim> &state,
                             StepPreconditioner<dim> &preconditioner,
                             const double             k,
                             const double             elastic_scale)
    {
      const TrilinosWrappers::SparseMatrix &step_matrix = state.step_matrix;
      const TrilinosWrappers::SparseMatrix &mass_matrix = state.mass_matrix;
      const TrilinosWrappers::SparseMatrix &elastic_matrix =
        state.elastic_matrix;
      const AffineConstraints<double> &base_constraints =
        state.base_constraints;
      const IndexSet &locally_owned_dofs = state.locally_owned_dofs;
      MPI_Comm        mpi_communicator   = state.mpi_communicator;
      // lambda_max(B; A + 2M/k) by LOBPCG, preconditioned by the AMG of
      // K0 = M/k + A (spectrally within a factor 2 of A + 2M/k), from a
      // fixed pseudo-random start (the same on any number of ranks); without
      // inertia lambda_max(B; A) with K = A (doc/theory.md, section 9.6)
      const bool inertia = state.scheme.has_inertia();
      const auto apply_b = [&](const TrilinosWrappers::MPI::Vector &in,
                               TrilinosWrappers::MPI::Vector       &out) {
        elastic_matrix.vmult(out, in);
        out *= elastic_scale;
        base_constraints.set_zero(out);
      };
      double                        current_k = k;
      TrilinosWrappers::MPI::Vector m_in(locally_owned_dofs, mpi_communicator);
      const auto apply_s = [&](const TrilinosWrappers::MPI::Vector &in,
                               TrilinosWrappers::MPI::Vector       &out) {
        step_matrix.vmult(out, in);
        if (inertia)
          {
            mass_matrix.vmult(m_in, in);
            out.add(1. / current_k, m_in);
          }
        base_constraints.set_zero(out);
      };
      const auto precondition =
        constrained(preconditioner.step_amg(step_matrix), base_constraints);
      TrilinosWrappers::MPI::Vector x(locally_owned_dofs, mpi_communicator);
      for (const auto i : locally_owned_dofs)
        x[i] = std::sin(12.9898 * static_cast<double>(i) + 78.233);
      x.compress(VectorOperation::insert);
      base_constraints.set_zero(x);

      // k is stable iff lambda_max(B; A + 2M/k) <= 2/k; the Ritz vector of a
      // k that fails gives a smaller stable k (stable_time_step_of_mode), and
      // the limit is refined from there
      double limit = std::numeric_limits<double>::infinity();
      TrilinosWrappers::MPI::Vector tmp(x);
      for (unsigned int round = 0; round < limit_refinements; ++round)
        {
          const EigenvalueEstimate estimate =
            largest_generalized_eigenvalue(apply_b,
                                           apply_s,
                                           precondition,
                                           x,
                                           stability_residual_tolerance,
                                           stability_max_iterations);
          if (!(estimate.value > 0) || estimate.value * current_k <= 2)
            return round == 0 ? std::numeric_limits<double>::infinity() : limit;
          mass_matrix.vmult(tmp, x);
          const double m = inertia ? x * tmp : 0.;
          step_matrix.vmult(tmp, x);
          const double a = x * tmp - m / current_k;
          elastic_matrix.vmult(tmp, x);
          const double b     = elastic_scale * (x * tmp);
          const double k_x   = stable_time_step_of_mode(m, a, b);
          const bool   close = k_x >= 0.99 * limit;
          limit              = std::min(limit, k_x);
          if (close)
            break;
          current_k = limit;
        }
      return limit;
    }

    /** The limit of the left-point rule: InputError or a warning above it. */
    template <int dim>
    void
    check_time_step_stability(const ProblemState<dim> &state,
                              StepPreconditioner<dim> &preconditioner,
                              TimerOutput             &timer)
    {
      const StepScheme &scheme = state.scheme;
      // the implicit rule is stable for every k (doc/theory.md, section 9.6)
      if (!scheme.has_time_step_limit())
        return;
      TimerOutput::Scope              t(timer, "stability check");
      const KelvinVoigtMaterial<dim> &material   = state.material;
      const double                    time_step  = state.time_step;
      const Parameters               &parameters = state.parameters;
      // a staggered coupling (the temperature's) adds c (tr eps)^2 to the
      // explicit elastic term (doc/theory.md 13.2): lambda + c on every
      // mesh, and at most the factor 1 + c/kappa_B on B's modes
      const StaggeredCoupling staggered =
        state.coupled_fields.staggered_coupling();
      const double coupling = staggered.ratio;
      const double kappa =
        2 * material.mu_elastic() / dim + material.lambda_elastic();
      const double elastic_scale =
        coupling == 0 ? 1. :
        kappa > 0     ? 1 + coupling / kappa :
                        std::numeric_limits<double>::infinity();
      const double material_limit =
        mesh_independent_stable_time_step(dim,
                                          material.mu_viscous(),
                                          material.lambda_viscous(),
                                          material.mu_elastic(),
                                          material.lambda_elastic() + coupling);
      if (time_step <= material_limit)
        return;
      const double limit = std::isfinite(elastic_scale) ?
                             largest_stable_time_step(state,
                                                      preconditioner,
                                                      time_step,
                                                      elastic_scale) :
                             material_limit;
      if (time_step <= limit)
        return;

      std::ostringstream message;
      message << std::setprecision(4) << "the time step k = " << time_step
              << " is above the stability limit of the left-point rule on this "
                 "mesh, k <= "
              << limit << " (estimated: " << scheme.stability_condition()
              << "): the elastic term is explicit, ";
      if (coupling > 0)
        message << "and with it the staggered " << staggered.coupling_name
                << "'s term, c = " << staggered.ratio_formula << " = "
                << coupling << " added to B's lambda (doc/theory.md 13.2), ";
      message << "and the energy of the run would grow without bound. Choose "
                 "a time step that divides the end time and is at most "
              << limit << " (e.g. " << parameters.time.end_time << " / "
              << std::ceil(parameters.time.end_time / limit)
              << "), a larger viscosity or a softer material; below k = "
              << material_limit
              << " the rule is stable on every mesh. 'problem/time scheme = "
                 "implicit' is stable for every time step";
      if (coupling > 0)
        message << " without the coupling, and with it for k <= "
                << coupling_stable_time_step(dim,
                                             material.mu_viscous(),
                                             material.lambda_viscous(),
                                             material.mu_elastic(),
                                             material.lambda_elastic(),
                                             coupling);
      message << "; 'time/allow unstable time step = true' runs it anyway.";
      if (!parameters.time.allow_unstable_time_step)
        throw InputError("time: " + message.str());
      if (Utilities::MPI::this_mpi_process(state.mpi_communicator) == 0)
        std::cerr << "hemicontact: warning: " << message.str() << std::endl;
    }
  } // namespace

  template <int dim>
  bool
  check_time_step_limits(const ProblemState<dim> &state,
                         StepPreconditioner<dim> &preconditioner,
                         TimerOutput             &timer)
  {
    check_time_step_stability(state, preconditioner, timer);
    check_coupling_stability(state, timer);
    return check_memory_stability(state, preconditioner, timer);
  }

#define HEMICONTACT_INSTANTIATE(dim)                              \
  template bool check_time_step_limits(const ProblemState<dim> &, \
                                       StepPreconditioner<dim> &, \
                                       TimerOutput &);

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
