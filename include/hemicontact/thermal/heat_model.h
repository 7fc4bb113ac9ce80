#pragma once

#include <deal.II/base/function.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/coupling/mechanical_view.h>
#include <hemicontact/expressions/expression.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/model/problem_data.h>
#include <hemicontact/solver/linear_solver.h>
#include <hemicontact/state/added_fields.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  /**
   * The heat step n tested with theta_n, times k (doc/theory.md, section
   * 13.4): with HeatModel::stored_heat() S, S(theta_n) - S(theta_{n-1}) +
   * numerical + dissipation = supply + coupling up to the solver
   * tolerance.
   */
  struct HeatStepEnergy
  {
    double numerical   = 0; ///< 1/2 c_theta |theta_n - theta_{n-1}|^2
    double dissipation = 0; ///< k (K grad theta_n, grad theta_n)
    /** k (q, theta_n) + k (q_N, theta_n)_{Gamma_N} + k sum_i m_i [k_e
     *  (theta_F - theta_n) + gamma |sigma_tau . w_tau| (+ g_3)]_i theta_n,i
     *  + the heat of the prescribed temperature's boundary */
    double supply   = 0;
    double coupling = 0; ///< -k (c_e div w_n, theta_n)
    /** k (c_e theta, div w_n) with the theta of the mechanical step's load
     *  (theta_{n-1}, or the iterated coupling's last): its share of the
     *  external work */
    double stress_work = 0;
    /** k sum_i m_i gamma |sigma_tau . w_tau|_i: the frictional heat in */
    double frictional_heat = 0;
    /** k sum_i m_i k_e,i (theta_F - theta_n)_i: the heat exchanged in */
    double exchanged_heat = 0;
  };

  /** What the heat model reports of the run (doc/theory.md, section 13.4). */
  struct HeatBalance
  {
    /** int c_theta theta_n of the last heat step and of theta_0. */
    double heat_content         = 0;
    double initial_heat_content = 0;
    /** CG iterations of the last heat step. */
    unsigned int linear_iterations = 0;
  };

  /**
   * The terms of the contact heat law at one contact node (doc/theory.md,
   * section 13.2): -K d_nu theta = k_e (theta - theta_F) - gamma |sigma_tau
   * . w_tau|.
   */
  struct NodeHeat
  {
    double temperature            = 0; ///< theta_i
    double exchange_coefficient   = 0; ///< k_e(x_i, t, u_nu,i)
    double foundation_temperature = 0; ///< theta_F(x_i, t)
    double frictional_power       = 0; ///< gamma |sigma_tau . w_tau|_i
    /** Whether the heat step books the law's terms here: not where theta
     *  is prescribed or hanging. */
    bool booked = true;

    /** k_e (theta_F - theta) where booked, else 0: the heat exchanged into
     *  the body per area. */
    double
    exchanged() const
    {
      return booked ?
               exchange_coefficient * (foundation_temperature - temperature) :
               0.;
    }

    /** gamma |sigma_tau . w_tau| where booked, else 0: the frictional heat
     *  entering the body per area. */
    double
    frictional() const
    {
      return booked ? frictional_power : 0.;
    }
  };

  /**
   * The temperature theta of the body (doc/theory.md, section 13): its
   * field of the state, the thermal stress load (c_e theta, div v) of the
   * mechanical step and the heat step of the staggered scheme,
   *
   *   (c_theta (theta_n - theta_{n-1})/k, eta) + (K grad theta_n, grad eta)
   *     + sum_i m_i k_e theta_n,i eta_i
   *   = -(c_e div w_n, eta) + (q, eta) + (q_N, eta)_{Gamma_N}
   *     + sum_i m_i [k_e theta_F + gamma |sigma_tau . w_tau|]_i eta_i,
   *
   * assembled with its constraints (hanging nodes, theta_D) and solved by
   * CG with the AMG of c_theta/k M + K, built once per mesh and step
   * length. In the static class theta is the data 'given temperature'.
   */
  template <int dim>
  class HeatModel
  {
  public:
    /** The data of @p parameters with the user @p constants; those of
     *  @p derived that are set replace them (a manufactured solution). */
    HeatModel(const TemperatureParameters &parameters,
              const std::string           &constants,
              const bool                   static_class,
              const HeatData<dim>         &derived,
              MPI_Comm                     comm);

    /** The name of theta in the state's list of fields. */
    static constexpr const char *field_name = "temperature";

    /**
     * The field theta of the state: P1/Q1 (@p simplex: FE_SimplexP(1)),
     * theta_0 (or the given theta at t = 0), saved, transferred, written.
     */
    FieldDefinition<dim>
    field(const bool simplex) const;

    /**
     * On a new mesh: theta's space @p theta_space, its sparsity and the
     * theta dof of each contact node of @p state; the thermal boundary ids
     * are checked to exist on the mesh (InputError).
     */
    void
    reinit(const FieldSpace<dim>     &theta_space,
           const MechanicalView<dim> &state);

    /**
     * Add the thermal stress load (c_e theta, div v) to @p load (the
     * displacement's space of @p state); in the static class @p theta is
     * set to the given theta at @p t first.
     */
    void
    add_thermal_stress(const double                   t,
                       const MechanicalView<dim>     &state,
                       TrilinosWrappers::MPI::Vector &theta,
                       TrilinosWrappers::MPI::Vector &load);

    /**
     * The heat step at t = @p t with step length @p k: @p theta holds
     * theta_{n-1} on entry and theta_n on return; w_n, u_n and the nodal
     * traction from @p state. Returns the step's energy terms.
     */
    HeatStepEnergy
    heat_step(const double                   t,
              const double                   k,
              const MechanicalView<dim>     &state,
              LinearSolver                  &solver,
              TrilinosWrappers::MPI::Vector &theta);

    /**
     * The contact heat law's terms at each contact node of @p state (in
     * their order) at time @p t, with theta from @p theta (owned entries)
     * and w, u and the nodal traction from @p state; the one place these
     * terms are evaluated, for the heat step and the contact CSV.
     */
    std::vector<NodeHeat>
    contact_heat(const double                         t,
                 const MechanicalView<dim>           &state,
                 const TrilinosWrappers::MPI::Vector &theta) const;

    /**
     * The cell averages the solution output writes beside stress_*:
     * thermal_stress = -c_e theta (the stress's part -c_e theta I, which
     * stress_* leaves out) and heat_flux_x, _y[, _z] = -K grad theta,
     * with theta from @p theta (owned entries).
     */
    std::vector<std::pair<std::string, Vector<float>>>
    cell_output(const TrilinosWrappers::MPI::Vector &theta) const;

    /** 1/2 int c_theta theta^2 of @p theta (owned entries), with the
     *  quadrature of the heat step's capacity term. */
    double
    stored_heat(const TrilinosWrappers::MPI::Vector &theta) const;

    /**
     * The largest c_e^2 / c_theta at the quadrature points of the mesh,
     * over all ranks: the coupling's strength that the staggered scheme's
     * time-step limit reads (doc/theory.md 13.2; coupling_ratio.cc).
     */
    double
    largest_coupling_ratio() const;

    /** Book int c_theta theta_0 (the start of a run); a theta_0 with a
     *  nodal value that is not a finite number is refused (InputError). */
    void
    start(const TrilinosWrappers::MPI::Vector &theta);

    const HeatBalance &
    balance() const
    {
      return heat;
    }

  private:
    /** The constraints of theta at time @p t: hanging nodes, theta_D(t),
     *  each value of theta_D checked to be a finite number. */
    void
    make_constraints(const double t);

    /**
     * c_theta, c_e and K (isotropic) at each quadrature point of each
     * locally owned cell, and the weights int c_theta phi_j; each checked
     * (finite, c_theta > 0, c_e >= 0, K > 0). On a new mesh.
     */
    void
    cache_coefficients();

    /**
     * The terms of the heat step at @p t of length @p k tested with
     * theta_n = @p theta_new from theta_{n-1} = @p theta_old (owned
     * entries, both meeting the constraints), by the energy matrices, the
     * step's source_load and coupling_load and the contact heat law's
     * terms @p nodes; the heat of the prescribed temperature's boundary
     * from the residual of its rows (heat_step_energy.cc).
     */
    HeatStepEnergy
    step_energy(const double                         t,
                const double                         k,
                const MechanicalView<dim>           &state,
                const TrilinosWrappers::MPI::Vector &theta_old,
                const TrilinosWrappers::MPI::Vector &theta_new,
                const std::vector<NodeHeat>         &nodes) const;

    /** K at a point where the cached isotropic value is @p kappa (the
     *  tensor of numbers where K is anisotropic). */
    Tensor<2, dim>
    conductivity_at(const double kappa) const
    {
      return conductivity ? kappa * unit_symmetric_tensor<dim>() :
                            conductivity_tensor;
    }

    /** The sparsity of theta's matrices condensed by @p with. */
    void
    make_sparsity(const AffineConstraints<double>   &with,
                  TrilinosWrappers::SparsityPattern &sparsity) const;

    /** capacity_matrix and conductivity_matrix on a new mesh. */
    void
    assemble_energy_matrices();

    /** @p theta with its hanging nodes' entries zero: the products with
     *  the condensed energy matrices are then those of the function. */
    TrilinosWrappers::MPI::Vector
    without_hanging(const TrilinosWrappers::MPI::Vector &theta) const;

    /** q_N at the quadrature points of @p fe_face (a face of a heat flux
     *  id) at time @p t into @p q_n. */
    void
    boundary_heat_flux(const FEFaceValues<dim> &fe_face,
                       const double             t,
                       std::vector<double>     &q_n) const;

    /** Whether face @p f of @p cell is on a heat flux id. */
    template <typename Cell>
    bool
    on_flux_boundary(const Cell &cell, const unsigned int f) const
    {
      return cell->face(f)->at_boundary() &&
             std::find(parameters.flux_ids.begin(),
                       parameters.flux_ids.end(),
                       cell->face(f)->boundary_id()) !=
               parameters.flux_ids.end();
    }

    /** int c_theta theta. */
    double
    heat_content(const TrilinosWrappers::MPI::Vector &theta) const;

    /** The vertex of theta's dof @p dof (a locally relevant one). */
    Point<dim>
    node_of(const types::global_dof_index dof) const;

    /**
     * The first owned entry of @p theta that is not a finite number into
     * @p error, as the value of the entry @p entry at its node at time
     * @p t (check_datum()).
     */
    void
    check_nodal_values(std::string                         &error,
                       const TrilinosWrappers::MPI::Vector &theta,
                       const std::string                   &entry,
                       const double                         t) const;

    TemperatureParameters          parameters;
    bool                           static_class;
    MPI_Comm                       mpi_communicator;
    std::shared_ptr<Function<dim>> heat_capacity;
    std::shared_ptr<Function<dim>> thermal_stress_coefficient;
    std::shared_ptr<Function<dim>> conductivity;
    Tensor<2, dim>                 conductivity_tensor;
    std::shared_ptr<Function<dim>> initial_temperature;
    std::shared_ptr<Function<dim>> heat_source;
    std::shared_ptr<Function<dim>> prescribed_temperature;
    std::shared_ptr<Function<dim>> heat_flux;
    std::shared_ptr<Function<dim>> foundation_temperature;
    std::shared_ptr<Function<dim>> given_temperature;
    std::unique_ptr<Expression>    exchange_coefficient;
    /** q_N and the Gamma_3 heat source of a manufactured solution */
    typename HeatData<dim>::NormalScalar normal_heat_flux, contact_heat_source;
    /** How the errors name the data: the entry, or what a manufactured
     *  solution derived them from. */
    struct DataNames
    {
      std::string initial_temperature, heat_source, prescribed_temperature,
        heat_flux, contact_heat_source;
    } names;

    const FieldSpace<dim>     *space          = nullptr;
    const Discretization<dim> *discretization = nullptr;
    /** The hanging nodes' constraints, and those with theta_D. */
    AffineConstraints<double> hanging_constraints, constraints;
    /** c_theta/k M + K for the step length operator_step_length. */
    TrilinosWrappers::SparseMatrix operator_matrix;
    double                         operator_step_length = 0;
    /** The AMG of operator_matrix, the heat step's preconditioner. */
    TrilinosWrappers::PreconditionAMG amg;
    /** operator_matrix plus the contact's sum_i m_i k_e,i at the step. */
    TrilinosWrappers::SparseMatrix matrix;
    TrilinosWrappers::MPI::Vector  rhs;
    /**
     * The energy identity's (doc/theory.md 13.4): int c_theta phi_i phi_j
     * and int K grad phi_i . grad phi_j with the hanging nodes condensed
     * (not theta_D), once per mesh; the step's loads (q, eta) + (q_N,
     * eta)_{Gamma_N} and -(c_e div w_n, eta), condensed alike.
     */
    TrilinosWrappers::SparseMatrix capacity_matrix, conductivity_matrix;
    TrilinosWrappers::MPI::Vector  source_load, coupling_load;
    /** The last thermal stress load (c_e theta, div v) that
     *  add_thermal_stress() added (the displacement's space). */
    TrilinosWrappers::MPI::Vector stress_load;
    /** The coefficients at the quadrature points, by cell (x only). */
    struct CellCoefficients
    {
      /** Values at cell active_cell_index * n_q + q. */
      std::vector<double> c_theta, c_e, kappa;
    } coefficients;
    /** int c_theta phi_j for every owned theta dof j. */
    TrilinosWrappers::MPI::Vector capacity_weights;
    /** The theta dof at each contact node (in the order of the nodes). */
    std::vector<types::global_dof_index> node_dofs;
    HeatBalance                          heat;
  };
} // namespace hemicontact
