#pragma once

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/contact_laws.h>
#include <hemicontact/laws/normal_law.h>
#include <hemicontact/memory/memory_history.h>
#include <hemicontact/mesh/discretization.h>
#include <hemicontact/model/contact_node.h>
#include <hemicontact/model/energy_balance.h>
#include <hemicontact/model/kelvin_voigt.h>
#include <hemicontact/model/problem_data.h>
#include <hemicontact/model/step_scheme.h>
#include <hemicontact/problem/error_estimator.h>
#include <hemicontact/problem/problem_state.h>
#include <hemicontact/solver/linear_solver.h>
#include <hemicontact/solver/step_preconditioner.h>
#include <hemicontact/solver/step_statistics.h>
#include <hemicontact/state/added_fields.h>
#include <hemicontact/state/state_field.h>
#include <hemicontact/state/state_source.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * Whether this rank prints the run's terminal lines: rank 0, unless
   * 'output/terminal = quiet'.
   */
  inline bool
  terminal_output_on(const Parameters &parameters, MPI_Comm comm)
  {
    return Utilities::MPI::this_mpi_process(comm) == 0 &&
           parameters.output.terminal != TerminalOutput::quiet;
  }

  /**
   * The contact problem of every class (doc/theory.md sections 1-9): the
   * dynamic one of Han & Han (2019), Problem 4.4 -- a Kelvin-Voigt body, a
   * normal damped response law and a friction law on Gamma_3, backward
   * Euler in the velocity, the left-point rule for the displacement, P1/Q1
   * elements, nodal quadrature on Gamma_3 -- and the quasistatic and static
   * classes and the implicit rule, whose step matrix, right-hand side and
   * update StepScheme holds. A MemoryHistory adds the relaxation memory of
   * the stress, the normal memory, the accumulated slip and wear (section
   * 11).
   *
   * Each time step minimises the step energy J_n by a semismooth Newton /
   * primal-dual active-set method (doc/theory.md section 3).
   *
   * A driver runs it through its public step interface (setup(),
   * resume(), advance(), adapt_mesh(), state(), fields()): Simulation
   * (source/simulation/) with the output and the checkpoints, the
   * convergence study, the tests. The state is one list of named fields
   * (fields(), state_fields.cc), which checkpoints, resume, adaptation and
   * the output loop over; add_field() adds one.
   *
   * The member functions are spread over source/problem/: setup.cc (mesh,
   * dofs, constraints, contact nodes, initial state), resume.cc (the same
   * from a StateSource), state_fields.cc (the list of the state's fields),
   * assembly.cc (matrices and loads), step.cc (one step, by
   * ActiveSetNewton on a ContactStep), diagnostics.cc (energies,
   * convexity), adaptivity.cc (the new mesh), residual_indicator.cc (the
   * error estimate) and run.cc (advance() and its interval with the
   * halvings). What reads the state and not the members is a free function
   * of a ProblemState (problem_state.h): the time-step limits
   * (stability.h), the wall checks (wall_admissibility.h), the indicators
   * (error_indicators.h), the projection of a transferred state
   * (state_projection.h), the contact nodes (contact_node_setup.h), the
   * cell matrices (cell_matrices.h).
   */
  template <int dim>
  class ContactProblem
  {
  public:
    /** A problem with data from the expressions of the parameter file. */
    ContactProblem(const Parameters &parameters,
                   ContactLaws       laws,
                   MPI_Comm          comm);

    /** A problem with given data (e.g. derived from a manufactured solution).
     */
    ContactProblem(const Parameters &parameters,
                   ContactLaws       laws,
                   ProblemData<dim>  data,
                   MPI_Comm          comm);

    /**
     * @name The step interface: what a driver (Simulation, the
     * convergence study, a test) calls.
     */
    /** @{ */
    /** Mesh, dofs, constraints, contact nodes, matrices, initial state. */
    void
    setup();

    /**
     * setup() from the state that @p source holds (a checkpoint) instead
     * of the initial data.
     */
    void
    resume(StateSource<dim> &source);

    /**
     * Start again from t = 0 on the current mesh (the pre-refinement
     * restart): the initial state, step 0.
     */
    void
    restart()
    {
      initialize_state();
    }

    /** Advance one time step; throws SolverFailure if Newton fails. */
    StepStatistics
    advance();

    /**
     * Refine and coarsen the mesh by the indicator of the 'adaptivity'
     * parameters and move w_n, u_n to the new mesh; rebuilds dofs,
     * constraints, matrices, contact nodes and the preconditioner. Fills
     * the adaptation fields of @p stats (energies before and after).
     */
    void
    adapt_mesh(StepStatistics &stats);

    /**
     * Solve the step just taken again (the static class's load value on a
     * new mesh, from the transferred solution).
     */
    StepStatistics
    solve_again()
    {
      --step_number;
      return advance();
    }

    /** Free every AMG hierarchy (rebuilt when a step needs one). */
    void
    release_preconditioner()
    {
      preconditioner.clear();
    }

    /** The timer of the run's sections (the performance summary's). */
    TimerOutput &
    get_timer()
    {
      return timer;
    }

    /**
     * The error estimate of the current state (doc/theory.md section 12:
     * the residual estimate of ErrorEstimator, or with 'output/error
     * estimate = equilibrated' equilibrated_estimate()), computed once per
     * state: every indicator and output derived from it reads the same one.
     */
    const ErrorEstimate &
    error_estimate() const;

    /**
     * The estimate advance() evaluated with 'output/error estimate' for the
     * current step and mesh, or nullptr (not enabled, no step solved
     * since the start or the last adaptation).
     */
    const ErrorEstimate *
    last_error_estimate() const
    {
      return parameters.output.error_estimate &&
                 solved_revision == state_revision && step_number > 0 ?
               &error_estimate() :
               nullptr;
    }

    /**
     * Add a field to the state (before setup() or resume()): one entry,
     * and checkpoints, resume, adaptation and the output take it
     * (doc/extending.md, "The state"): plain_field() of a definition, or
     * a coupled field with its hooks but no energy terms (those of a
     * registered kind are in the registry). Throws InputError if its name
     * is taken.
     */
    void
    add_field(std::unique_ptr<CoupledField<dim>> field);

    /** The added fields (their vectors, to set and to read). */
    AddedFields<dim> &
    get_added_fields()
    {
      return added_fields;
    }

    /**
     * The state as its one list of named fields: w_n, u_n, the contact
     * traction, w_{n-1}, the branches, the memory's history and the added
     * fields (state_fields.cc); read only.
     */
    std::vector<StateField<dim>>
    fields() const;

    /** Whether the final time has been reached. */
    bool
    finished() const
    {
      return step_number >= n_steps;
    }
    /** @} */

    /** @name Read access to the state (after setup()): state(). */
    /** @{ */
    using State = ProblemState<dim>;

    State
    state() const
    {
      return {parameters,
              mpi_communicator,
              discretization,
              dof_handler,
              locally_owned_dofs,
              locally_relevant_dofs,
              material,
              *law,
              *friction,
              step_matrix,
              mass_matrix,
              elastic_matrix,
              base_constraints,
              velocity,
              old_velocity,
              displacement,
              step_rhs,
              contact_traction,
              contact_nodes,
              preconditioner,
              energy,
              convexity,
              scheme,
              step_number * time_step,
              time_step,
              last_step_length,
              step_number,
              n_steps,
              memory,
              memory_rule_unstable,
              coupled_fields,
              added_fields};
    }
    /** @} */

  private:
    /** @name setup.cc */
    /**
     * Dofs, constraints (hanging nodes, u = 0 on Gamma_1), constant
     * matrices, contact nodes (collect_contact_nodes()) with their friction
     * bounds, AMG modes, the memory's vectors.
     */
    void
    setup_on_current_mesh();
    /**
     * u_0 and w_0 from the data; where the class asks for it, w_0 as the
     * step problem at t_0 with the data u_0 (K = A, b = F_0 - B u_0,
     * doc/theory.md 9.2); in the static class with memory, u_0 as the
     * solution of load value 0, the memory sum's first state (section 11).
     */
    void
    initialize_state();
    /**
     * F_b at every contact node from 'data/friction bound' at time @p t,
     * u_nu from the displacement held (static class: from the step's
     * unknown), w_nu from the step's unknown and p_nu = traction . nu from
     * @p traction (by default contact_traction, the last solve's)
     * (doc/theory.md 7, 9.8, 9.9). Returns the largest change of a nodal
     * bound relative to the largest bound (0 if every bound is 0).
     */
    double
    update_friction_bounds(
      const double                         t,
      const TrilinosWrappers::MPI::Vector *traction = nullptr);

    /** @name assembly.cc */
    /**
     * rho M, B and the step matrix K = @p c.mass rho M + @p c.viscous A +
     * @p c.elastic B; A is not kept (doc/performance.md, "Memory").
     */
    void
    assemble_constant_matrices(const StepMatrixCoefficients &c);
    void
    assemble_load(const double time);
    void
    assemble_step_rhs();

    /** @name step.cc */
    /**
     * Solve the current step by ActiveSetNewton on a ContactStep; the wall
     * limits w by (g - u_nu)/@p wall_length (StepScheme::wall_step_length()).
     */
    StepStatistics
    solve_step(const double wall_length);
    /**
     * solve_step(), then, if the friction bound reads the step's own
     * unknown, the fixed point on it (iterate_friction_bound()) with the
     * bounds at time @p t and the pressure @p pressure
     * (update_friction_bounds()): the one solve of a step, of the initial
     * velocity and of the static initial state (@p initial: the latter
     * two, no convexity recheck).
     */
    StepStatistics
    solve_with_bound(const double                         t,
                     const TrilinosWrappers::MPI::Vector *pressure,
                     const double                         wall_length,
                     const bool                           initial);

    /** @name diagnostics.cc */
    void
    update_energy_balance(const bool initial);
    /**
     * Estimate the convexity bound of the step energy for the current
     * friction bounds and warn (or stop, with 'strict convexity check') if
     * a step may not be convex; @p context starts the message of a check
     * during the run, which warns only when the steps leave the convex
     * regime.
     */
    void
    check_convexity(const std::string &context = "");
    /** @name state_fields.cc */
    /**
     * The one list of the state's fields, with @p history the vectors of
     * the memory's history (MemoryHistory::saved_fields() or restore()).
     */
    std::vector<StateField<dim>>
    state_fields(const std::vector<TrilinosWrappers::MPI::Vector *> &history);
    /** @name run.cc */
    /**
     * One interval [start, start + k]: a step of size k, or if Newton
     * fails (and 'time step halvings' allows) two intervals of k/2;
     * @p following_k is the length of the interval after it (the wall's
     * limit in the left-point rule, StepScheme::wall_step_length()).
     */
    StepStatistics
    advance_interval(const double       start,
                     const double       k,
                     const unsigned int depth,
                     const double       following_k);
    /** Change k and what depends on it (step matrix, AMG). */
    void
    set_time_step(const double k);

    MPI_Comm           mpi_communicator;
    Parameters         parameters;
    ConditionalOStream pcout;
    TimerOutput        timer;

    KelvinVoigtMaterial<dim> material;
    /** What differs between the problem classes and time schemes. */
    StepScheme                   scheme;
    std::unique_ptr<NormalLaw>   law;
    std::unique_ptr<FrictionLaw> friction;
    ProblemData<dim>             data;
    /** The memory term of the stress: its history and its step functional. */
    MemoryHistory<dim> memory;
    /**
     * Whether the time step is above the memory rule's stability limit
     * (allowed by 'time/allow unstable time step'); set by
     * check_memory_stability().
     */
    bool memory_rule_unstable = false;
    /**
     * The coupled fields (doc/extending.md, "A coupled field"): those the
     * parameters enable (the temperature, doc/theory.md section 13), by the
     * registry, and those add_field() adds.
     */
    CoupledFields<dim> coupled_fields;

    Discretization<dim> discretization;
    DoFHandler<dim>     dof_handler;
    IndexSet            locally_owned_dofs;
    IndexSet            locally_relevant_dofs;

    /** Hanging nodes and u = 0 on Gamma_1. */
    AffineConstraints<double> base_constraints;
    /** The space of w, u and every displacement-like field of the state. */
    FieldSpace<dim> displacement_space;
    /** The fields added to the state (add_field()). */
    AddedFields<dim> added_fields;
    /** The branches as fields, filled when the state is saved. */
    mutable TrilinosWrappers::MPI::Vector branch_field;
    mutable TrilinosWrappers::MPI::Vector amg_branch_field;

    /**
     * Constant on a fixed mesh, condensed with the base constraints. The
     * viscous matrix A is not held: w.A w is formed from K, M and B.
     */
    TrilinosWrappers::SparseMatrix mass_matrix; ///< rho M
    TrilinosWrappers::SparseMatrix
      step_matrix; ///< K (StepScheme::step_matrix())
    TrilinosWrappers::SparseMatrix elastic_matrix; ///< B

    TrilinosWrappers::MPI::Vector velocity;     ///< w_n
    TrilinosWrappers::MPI::Vector old_velocity; ///< w_{n-1}
    TrilinosWrappers::MPI::Vector displacement; ///< u_n
    TrilinosWrappers::MPI::Vector load;         ///< F_n = (f0, f2, f3) tested
    TrilinosWrappers::MPI::Vector
      step_rhs; ///< b = rho/k M w_{n-1} - B u_n + F_n
    /**
     * The nodal traction -(K w - b)_i / m_i of the last solve at the owned
     * contact node dofs: the contact pressure p_nu = -sigma_nu of a
     * friction bound is its normal part. Checkpointed and moved to an
     * adapted mesh with the state.
     */
    TrilinosWrappers::MPI::Vector contact_traction;

    std::vector<ContactNode<dim>> contact_nodes; ///< locally relevant nodes
    LinearSolver                  linear_solver;
    /** Every AMG of the mesh and the preconditioner of the Newton solves. */
    StepPreconditioner<dim> preconditioner;
    EnergyBalance           energy;
    ConvexityCheck          convexity;

    /**
     * The state the members hold, changed by every solve, adaptation,
     * restart and resume; the revision of the last step solved.
     */
    unsigned int state_revision  = 0;
    unsigned int solved_revision = numbers::invalid_unsigned_int;
    /** error_estimate() of revision estimate_revision. */
    mutable ErrorEstimate cached_estimate;
    mutable unsigned int  estimate_revision = numbers::invalid_unsigned_int;

    double time_step = 0;
    /** Length of the last converged step (0: none yet). */
    double       last_step_length = 0;
    unsigned int n_steps          = 0;
    unsigned int step_number      = 0;
  };
} // namespace hemicontact
