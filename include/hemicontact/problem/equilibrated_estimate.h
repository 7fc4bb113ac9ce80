#pragma once

#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/model/problem_data.h>
#include <hemicontact/problem/error_estimator.h>
#include <hemicontact/problem/problem_state.h>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The equilibrated (Prager-Synge) error bound of the static step just
   * solved (doc/theory.md, section 12.5): a stress sigma^eq reconstructed
   * by local mixed problems on the vertex patches, its rows in
   * FE_RaviartThomas(1) (no symmetry constraint: the skew part is
   * minimised with the rest and bounded apart), div sigma^eq = -f0 up to its
   * Q1 projection on each cell, sigma^eq nu = f2 on Gamma_2 and f3 - xi~ on
   * Gamma_3 up to their P1 projections on each face, xi~ the continuous
   * piecewise-linear traction on Gamma_3 whose moments against the hat
   * functions are the nodal contact forces m_i xi_i of the solve. The terms per
   * cell, in the fields of ErrorEstimate:
   *
   * - @p jumps: |A^{-1/2}(sym sigma^eq - sigma_h)|^2_K +
   *   |skew sigma^eq|^2_K / (2 mu),
   * - @p interior: C_K^2 ((h_K/pi)^2 |r - r_K|^2_K + (diam/pi)^2
   *   |r_K|^2_K) / (2 mu), r = f0 + div sigma^eq, r_K its mean on K,
   * - @p neumann: C_K^2 h_E |g - sigma^eq nu|^2_E / (2 mu) on the faces off
   *   Gamma_1 (C_K^2 = 2 assumed),
   * - @p contact: |xi~ - xi^|^2_E / lambda_tr on Gamma_3, xi^ the element of
   *   the laws' subdifferential at u_h nearest to xi~,
   *
   * energy_scale = 1/(1 - theta)^2, theta the relaxed-monotonicity margin of
   * the convexity check; ErrorEstimate::bound (what total() returns) the
   * bound of section 12.5, the terms added as norms.
   *
   * @p u and @p xi ghosted, hanging-node values distributed; @p data at the
   * time of the step. Throws InputError for what it does not do (one MPI
   * rank, 2D quadrilaterals without hanging nodes, the static class, a
   * law without a wall whose convexity check gives a trace eigenvalue).
   */
  template <int dim>
  ErrorEstimate
  equilibrated_estimate(const ProblemState<dim>             &state,
                        const ProblemData<dim>              &data,
                        const TrilinosWrappers::MPI::Vector &u,
                        const TrilinosWrappers::MPI::Vector &xi);

  /**
   * The refusals of 'output/error estimate = equilibrated' that the
   * parameters alone decide (InputError naming the entry): the velocity
   * classes, 3D, simplices, adaptive meshes, memory, more than one MPI
   * rank of MPI_COMM_WORLD.
   */
  void
  require_equilibrated_usable(const Parameters &parameters);
} // namespace hemicontact
