#include <deal.II/base/mpi.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/model/memory_stability.h>
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
    /**
     * The masses m/(a k) of the dynamic class's modes that are tried: the
     * stiff modes, whose viscous damping per step is of order one (m <= a
     * k); in a mode of larger mass the memory acts on the model's time
     * scale, not on the step's (doc/theory.md 11.13).
     */
    std::vector<double>
    mode_masses()
    {
      std::vector<double> masses{0.};
      for (int e = -12; e <= 0; ++e)
        masses.push_back(std::pow(10., e / 4.));
      return masses;
    }

    /** What one check found: the largest stable k, the rule's growth at
     *  k and the model's own growth over a step of length k. */
    struct MemoryLimit
    {
      double      limit        = std::numeric_limits<double>::infinity();
      double      growth       = 0;
      double      model_growth = 1;
      std::string where;
    };

    /**
     * The smallest limit over @p mode with the masses of mode_masses()
     * (velocity classes; the static class has none), skipping the masses
     * at which the rule without memory is unstable already (section 9.6's
     * check is theirs).
     */
    void
    check_mode(MemoryMode         mode,
               const double       k,
               const StepScheme  &scheme,
               const std::string &where,
               MemoryLimit       &result)
    {
      const std::vector<double> masses =
        scheme.has_inertia() ? mode_masses() : std::vector<double>{0.};
      for (const double m : masses)
        {
          mode.mass = m * mode.viscosity * k;
          if (!scheme.is_static() &&
              memory_rule_growth(mode, k, scheme, false) > 1 + 1e-10)
            continue;
          // the rule may grow as the model does (a kernel with a negative
          // long-term modulus), not faster
          const double growth = memory_rule_growth(mode, k, scheme);
          const double rate   = model_growth_rate(mode, scheme);
          if (growth <= allowed_memory_growth(rate, k))
            continue;
          const double limit = largest_stable_memory_step(mode, k, scheme);
          if (limit < result.limit)
            result = {limit, growth, std::exp(rate * k), where};
        }
    }

    /**
     * The kernel's terms as exponentials (r_l, tau_l) for one quotient:
     * the Prony terms, or the exponential through the values at k and 2k.
     */
    template <class Amplitude, class Time, class Value>
    void
    set_terms(MemoryMode        &mode,
              const bool         prony,
              const unsigned int n_terms,
              const Amplitude   &amplitude,
              const Time        &tau,
              const Value       &value,
              const double       k)
    {
      mode.amplitudes.clear();
      mode.relaxation_times.clear();
      if (prony)
        for (unsigned int l = 0; l < n_terms; ++l)
          {
            mode.amplitudes.push_back(amplitude(l));
            mode.relaxation_times.push_back(tau(l));
          }
      else
        {
          const auto [r, t] = exponential_through(value(k), value(2 * k), k);
          if (r != 0 && std::isfinite(r))
            {
              mode.amplitudes.push_back(r);
              mode.relaxation_times.push_back(t);
            }
        }
    }
  } // namespace

  template <int dim>
  bool
  check_memory_stability(const ProblemState<dim> &state,
                         StepPreconditioner<dim> &preconditioner,
                         TimerOutput             &timer)
  {
    const RelaxationKernel   &stress = state.memory.get_kernel();
    const NormalMemoryKernel &normal =
      state.memory.contact_memory().get_kernel();
    const bool stress_memory = stress.type() != RelaxationKernelType::none;
    const bool normal_memory = normal.type() != RelaxationKernelType::none;
    if (!stress_memory && !normal_memory)
      return false;
    TimerOutput::Scope                   t(timer, "stability check");
    const double                         k             = state.time_step;
    const Parameters                    &parameters    = state.parameters;
    const KelvinVoigtMaterial<dim>      &material      = state.material;
    const StepScheme                    &scheme        = state.scheme;
    const NormalLaw                     &law           = state.normal_law;
    const std::vector<ContactNode<dim>> &contact_nodes = state.contact_nodes;
    const AffineConstraints<double> &base_constraints  = state.base_constraints;
    const TrilinosWrappers::SparseMatrix &step_matrix  = state.step_matrix;
    const TrilinosWrappers::SparseMatrix &mass_matrix  = state.mass_matrix;
    const TrilinosWrappers::SparseMatrix &elastic_matrix = state.elastic_matrix;
    MPI_Comm    mpi_communicator = state.mpi_communicator;
    MemoryLimit result;

    // the stress: the deviatoric and the volumetric channel of the
    // isotropic tensors (doc/theory.md 11.13), moduli 2 mu and 2 mu + d lambda
    std::ostringstream growing_model;
    if (stress_memory)
      for (const bool volumetric : {false, true})
        {
          const auto channel = [&](const double mu, const double lambda) {
            return 2 * mu + (volumetric ? dim * lambda : 0.);
          };
          MemoryMode mode;
          mode.viscosity =
            channel(material.mu_viscous(), material.lambda_viscous());
          mode.elasticity =
            channel(material.mu_elastic(), material.lambda_elastic());
          set_terms(
            mode,
            stress.type() == RelaxationKernelType::prony,
            stress.n_terms(),
            [&](const unsigned int l) {
              return channel(stress.mu_amplitude(l),
                             stress.lambda_amplitude(l));
            },
            [&](const unsigned int l) { return stress.relaxation_time(l); },
            [&](const double s) {
              const auto [mu, lambda] = stress(s);
              return channel(mu, lambda);
            },
            k);
          const std::string where = std::string("the ") +
                                    (volumetric ? "volumetric" : "deviatoric") +
                                    " part of 'relaxation'";
          check_mode(mode, k, scheme, where, result);

          // the long-term modulus B + int_0^T R: negative, the model grows
          double integral = 0;
          if (stress.type() == RelaxationKernelType::prony)
            for (unsigned int l = 0; l < stress.n_terms(); ++l)
              integral +=
                channel(stress.mu_amplitude(l), stress.lambda_amplitude(l)) *
                stress.relaxation_time(l);
          else
            for (unsigned int n = 1; n <= state.n_steps; ++n)
              {
                const auto [mu, lambda] = stress(n * k);
                integral += k * channel(mu, lambda);
              }
          if (mode.elasticity + integral < 0 && growing_model.str().empty())
            growing_model
              << std::setprecision(4) << "the long-term modulus of "
              << where.substr(4) << ", " << mode.elasticity << " + " << integral
              << " (the modulus of B plus the kernel's integral), "
              << "is negative: the model itself grows without bound under a "
                 "constant load, whatever the time step (doc/theory.md "
                 "11.13).";
        }

    // the normal memory: the contact mode with the largest sum m_i u_nu^2
    // against the step's stiffness, its Rayleigh quotients against that sum,
    // with the law's largest slope; none behind a wall, which bounds
    // (u_nu)_+ <= g and so N
    if (normal_memory && !contact_nodes.empty() &&
        !std::isfinite(law.penetration_limit()))
      {
        const auto apply_c = [&](const TrilinosWrappers::MPI::Vector &in,
                                 TrilinosWrappers::MPI::Vector       &out) {
          out = 0;
          for (const ContactNode<dim> &node : contact_nodes)
            if (node.locally_owned)
              {
                double vn = 0;
                for (unsigned int c = 0; c < dim; ++c)
                  vn += in[node.dofs[c]] * node.normal[c];
                for (unsigned int c = 0; c < dim; ++c)
                  out[node.dofs[c]] = node.mass * vn * node.normal[c];
              }
          out.compress(VectorOperation::insert);
          base_constraints.set_zero(out);
        };
        const auto apply_k = constrained(step_matrix, base_constraints);
        const auto precondition =
          constrained(preconditioner.step_amg(step_matrix), base_constraints);
        TrilinosWrappers::MPI::Vector x(state.locally_owned_dofs,
                                        mpi_communicator);
        for (const ContactNode<dim> &node : contact_nodes)
          if (node.locally_owned)
            for (unsigned int c = 0; c < dim; ++c)
              x[node.dofs[c]] = node.normal[c];
        x.compress(VectorOperation::insert);
        base_constraints.set_zero(x);
        const EigenvalueEstimate estimate = largest_generalized_eigenvalue(
          apply_c, apply_k, precondition, x, 1e-4, 300);
        if (estimate.value > 0)
          {
            TrilinosWrappers::MPI::Vector tmp(x);
            apply_c(x, tmp);
            const double                 c            = x * tmp;
            const StepMatrixCoefficients coefficients = scheme.step_matrix(k);
            mass_matrix.vmult(tmp, x);
            const double m = x * tmp / c;
            elastic_matrix.vmult(tmp, x);
            const double b = x * tmp / c;
            step_matrix.vmult(tmp, x);
            const double kx = x * tmp / c;
            // the law acts on u_nu (static class) or w_nu
            const double law_slope = law.largest_remainder_slope();
            MemoryMode   mode;
            mode.elasticity = scheme.is_static() ? kx + law_slope : b;
            mode.viscosity  = scheme.is_static() ?
                                0. :
                                kx - coefficients.mass * m -
                                 coefficients.elastic * b + law_slope;
            set_terms(
              mode,
              normal.type() == RelaxationKernelType::prony,
              normal.n_terms(),
              [&](const unsigned int l) { return normal.amplitude(l); },
              [&](const unsigned int l) { return normal.relaxation_time(l); },
              [&](const double s) { return normal(s); },
              k);
            check_mode(mode, k, scheme, "'normal memory'", result);
          }
      }

    if (!growing_model.str().empty() &&
        Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::cerr << "hemicontact: warning: " << growing_model.str() << std::endl;
    if (!(result.limit < k))
      return false;
    std::ostringstream message;
    message << std::setprecision(4) << "the time step k = " << k
            << " is above the stability limit of the memory rule for "
            << result.where << ", k <= " << result.limit
            << ": the memory sum is explicit (the left-rectangle rule, "
               "doc/theory.md 11.13), and its recursion grows by a factor "
            << result.growth << " per step, while the model ";
    if (result.model_growth > 1 + 1e-10)
      message << "grows by a factor " << result.model_growth
              << " per step (the rule may grow by up to its square)";
    else
      message << "does not grow";
    message << ". Choose a time step that "
               "divides the end time and is at most "
            << result.limit << " (e.g. " << parameters.time.end_time << " / "
            << std::ceil(parameters.time.end_time / result.limit)
            << "), or a smaller kernel; 'time/allow unstable time step = "
               "true' runs it anyway.";
    if (!parameters.time.allow_unstable_time_step)
      throw InputError("time: " + message.str());
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::cerr << "hemicontact: warning: " << message.str() << std::endl;
    return true;
  }

#define HEMICONTACT_INSTANTIATE(dim)                              \
  template bool check_memory_stability(const ProblemState<dim> &, \
                                       StepPreconditioner<dim> &, \
                                       TimerOutput &);

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
