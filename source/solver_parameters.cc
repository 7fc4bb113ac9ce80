// The solver subsections of the parameter file ('nonlinear solver',
// 'linear solver'); the other subsections are in parameters.cc.
#include <hemicontact/input_error.h>
#include <hemicontact/parameters.h>

#include <string>

namespace hemicontact
{
  void
  NonlinearSolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("nonlinear solver");
    prm.declare_entry("tolerance", "1e-8", Patterns::Double(0),
                      "Converged when no node changes branch and the "
                      "nonsmooth residual (equilibrium + complementarity) is "
                      "below this times the norm of the step's load. On the "
                      "examples, 1e-8 moves w by at most 4.3e-8 (relative) "
                      "against 1e-9, while one mesh refinement moves it by "
                      "2e-3 to 3e-2 (doc/performance.md); the manufactured-"
                      "solution studies set 1e-10.");
    prm.declare_entry("absolute tolerance", "1e-14", Patterns::Double(0),
                      "Absolute floor of the residual test (for unloaded "
                      "steps).");
    prm.declare_entry("max iterations", "50", Patterns::Integer(1),
                      "Iteration limit of one step; exceeding it stops the run "
                      "after writing the last converged state.");
    prm.declare_entry(
      "time step halvings", "0", Patterns::Integer(0, 10),
      "When Newton fails in a step, retry its interval with two steps of "
      "k/2, recursively up to this many times (reported on the terminal and "
      "in steps.csv); 0: stop with the message and a checkpoint of the last "
      "converged step.");
    prm.declare_entry("complementarity constant factor", "1",
                      Patterns::Double(0),
                      "The constant c of the node-wise projections is this "
                      "factor times diag(step matrix)_i / m_i.");
    prm.declare_entry("line search", "true", Patterns::Bool(),
                      "Backtracking on the step energy J_n.");
    prm.declare_entry("minimum step length", "1e-3", Patterns::Double(0, 1),
                      "Smallest damping factor tried by the line search.");
    prm.declare_entry(
      "initial guess", "extrapolated",
      Patterns::Selection("extrapolated|previous"),
      "Where Newton starts in a step: 'extrapolated': w_{n-1} + "
      "k_n/k_{n-1} (w_{n-1} - w_{n-2}), so the first active set already "
      "follows moving contact and stick-slip fronts (the first step, and the "
      "first after an adaptation or a resume, start from w_{n-1}); "
      "'previous': w_{n-1}. The converged w_n is the same either way, to the "
      "tolerance.");
    prm.declare_entry(
      "gradual normal branch changes", "true", Patterns::Bool(),
      "From the second Newton iteration of a step on, a node that the "
      "complementarity function would move from separating straight to "
      "damped, or back, is held at normal stick (w_nu = 0) for that "
      "iteration. Stops groups of nodes at the edge of a lifting "
      "contact zone from alternating between free and damped; the converged "
      "solution is the same. Laws without a jump (a = 0) are not affected.");
    prm.declare_entry("strict convexity check", "false", Patterns::Bool(),
                      "If the per-step convexity condition fails for the "
                      "chosen time step: stop with an error (true) or warn "
                      "(false).");
    prm.leave_subsection();
  }

  void
  NonlinearSolverParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("nonlinear solver");
    tolerance              = prm.get_double("tolerance");
    absolute_tolerance     = prm.get_double("absolute tolerance");
    max_iterations         = prm.get_integer("max iterations");
    time_step_halvings     = prm.get_integer("time step halvings");
    complementarity_factor = prm.get_double("complementarity constant factor");
    line_search            = prm.get_bool("line search");
    min_step_length        = prm.get_double("minimum step length");
    initial_guess          = prm.get("initial guess");
    gradual_normal_branches = prm.get_bool("gradual normal branch changes");
    strict_convexity_check = prm.get_bool("strict convexity check");
    prm.leave_subsection();
    require(complementarity_factor > 0,
            "nonlinear solver: 'complementarity constant factor' must be "
            "positive.");
  }

  void
  LinearSolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("linear solver");
    prm.declare_entry("type", "cg amg", Patterns::Selection("cg amg|direct"),
                      "'cg amg': conjugate gradients with Trilinos ML AMG "
                      "(rigid-body near-null space); 'direct': sparse direct "
                      "solver (Amesos KLU; small problems).");
    prm.declare_entry(
      "newton operator", "projected", Patterns::Selection("projected|assembled"),
      "How each Newton iteration gets its matrix (with 'cg amg'). "
      "'projected': the step matrix rho/k M + A and its AMG hierarchy are "
      "built once per mesh; an iteration only applies the nodal contact "
      "blocks and projects out the constrained directions. 'assembled': the "
      "Newton matrix is reassembled with the contact constraints and its AMG "
      "rebuilt in every iteration. 'direct' always assembles.");
    prm.declare_entry(
      "forcing term", "eisenstat-walker",
      Patterns::Selection("eisenstat-walker|fixed"),
      "Krylov stopping rule of a Newton iteration (projected operator). "
      "'eisenstat-walker': reduce the linear residual by eta_k = "
      "0.9 (r_k/r_{k-1})^2 (capped by 'maximum forcing term', never below "
      "what the Newton tolerance needs); 'fixed': 'relative tolerance'.");
    prm.declare_entry("maximum forcing term", "0.01", Patterns::Double(0, 1),
                      "Largest Eisenstat-Walker forcing term eta_k.");
    prm.declare_entry(
      "exact solve when settled", "true", Patterns::Bool(),
      "With 'eisenstat-walker': a Newton iteration in which no contact node "
      "changed branch solves to half the Newton target ('nonlinear "
      "solver/tolerance' times the load, plus its 'absolute tolerance') "
      "instead of eta_k. With the branches settled the step is smooth "
      "(linear for a piecewise linear law), so one accurate solve usually "
      "ends it; loose solves would add 1-3 Newton iterations per step "
      "(doc/performance.md).");
    prm.declare_entry(
      "constrained preconditioner", "true", Patterns::Bool(),
      "Projected operator: build the AMG hierarchy of each mesh at its first "
      "Newton solve from rho/k M + A plus a penalty on the directions that "
      "the contact branches of that iteration constrain, so that it treats "
      "stuck contact nodes as the Dirichlet conditions they are (the AMG of "
      "rho/k M + A alone treats them as free: 14.2 instead of 8.8 Krylov "
      "iterations per solve while Gamma_3 sticks at 3D r4, 23.5 instead of "
      "10 in the 0.8M-dof case; doc/performance.md). Once more than 5% of the contact nodes have "
      "freed a direction it constrains, the AMG of rho/k M + A is used "
      "instead until the next mesh. false: always the AMG of rho/k M + A.");
    prm.declare_entry(
      "preconditioner rebuild factor", "0", Patterns::Double(0),
      "Projected operator: the AMG hierarchy is rebuilt as for 'constrained "
      "preconditioner', from the current constraints, once the Krylov time "
      "lost since the last build (iterations per decade above those of the "
      "first solve after it) exceeds this factor times the time of one "
      "set-up. 0: never rebuild.");
    prm.declare_entry(
      "stiff contact threshold", "0.3", Patterns::Double(0),
      "Projected operator: at each contact node, the eigendirections of the "
      "nodal contact stiffness L_i that are stiffer than this factor times "
      "the diagonal of rho/k M + A (e.g. the slip stiffness next to a "
      "stick-slip front) are taken out of the AMG preconditioner and "
      "inverted node by node: 3D Krylov iterations per solve 5.0 / 5.6 / 6.9 "
      "instead of 11.3 / 16.6 / 23.1 at 3D r2 / r3 / r4 (doc/performance.md). "
      "0: off (the AMG sees only rho/k M + A).");
    prm.declare_entry("relative tolerance", "1e-10", Patterns::Double(0),
                      "Krylov tolerance relative to the right-hand side (the "
                      "floor of every linear solve).");
    prm.declare_entry("max iterations", "1000", Patterns::Integer(1),
                      "Krylov iteration limit.");
    prm.declare_entry("aggregation threshold", "1e-4", Patterns::Double(0),
                      "ML aggregation threshold.");
    prm.declare_entry("smoother sweeps", "2", Patterns::Integer(1),
                      "ML smoother sweeps.");
    prm.leave_subsection();
  }

  void
  LinearSolverParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("linear solver");
    type                  = prm.get("type");
    newton_operator       = prm.get("newton operator");
    forcing_term          = prm.get("forcing term");
    maximum_forcing_term  = prm.get_double("maximum forcing term");
    exact_solve_when_settled = prm.get_bool("exact solve when settled");
    constrained_preconditioner = prm.get_bool("constrained preconditioner");
    preconditioner_rebuild_factor =
      prm.get_double("preconditioner rebuild factor");
    stiff_contact_threshold = prm.get_double("stiff contact threshold");
    relative_tolerance    = prm.get_double("relative tolerance");
    max_iterations        = prm.get_integer("max iterations");
    aggregation_threshold = prm.get_double("aggregation threshold");
    smoother_sweeps       = prm.get_integer("smoother sweeps");
    prm.leave_subsection();
  }
} // namespace hemicontact
