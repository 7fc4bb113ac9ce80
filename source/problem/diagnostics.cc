#include <deal.II/base/mpi.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/model/contact_step.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/solver/constrained_operator.h>
#include <hemicontact/solver/generalized_eigenvalue.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <sstream>
#include <tuple>

namespace hemicontact
{
  namespace
  {
    /**
     * The convexity estimate stops once its relative residual is below
     * this: the eigenvalue is then accurate to about its square. On the
     * examples (3D r2-r4, 2D r6, the 812k-dof box) it agreed with a solve to
     * 1e-7 within 1.5e-7 relative, in 25-90 iterations.
     */
    constexpr double       convexity_residual_tolerance = 1e-4;
    constexpr unsigned int convexity_max_iterations     = 300;
    /**
     * A check that finds the step convex with room to spare covers alpha_tau
     * up to this factor above the values met (N grows at most by the same
     * factor), so that a bound growing step by step is checked again only
     * every 10%.
     */
    constexpr double convexity_recheck_headroom = 1.1;

    /**
     * The step energy J = 1/2 v.K v - b.v + sum_i m_i [j_nu + phi] at @p v
     * (constrained entries zero; doc/theory.md section 9): what the step
     * minimised, at its solution.
     */
    template <int dim>
    double
    minimised_step_energy(const TrilinosWrappers::SparseMatrix &K,
                          const TrilinosWrappers::MPI::Vector  &b,
                          const TrilinosWrappers::MPI::Vector  &v,
                          const std::vector<ContactNode<dim>>  &nodes,
                          const NormalLaw                      &law,
                          const FrictionLaw                    &friction)
    {
      TrilinosWrappers::MPI::Vector Kv(v);
      K.vmult(Kv, v);
      double nodal = 0;
      for (const ContactNode<dim> &node : nodes)
        if (node.locally_owned)
          nodal += nodal::energy(node, nodal_vector(node, v), law, friction);
      return 0.5 * (v * Kv) - b * v +
             Utilities::MPI::sum(nodal, v.get_mpi_communicator());
    }

    /**
     * The identity of the static class at one load value (doc/theory.md
     * 9.4), u.B u + sum_i m_i (xi_nu u_nu + xi_tau . u_tau) = F.u, in the
     * terms of EnergyBalance: the stored energy 1/2 u.B u as elastic, half
     * the work of the contact forces (normal as damping, tangential as
     * friction) and half the work of the loads as external work, so that
     * the defect is the identity's, halved (Clapeyron's theorem: the work
     * of forces raised in proportion from zero).
     */
    template <int dim>
    EnergyBalance
    clapeyron_balance(const TrilinosWrappers::SparseMatrix &B,
                      const TrilinosWrappers::MPI::Vector  &F,
                      const TrilinosWrappers::MPI::Vector  &u,
                      const TrilinosWrappers::MPI::Vector  &traction,
                      const std::vector<ContactNode<dim>>  &nodes,
                      const NormalLaw                      &law,
                      const FrictionLaw                    &friction,
                      MPI_Comm                              comm)
    {
      TrilinosWrappers::MPI::Vector Bu(u);
      B.vmult(Bu, u);
      double normal = 0, tangential = 0;
      for (const ContactNode<dim> &node : nodes)
        if (node.locally_owned)
          {
            const auto [n, t] =
              nodal::contact_work(node,
                                  nodal_vector(node, u),
                                  nodal_vector(node, traction) * node.normal,
                                  law,
                                  friction);
            normal += n;
            tangential += t;
          }
      EnergyBalance e;
      e.elastic              = 0.5 * (u * Bu);
      e.damping_dissipation  = 0.5 * Utilities::MPI::sum(normal, comm);
      e.friction_dissipation = 0.5 * Utilities::MPI::sum(tangential, comm);
      e.external_work        = 0.5 * (F * u);
      return e;
    }
  } // namespace

  template <int dim>
  StoredEnergy
  stored_energy(const ProblemState<dim> &state)
  {
    const AffineConstraints<double> &base_constraints = state.base_constraints;
    const StepScheme                &scheme           = state.scheme;
    const TrilinosWrappers::MPI::Vector &velocity     = state.velocity;
    // rho/2 |w_n|^2 and 1/2 a_B(u, u) with u the displacement held after
    // step n: u_{n+1} = u_n + k w_n (left point) or u_n (implicit); no
    // kinetic energy without inertia (doc/theory.md, section 9.3)
    const TrilinosWrappers::MPI::Vector w =
      without_constrained(velocity, base_constraints);
    TrilinosWrappers::MPI::Vector u_next(state.displacement);
    const double offset = scheme.held_displacement_offset(state.time_step);
    if (offset != 0.)
      u_next.add(offset, velocity);
    u_next = without_constrained(u_next, base_constraints);
    TrilinosWrappers::MPI::Vector tmp(state.locally_owned_dofs,
                                      state.mpi_communicator);
    state.mass_matrix.vmult(tmp, w);
    const double kinetic = scheme.kinetic_energy(w * tmp);
    state.elastic_matrix.vmult(tmp, u_next);
    StoredEnergy stored;
    stored.kinetic = kinetic;
    stored.elastic = 0.5 * (u_next * tmp);
    state.coupled_fields.stored_energies(mechanical_view(state),
                                         state.added_fields,
                                         stored.coupled);
    return stored;
  }

  template <int dim>
  void
  ContactProblem<dim>::update_energy_balance(const bool initial)
  {
    TimerOutput::Scope                  t(timer, "energy balance");
    const double                        k = time_step;
    const TrilinosWrappers::MPI::Vector w =
      without_constrained(velocity, base_constraints);
    TrilinosWrappers::MPI::Vector tmp(locally_owned_dofs, mpi_communicator);
    // the laws' part xi of the traction -sigma nu: the memory pressure's
    // work is in memory_work (doc/theory.md, section 11.9)
    TrilinosWrappers::MPI::Vector law_traction(contact_traction);
    memory.subtract_pressure(law_traction);
    if (scheme.is_static())
      {
        energy = clapeyron_balance(elastic_matrix,
                                   load,
                                   w,
                                   law_traction,
                                   contact_nodes,
                                   *law,
                                   *friction,
                                   mpi_communicator);
        if (!initial)
          energy.minimised_energy = minimised_step_energy(
            step_matrix, step_rhs, w, contact_nodes, *law, *friction);
        // the memory term of the identity, halved as the others
        if (memory.active())
          energy.memory_work = 0.5 * (memory.step_functional() * w);
        return;
      }
    const StoredEnergy stored = stored_energy(state());
    stored.book_into(energy);
    if (initial)
      {
        energy.initial_energy = energy.total_energy();
        return;
      }
    energy.minimised_energy = minimised_step_energy(
      step_matrix, step_rhs, w, contact_nodes, *law, *friction);

    // the terms of doc/theory.md, section 9.3: k a_A(w, w) from A, the
    // numerical dissipation rho/2 |w_n - w_{n-1}|^2 -+ k^2/2 a_B(w_n, w_n)
    // A is not held: w.A w = (w.K w - c_M w.rho M w - c_B w.B w) / c_A
    const StepMatrixCoefficients c = scheme.step_matrix(k);
    step_matrix.vmult(tmp, w);
    const double w_K_w = w * tmp;
    mass_matrix.vmult(tmp, w);
    const double w_M_w = w * tmp;
    elastic_matrix.vmult(tmp, w);
    const double w_B_w = w * tmp;
    const double w_A_w =
      (w_K_w - c.mass * w_M_w - c.elastic * w_B_w) / c.viscous;
    TrilinosWrappers::MPI::Vector dw(velocity);
    dw -= old_velocity;
    dw = without_constrained(dw, base_constraints);
    mass_matrix.vmult(tmp, dw);
    const double                 dw_M_dw = dw * tmp;
    const StepScheme::StepEnergy terms =
      scheme.step_energy(k, w_A_w, dw_M_dw, w_B_w);
    energy.viscous_dissipation += terms.viscous;
    energy.numerical_dissipation += terms.numerical;
    energy.external_work += k * (load * w);
    // the work k (M_n, eps(w_n)) of the memory stress (doc/theory.md 11)
    if (memory.active())
      energy.memory_work += k * (memory.step_functional() * w);

    // the work xi . w of the contact forces, not their potentials: with a
    // nonconvex law the two differ, and the work is what the step balances
    double friction_work = 0, damping = 0;
    for (const ContactNode<dim> &node : contact_nodes)
      if (node.locally_owned)
        {
          Tensor<1, dim> v;
          for (unsigned int c = 0; c < dim; ++c)
            v[c] = velocity[node.dofs[c]];
          const auto [normal, tangential] =
            nodal::contact_work(node,
                                v,
                                nodal_vector(node, law_traction) * node.normal,
                                *law,
                                *friction);
          damping += normal;
          friction_work += tangential;
        }
    energy.friction_dissipation +=
      k * Utilities::MPI::sum(friction_work, mpi_communicator);
    energy.damping_dissipation +=
      k * Utilities::MPI::sum(damping, mpi_communicator);
  }

  template <int dim>
  void
  ContactProblem<dim>::check_convexity(const std::string &context)
  {
    // J_n is strongly convex if K (rho/k M + A for the dynamic left point,
    // the K of the class and scheme otherwise: doc/theory.md, section 9.5)
    // dominates the nodal form
    // N = sum_i m_i (alpha_nu nu nu + alpha_tau,i (I - nu nu)) of the laws'
    // nonconvexity (doc/theory.md, section 7). Without friction remainder
    // (alpha_tau = 0) the bound is stated for alpha_nu: the smallest
    // eigenvalue of K0 against sum m_i nu nu, to be compared with alpha_nu.
    // N grows with every alpha_tau,i, so the check covers every later step
    // whose alpha_tau,i stay below convexity.checked_alpha_tau (the values
    // checked, times the room the bound leaves, at most the headroom).
    const double alpha = law->relaxed_monotonicity_constant();
    convexity.checked_alpha_tau.assign(contact_nodes.size(), 0.);
    convexity.largest_alpha_tau = 0;
    for (std::size_t i = 0; i < contact_nodes.size(); ++i)
      {
        convexity.checked_alpha_tau[i] =
          friction->relaxed_monotonicity_constant(
            contact_nodes[i].friction_bound);
        if (contact_nodes[i].locally_owned)
          convexity.largest_alpha_tau =
            std::max(convexity.largest_alpha_tau,
                     convexity.checked_alpha_tau[i]);
      }
    convexity.largest_alpha_tau =
      Utilities::MPI::max(convexity.largest_alpha_tau, mpi_communicator);
    convexity.with_friction = convexity.largest_alpha_tau > 0;
    if (alpha == 0 && !convexity.with_friction)
      {
        convexity.bound = std::numeric_limits<double>::infinity();
        return;
      }
    TimerOutput::Scope t(timer, "convexity check");

    const double alpha_nu = convexity.with_friction ? alpha : 1.;
    const auto   apply_n  = [&](const TrilinosWrappers::MPI::Vector &in,
                             TrilinosWrappers::MPI::Vector       &out) {
      out = 0;
      for (std::size_t i = 0; i < contact_nodes.size(); ++i)
        if (const ContactNode<dim> &node = contact_nodes[i]; node.locally_owned)
          {
            Tensor<1, dim> v;
            for (unsigned int c = 0; c < dim; ++c)
              v[c] = in[node.dofs[c]];
            const double   vn = v * node.normal;
            Tensor<1, dim> nv = alpha_nu * vn * node.normal;
            if (convexity.with_friction)
              nv += convexity.checked_alpha_tau[i] * (v - vn * node.normal);
            for (unsigned int c = 0; c < dim; ++c)
              out[node.dofs[c]] = node.mass * nv[c];
          }
      out.compress(VectorOperation::insert);
      base_constraints.set_zero(out);
    };
    const auto apply_k = constrained(step_matrix, base_constraints);
    // preconditioned by one cycle of the AMG of K0, which the steps reuse
    const auto precondition =
      constrained(preconditioner.step_amg(step_matrix), base_constraints);
    // start from the normal field on Gamma_3 (plus a tangential field when
    // friction counts)
    TrilinosWrappers::MPI::Vector x(locally_owned_dofs, mpi_communicator);
    for (const ContactNode<dim> &node : contact_nodes)
      if (node.locally_owned)
        {
          Tensor<1, dim> start = node.normal;
          if (convexity.with_friction)
            for (const Tensor<1, dim> &t : nodal::tangent_basis(node.normal))
              start += t;
          for (unsigned int c = 0; c < dim; ++c)
            x[node.dofs[c]] = start[c];
        }
    x.compress(VectorOperation::insert);
    base_constraints.set_zero(x);
    const EigenvalueEstimate estimate =
      largest_generalized_eigenvalue(apply_n,
                                     apply_k,
                                     precondition,
                                     x,
                                     convexity_residual_tolerance,
                                     convexity_max_iterations);
    // value 0: N vanishes on the free dofs, and every alpha is admissible
    convexity.bound = estimate.value > 0 ?
                        1. / estimate.value :
                        std::numeric_limits<double>::infinity();
    if (estimate.value > 0 && !estimate.converged &&
        Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      std::cerr << "hemicontact: warning: the convexity estimate did not "
                   "converge in "
                << convexity_max_iterations << " iterations (relative residual "
                << estimate.relative_residual
                << "); the bound it reports may be too large, i.e. the step "
                   "may be less convex than stated."
                << std::endl;

    const bool convex =
      convexity.with_friction ? convexity.bound > 1 : alpha < convexity.bound;
    if (convexity.with_friction && convex)
      for (double &checked : convexity.checked_alpha_tau)
        checked *= std::min(convexity.bound, convexity_recheck_headroom);
    // during the run, a step that stays non-convex is not named again
    const bool report      = context.empty() || convexity.steps_convex;
    convexity.steps_convex = convex;
    if (!convex && report)
      {
        std::ostringstream message;
        if (convexity.with_friction)
          message << "the step energy J_n is not convex for this time step: "
                     "the laws' relaxed-monotonicity constants alpha_nu = "
                  << alpha << " (normal law) and alpha_tau up to "
                  << convexity.largest_alpha_tau << " (friction law '"
                  << friction->name() << "') are too large for ("
                  << scheme.step_matrix_name()
                  << "): its smallest "
                     "eigenvalue against sum m_i (alpha_nu nu nu + alpha_tau "
                     "(I - nu nu)) is estimated at "
                  << convexity.bound
                  << ", below 1 (the convexity condition of the step "
                     "problem, doc/theory.md sections 7 and 9.5). Newton may "
                     "fail or the step may have several solutions; "
                  << scheme.convexity_remedy(time_step)
                  << " or the laws' nonmonotonicity (e.g. a larger "
                     "characteristic slip speed).";
        else
          message
            << "the step energy J_n is not convex for this time step: the "
               "normal law's relaxed-monotonicity constant alpha = "
            << alpha << " is not below the estimated smallest eigenvalue "
            << convexity.bound << " of (" << scheme.step_matrix_name()
            << ") against the normal boundary mass "
               "(the convexity condition of the step problem, cf. Han & Han 2019, (4.26); doc/theory.md section 9.5). Newton may fail "
               "or the step may have several solutions; "
            << scheme.convexity_remedy(time_step)
            << " or the law's nonmonotonicity.";
        if (parameters.nonlinear_solver.strict_convexity_check)
          {
            if (context.empty())
              throw InputError("nonlinear solver: " + message.str());
            throw SolverFailure(context + message.str());
          }
        if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
          std::cerr << "hemicontact: warning: " << context << message.str()
                    << std::endl;
      }
  }

  template <int dim>
  std::optional<std::string>
  convexity_recheck(const ProblemState<dim> &state, const double t)
  {
    // a bound from u_nu or t may raise alpha_tau above what was checked
    const std::vector<ContactNode<dim>> &nodes = state.contact_nodes;
    const std::vector<double> &checked = state.convexity.checked_alpha_tau;
    int                        grew    = checked.size() != nodes.size();
    for (std::size_t i = 0; i < nodes.size() && !grew; ++i)
      grew = nodes[i].locally_owned &&
             state.friction_law.relaxed_monotonicity_constant(
               nodes[i].friction_bound) > checked[i];
    if (Utilities::MPI::max(grew, state.mpi_communicator) == 0)
      return std::nullopt;
    std::ostringstream context;
    context << "at t = " << t
            << " (the friction bound or the mesh changed since the last "
               "convexity check) ";
    return context.str();
  }

#define HEMICONTACT_INSTANTIATE(dim)                                            \
  template void         ContactProblem<dim>::update_energy_balance(const bool); \
  template StoredEnergy stored_energy(const ProblemState<dim> &);               \
  template void ContactProblem<dim>::check_convexity(const std::string &);      \
  template std::optional<std::string> convexity_recheck(                        \
    const ProblemState<dim> &, const double);

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
