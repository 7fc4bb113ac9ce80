#pragma once

#include <deal.II/base/timer.h>
#include <deal.II/lac/trilinos_vector.h>

#include <string>

namespace hemicontact
{
  using namespace dealii;

  /**
   * One time step as ActiveSetNewton sees it: the minimisation of
   *
   *   J_n(w) = 1/2 w.K0 w - b.w + Phi(w),
   *
   * with K0 symmetric positive definite and Phi a sum of node-wise
   * (nonsmooth, possibly nonconvex) terms, solved by choosing a branch at
   * every node and solving the linearisation on those branches
   * (doc/theory.md section 3).
   *
   * update_branches() evaluates the node-wise quantities that
   * nonsmooth_residual() and solve_linearized() then use.
   */
  class ActiveSetProblem
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    virtual ~ActiveSetProblem() = default;

    /** residual = K0 w - b (zero in constrained rows). */
    virtual void
    residual(const VectorType &w, VectorType &residual) const = 0;

    /** The norm of b: the scale of the relative tolerance. */
    virtual double
    load_norm() const = 0;

    /**
     * |K0 w| from @p residual = K0 w - b: with |b|, the scale of the
     * round-off in the residual. 0 by default (a problem whose residual
     * carries no held offsets).
     */
    virtual double
    operator_norm(const VectorType & /*residual*/) const
    {
      return 0;
    }

    /**
     * Choose every node's branches at (w, residual) for Newton iteration
     * @p iteration of the step (from 0); returns how many nodes changed
     * branch, summed over all ranks.
     */
    virtual unsigned int
    update_branches(const VectorType  &w,
                    const VectorType  &residual,
                    const unsigned int iteration) = 0;

    /**
     * The nonsmooth residual: equilibrium off the contact nodes and the
     * node-wise complementarity functions (as forces) on them.
     */
    virtual double
    nonsmooth_residual(const VectorType &residual) const = 0;

    /**
     * The minimiser @p trial of the quadratic model of J_n on the current
     * branches about @p w; an iterative solve stops when its residual has
     * dropped by @p reduction (0: never) or below @p absolute_tolerance.
     * Returns the number of Krylov iterations (1 for a direct solve).
     */
    virtual unsigned int
    solve_linearized(const VectorType &w,
                     const double      reduction,
                     const double      absolute_tolerance,
                     VectorType       &trial) = 0;

    /** k_d = K0 d, d without its constrained entries. */
    virtual void
    apply_quadratic(const VectorType &d, VectorType &k_d) const = 0;

    /** Phi(w), the node-wise part of J_n. */
    virtual double
    nodal_energy(const VectorType &w) const = 0;

    /**
     * Move @p w into the feasible set of Phi where it has one (the nodal
     * walls w . nu <= limit: doc/theory.md section 10), so that the line search
     * runs between feasible points. Nothing by default.
     */
    virtual void
    make_feasible(VectorType &) const
    {}
  };

  /**
   * The semismooth Newton / primal-dual active-set method of one step:
   * update the branches, test convergence on the nonsmooth residual, solve
   * the linearisation inexactly (Eisenstat-Walker forcing terms) and damp
   * the update by backtracking on J_n. Knows nothing of meshes or laws.
   */
  class ActiveSetNewton
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    struct Settings
    {
      /** Converged: no branch changed and residual <= tolerance |b| +
       *  roundoff_tolerance (|b| + |K0 w|) (or 100 times below that). */
      double       tolerance           = 1e-8;
      double       roundoff_tolerance  = 1e-14;
      unsigned int max_iterations      = 50;
      bool         line_search         = true;
      double       minimum_step_length = 1e-3;
      /** Krylov reduction eta_k by Eisenstat-Walker (else 0: to the floor). */
      bool   eisenstat_walker         = true;
      double maximum_forcing_term     = 0.01;
      bool   exact_solve_when_settled = true;
      /** The Krylov floor, a fraction of the Newton target. */
      double krylov_floor_fraction = 0.5;
      /** For the failure message: the linear solver's relative tolerance. */
      double linear_relative_tolerance = 1e-10;
    };

    /** What one solve() did. */
    struct Report
    {
      unsigned int newton_iterations      = 0;
      unsigned int linear_iterations      = 0;
      unsigned int line_search_reductions = 0;
      double       relative_residual      = 0; ///< residual / |b|
    };

    /** @p timer (optional) gets the section "line search". */
    ActiveSetNewton(const Settings &settings, TimerOutput *timer = nullptr);

    /**
     * Minimise J_n of @p problem from @p w; on return w is the solution and
     * @p residual = K0 w - b. Throws SolverFailure (with the reason) if the
     * residual is not finite or 'max iterations' do not suffice.
     */
    Report
    solve(ActiveSetProblem &problem, VectorType &w, VectorType &residual) const;

  private:
    /**
     * Move @p w towards @p trial by the backtracking step length on J_n and
     * update @p residual to the new w by the product K0 d that the line
     * search needs anyway.
     */
    void
    line_search(const ActiveSetProblem &problem,
                VectorType             &w,
                const VectorType       &trial,
                VectorType             &residual,
                unsigned int           &n_reductions) const;

    /**
     * Why 'max iterations' did not suffice, from the @p relative_residual
     * and @p n_changed of the last iteration, the factor @p last_reduction
     * of the residual over the step before it and the number of
     * @p settled_iterations before it in a row with no branch changed:
     * nodes still changing branch, an iteration cut short by the limit
     * (the branches settled in the last iteration, or the residual still
     * falling), or a stall on fixed branches.
     */
    std::string
    failure_message(double       relative_residual,
                    unsigned int n_changed,
                    double       last_reduction,
                    unsigned int settled_iterations) const;

    Settings     settings;
    TimerOutput *timer;
  };
} // namespace hemicontact
