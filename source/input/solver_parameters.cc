// The solver subsections of the parameter file ('nonlinear solver',
// 'linear solver'); the other subsections are in parameters.cc. The
// solver's tuning constants are not parameters: see solver_tuning.h.
#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/input/selection.h>

#include <string>

namespace hemicontact
{
  namespace
  {
    const SelectionNames<InitialGuess> initial_guesses = {
      {"extrapolated", InitialGuess::extrapolated},
      {"previous", InitialGuess::previous}};
    const SelectionNames<LinearSolverType> linear_solver_types = {
      {"cg amg", LinearSolverType::cg_amg},
      {"direct", LinearSolverType::direct}};
    const SelectionNames<ForcingTerm> forcing_terms = {
      {"eisenstat-walker", ForcingTerm::eisenstat_walker},
      {"fixed", ForcingTerm::fixed}};
  } // namespace

  void
  NonlinearSolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("nonlinear solver");
    prm.declare_entry("tolerance",
                      "1e-8",
                      Patterns::Double(0),
                      "A step has converged when no contact node changes "
                      "branch and the nonsmooth residual (equilibrium and "
                      "complementarity) is below this times the norm of the "
                      "step's load.");
    prm.declare_entry("max iterations",
                      "50",
                      Patterns::Integer(1),
                      "Newton iterations allowed in one step; a step that "
                      "needs more fails (see 'time step halvings').");
    prm.declare_entry(
      "time step halvings",
      "0",
      Patterns::Integer(0, 10),
      "When Newton fails, retry the interval as two steps of k/2, "
      "recursively up to this many times; 0: stop with a checkpoint of the "
      "last converged step.");
    prm.declare_entry(
      "line search",
      "true",
      Patterns::Bool(),
      "Expert: damp each Newton update by backtracking on the step "
      "energy J_n (needed for nonconvex laws).");
    prm.declare_entry("initial guess",
                      "extrapolated",
                      selection_pattern(initial_guesses),
                      "Expert: where Newton starts, 'extrapolated' w_{n-1} + "
                      "k_n/k_{n-1} (w_{n-1} - w_{n-2}), or 'previous' "
                      "w_{n-1}. Changes the cost, not the solution.");
    prm.declare_entry("strict convexity check",
                      "false",
                      Patterns::Bool(),
                      "If the per-step convexity condition fails for the "
                      "chosen time step: stop with an error (true) or warn "
                      "(false).");
    prm.declare_entry(
      "friction bound tolerance",
      "1e-8",
      Patterns::Double(0),
      "A friction bound that depends on the step's unknown (u_nu or p_nu in "
      "the static class, w_nu in the velocity classes) is found by "
      "fixed-point iterations on the bound (doc/theory.md, sections 9.8 and "
      "9.9); they stop when no nodal bound changes by more than this times "
      "the largest bound.");
    prm.declare_entry("friction bound iterations",
                      "30",
                      Patterns::Integer(1),
                      "Fixed-point iterations on the friction bound allowed "
                      "in one step; a step whose bound has not settled by "
                      "then fails (see 'time step halvings').");
    prm.leave_subsection();
  }

  void
  NonlinearSolverParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("nonlinear solver");
    tolerance          = prm.get_double("tolerance");
    max_iterations     = prm.get_integer("max iterations");
    time_step_halvings = prm.get_integer("time step halvings");
    line_search        = prm.get_bool("line search");
    initial_guess      = get_selection(prm, "initial guess", initial_guesses);
    strict_convexity_check = prm.get_bool("strict convexity check");
    bound_tolerance        = prm.get_double("friction bound tolerance");
    bound_iterations       = prm.get_integer("friction bound iterations");
    prm.leave_subsection();
  }

  void
  LinearSolverParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("linear solver");
    prm.declare_entry("type",
                      "cg amg",
                      selection_pattern(linear_solver_types),
                      "'cg amg': conjugate gradients with an AMG-based "
                      "preconditioner (any size, any number of ranks); "
                      "'direct': a sparse direct solve of each Newton system "
                      "(Amesos KLU), a reference for small problems.");
    prm.declare_entry("forcing term",
                      "eisenstat-walker",
                      selection_pattern(forcing_terms),
                      "Expert: how far each Krylov solve goes. "
                      "'eisenstat-walker' follows the decrease of the Newton "
                      "residual; 'fixed' always solves to 'relative "
                      "tolerance'. Changes the cost, not the solution.");
    prm.declare_entry("relative tolerance",
                      "1e-10",
                      Patterns::Double(0),
                      "Expert: Krylov tolerance relative to the right-hand "
                      "side, the accuracy of every linear solve (at most the "
                      "Newton tolerance).");
    prm.declare_entry("max iterations",
                      "1000",
                      Patterns::Integer(1),
                      "Expert: Krylov iterations allowed in one linear "
                      "solve.");
    prm.leave_subsection();
  }

  void
  LinearSolverParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("linear solver");
    type               = get_selection(prm, "type", linear_solver_types);
    forcing_term       = get_selection(prm, "forcing term", forcing_terms);
    relative_tolerance = prm.get_double("relative tolerance");
    max_iterations     = prm.get_integer("max iterations");
    prm.leave_subsection();
  }
} // namespace hemicontact
