#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <hemicontact/input/parameters.h>

#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The errors of doc/theory.md section 5 for one run against a manufactured
   * solution, with e_n = w(t_n) - w_n and ||v||_V = ||eps(v)||_L2:
   * E_H = max_n ||e_n||_L2, E_V = (k sum_n ||e_n||_V^2)^{1/2},
   * E_u = max_n ||u(t_n) - u_n||_V, and the same in the H1 seminorm; with
   * a temperature also E_theta and E_theta_H1.
   */
  struct ErrorNorms
  {
    double E_H    = 0;
    double E_V    = 0;
    double E_u    = 0;
    double E_V_H1 = 0;
    double E_u_H1 = 0;
    /**
     * (k sum_n |||e_n|||^2)^{1/2}, e_n the error of the step's unknown
     * (static: u) and |||v|||^2 = c_A a_A(v, v) + c_B a_B(v, v) with the
     * step matrix's coefficients: the norm the estimate bounds
     * (doc/theory.md 12.1).
     */
    double E_energy = 0;
    /**
     * With a manufactured temperature (doc/theory.md 13.6): E_theta =
     * max_n ||theta(t_n) - theta_n||_L2 and E_theta_H1 = (k sum_n
     * |theta(t_n) - theta_n|_H1^2)^{1/2}.
     */
    double E_theta = 0, E_theta_H1 = 0;
  };

  /** One level of a convergence study. */
  struct LevelResult
  {
    /** largest cell diameter of the final mesh, and the time step */
    double h = 0, k = 0;
    /** dofs of the final mesh, and the number of steps */
    unsigned int n_dofs = 0, n_steps = 0;
    /**
     * dofs of the meshes the steps ran on: their mean over the steps (the
     * time average, all steps having length k) and their maximum; both
     * equal n_dofs on a fixed mesh
     */
    double       mean_dofs = 0;
    unsigned int max_dofs  = 0;
    ErrorNorms   errors;
    /** Whether errors has E_theta and E_theta_H1. */
    bool         with_temperature       = false;
    double       mean_newton_iterations = 0;
    unsigned int max_newton_iterations  = 0;
    double       wall_seconds           = 0;
    /** Of those, the time loop: the steps, their errors and adaptations. */
    double step_wall_seconds = 0;
    /** shares of (node, step) pairs: separating, normal stick, damped,
     *  tangential stick, slip */
    double branch_share[5] = {0, 0, 0, 0, 0};
    /** shares of (node, step) pairs held at a breakpoint and at the wall */
    double breakpoint_share = 0;
    double wall_share       = 0;
    /** @name The error estimate ('output/error estimate', doc/theory.md 12) */
    bool estimated = false;
    /** (k sum_n eta_n^2)^{1/2} */
    double estimate = 0;
    /** estimate / E_energy */
    double effectivity = 0;
    /** interior, jumps, Neumann and contact terms, each (k sum_n .^2)^{1/2} */
    double estimate_terms[4] = {0, 0, 0, 0};
    /** The time indicator (velocity classes, doc/theory.md 12.4): (k sum_n
     *  |||w_n - w_{n-1}|||^2)^{1/2}; static class: none */
    bool   time_estimated = false;
    double estimate_time  = 0;
    /** (estimate^2 + estimate_time^2)^{1/2} / E_energy */
    double effectivity_total = 0;
  };

  /**
   * The parameters of level @p level of the study of @p parameters: 'h'
   * adds @p level to the global refinements (and, on an adaptive study, to
   * 'adaptivity/max level', and multiplies 'adaptivity/max cells' by
   * 2^(dim level)), 'k' divides the time step by 2^level, 'coupled' does
   * both.
   */
  Parameters
  study_parameters(const Parameters &parameters, const unsigned int level);

  /**
   * Run a manufactured-solution problem once or as a convergence study
   * (parameters.study): print a ConvergenceTable with observed orders and
   * write convergence.csv to the output directory. @p prm holds the parsed
   * file (the normal law is created from it for every level). Returns the
   * results per level.
   *
   * With 'adaptivity/interval' > 0 the mesh is adapted during each level
   * as in ContactProblem::run() (with the errors of each step computed
   * on the mesh it ran on), the levels are those of study_parameters(),
   * and the orders of 'h' and 'coupled' studies are taken against the mean
   * number of dofs.
   */
  template <int dim>
  std::vector<LevelResult>
  run_convergence_study(const Parameters &parameters,
                        ParameterHandler &prm,
                        MPI_Comm          comm);
} // namespace hemicontact
