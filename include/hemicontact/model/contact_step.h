#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/friction_law.h>
#include <hemicontact/laws/normal_law.h>
#include <hemicontact/model/contact_node.h>
#include <hemicontact/solver/active_set_newton.h>
#include <hemicontact/solver/linear_solver.h>
#include <hemicontact/solver/step_preconditioner.h>

#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /** The Newton settings of the 'nonlinear solver' and 'linear solver'
   *  parameters and the solver tuning. */
  ActiveSetNewton::Settings
  newton_settings(const Parameters &parameters);

  /**
   * @p v with the entries @p constraints constrains (hanging nodes,
   * Gamma_1) zeroed.
   */
  TrilinosWrappers::MPI::Vector
  without_constrained(const TrilinosWrappers::MPI::Vector &v,
                      const AffineConstraints<double>     &constraints);

  /** The pieces of a mesh that one time step reads, and the solvers it uses. */
  template <int dim>
  struct StepSystem
  {
    const TrilinosWrappers::SparseMatrix &step_matrix; ///< K0, condensed
    const TrilinosWrappers::MPI::Vector  &step_rhs;    ///< b, condensed
    const AffineConstraints<double>      &base_constraints;
    const IndexSet                       &locally_owned_dofs;
    const IndexSet                       &locally_relevant_dofs;
    /** Locally relevant contact nodes; their branches are updated. */
    std::vector<ContactNode<dim>> &contact_nodes;
    const NormalLaw               &law;
    const FrictionLaw             &friction;
    LinearSolver                  &linear_solver;
    StepPreconditioner<dim>       &preconditioner;
    TimerOutput                   &timer;
    MPI_Comm                       mpi_communicator;
  };

  /**
   * One time step of the contact problem as an ActiveSetProblem: K0 and b
   * of the step, the node-wise branches and complementarity functions of
   * the laws (nodal::), and the projected Newton operator solved by CG with
   * the StepPreconditioner, or directly ('linear solver/type = direct').
   */
  template <int dim>
  class ContactStep : public ActiveSetProblem
  {
  public:
    ContactStep(const StepSystem<dim> &system, const Parameters &parameters);

    void
    residual(const VectorType &w, VectorType &residual) const override;

    double
    load_norm() const override;

    double
    operator_norm(const VectorType &residual) const override;

    unsigned int
    update_branches(const VectorType  &w,
                    const VectorType  &residual,
                    const unsigned int iteration) override;

    double
    nonsmooth_residual(const VectorType &residual) const override;

    unsigned int
    solve_linearized(const VectorType &w,
                     const double      reduction,
                     const double      absolute_tolerance,
                     VectorType       &trial) override;

    void
    apply_quadratic(const VectorType &d, VectorType &k_d) const override;

    double
    nodal_energy(const VectorType &w) const override;

    void
    make_feasible(VectorType &w) const override;

  private:
    /**
     * The vector x0 with w . nu = held_value at the owned nodes held away
     * from zero (breakpoint, wall, and stick at a law_offset) and zero
     * elsewhere, and whether any
     * rank has one: the inhomogeneous part of the constraints.
     */
    bool
    held_offset(VectorType &x0) const;

    StepSystem<dim>        system;
    const LinearSolverType solver_type;
    const double           linear_relative_tolerance;
    const bool             gradual_normal_branches;
    /** w and K0 w - b of the current iteration, with ghost entries. */
    VectorType w_ghosted;
    VectorType residual_ghosted;
    /** The state of every contact node at the current iterate. */
    std::vector<NodeState<dim>> node_states;
  };
} // namespace hemicontact
