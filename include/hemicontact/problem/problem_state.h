#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/coupling/coupled_fields.h>
#include <hemicontact/coupling/mechanical_view.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/friction_law.h>
#include <hemicontact/laws/normal_law.h>
#include <hemicontact/memory/memory_history.h>
#include <hemicontact/mesh/discretization.h>
#include <hemicontact/model/contact_node.h>
#include <hemicontact/model/energy_balance.h>
#include <hemicontact/model/kelvin_voigt.h>
#include <hemicontact/model/step_scheme.h>
#include <hemicontact/solver/step_preconditioner.h>
#include <hemicontact/state/added_fields.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /** The last check of the convexity of the step energy (diagnostics.cc). */
  struct ConvexityCheck
  {
    /**
     * Estimated smallest eigenvalue of K0 against sum m_i nu nu (0 if not
     * computed); with a friction law that has alpha_tau > 0, against
     * sum m_i (alpha_nu nu nu + alpha_tau (I - nu nu)), so that each step
     * is strongly convex iff it exceeds 1.
     */
    double bound = 0;
    /** Whether the bound includes the friction law's alpha_tau. */
    bool with_friction = false;
    /** The largest alpha_tau over the contact nodes at the check. */
    double largest_alpha_tau = 0;
    /** alpha_tau of each contact node that the check covers. */
    std::vector<double> checked_alpha_tau;
    /** Whether the check found the steps strongly convex. */
    bool steps_convex = true;
  };

  /**
   * A read-only view of the discretization and the state, for the run's
   * output, its checkpoints and tests.
   */
  template <int dim>
  struct ProblemState
  {
    const Parameters                     &parameters;
    MPI_Comm                              mpi_communicator;
    const Discretization<dim>            &discretization;
    const DoFHandler<dim>                &dof_handler;
    const IndexSet                       &locally_owned_dofs;
    const IndexSet                       &locally_relevant_dofs;
    const KelvinVoigtMaterial<dim>       &material;
    const NormalLaw                      &normal_law;
    const FrictionLaw                    &friction_law;
    const TrilinosWrappers::SparseMatrix &step_matrix;    ///< K0 = rho/k M + A
    const TrilinosWrappers::SparseMatrix &mass_matrix;    ///< rho M
    const TrilinosWrappers::SparseMatrix &elastic_matrix; ///< B
    /** Hanging nodes and u = 0 on Gamma_1. */
    const AffineConstraints<double>     &base_constraints;
    const TrilinosWrappers::MPI::Vector &velocity;     ///< w_n
    const TrilinosWrappers::MPI::Vector &old_velocity; ///< w_{n-1}
    const TrilinosWrappers::MPI::Vector &displacement; ///< u_n
    /** b = rho/k M w_{n-1} - B u_n + F_n of the last step. */
    const TrilinosWrappers::MPI::Vector &step_rhs;
    /** Nodal traction -(K w - b)_i / m_i at owned contact node dofs. */
    const TrilinosWrappers::MPI::Vector &contact_traction;
    const std::vector<ContactNode<dim>> &contact_nodes;
    const StepPreconditioner<dim>       &preconditioner;
    const EnergyBalance                 &energy;
    const ConvexityCheck                &convexity;
    /** The problem class and time scheme of the run. */
    const StepScheme &scheme;
    double            time; ///< t_n = n k
    double            time_step;
    /** Length of the last converged step (0: none yet). */
    double       last_step_length;
    unsigned int step_number;
    unsigned int n_steps;
    /** The history of the memory term of the stress. */
    const MemoryHistory<dim> &memory;
    /**
     * Whether the time step is above the memory rule's stability limit
     * (allowed by 'time/allow unstable time step').
     */
    bool memory_rule_unstable;
    /** The coupled fields of the run (the temperature among them). */
    const CoupledFields<dim> &coupled_fields;
    /** The fields added to the state (the coupled fields' among them). */
    const AddedFields<dim> &added_fields;
  };

  /** What the coupled fields read of @p state. */
  template <int dim>
  MechanicalView<dim>
  mechanical_view(const ProblemState<dim> &state)
  {
    return {state.discretization,
            state.dof_handler,
            state.locally_owned_dofs,
            state.locally_relevant_dofs,
            state.base_constraints,
            state.velocity,
            state.displacement,
            state.contact_traction,
            state.contact_nodes,
            state.time,
            state.scheme.held_displacement_offset(state.time_step),
            state.scheme.is_static(),
            state.added_fields};
  }

  /**
   * Whether an adaptation is due after the step just taken: every
   * 'adaptivity/interval' steps (never if 0), and not after the last step.
   */
  template <int dim>
  bool
  adaptation_due(const ProblemState<dim> &state)
  {
    const unsigned int every = state.parameters.adaptivity.interval;
    return every != 0 && state.step_number % every == 0 &&
           state.step_number < state.n_steps;
  }

  /** The energy stored in the state (doc/theory.md 9.3, 13.4). */
  struct StoredEnergy
  {
    double kinetic = 0; ///< rho/2 |w_n|^2
    double elastic = 0; ///< 1/2 a_B(u, u), u held after step n
    /** The coupled fields' stored terms in EnergyBalance::coupled's
     *  layout (the others zero). */
    std::vector<double> coupled =
      std::vector<double>(coupled_energy_terms().size(), 0.);

    /** The change from @p before (in the order of the terms, so that a
     *  run without coupled fields books the same number as it always has). */
    double
    change_from(const StoredEnergy &before) const
    {
      double change = kinetic + elastic;
      for (const double e : coupled)
        change += e;
      change -= before.kinetic;
      change -= before.elastic;
      for (const double e : before.coupled)
        change -= e;
      return change;
    }

    /** The stored terms into @p energy. */
    void
    book_into(EnergyBalance &energy) const
    {
      energy.kinetic                           = kinetic;
      energy.elastic                           = elastic;
      const std::vector<EnergyTermSpec> &terms = coupled_energy_terms();
      for (std::size_t i = 0; i < terms.size(); ++i)
        if (terms[i].role == EnergyRole::stored)
          energy.coupled[i] = coupled[i];
    }
  };

  /** The stored energy now (diagnostics.cc). */
  template <int dim>
  StoredEnergy
  stored_energy(const ProblemState<dim> &state);

  /**
   * The context of a convexity check due at time @p t, if a node's
   * alpha_tau exceeds the value last checked or the contact nodes changed
   * (a new mesh); none if the last check still covers the steps
   * (diagnostics.cc).
   */
  template <int dim>
  std::optional<std::string>
  convexity_recheck(const ProblemState<dim> &state, const double t);
} // namespace hemicontact
