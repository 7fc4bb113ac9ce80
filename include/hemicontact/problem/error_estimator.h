#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/mesh/discretization.h>
#include <hemicontact/model/kelvin_voigt.h>
#include <hemicontact/model/problem_data.h>
#include <hemicontact/model/step_scheme.h>

#include <cmath>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The residual error estimate of one step (doc/theory.md, section 12):
   * the four terms of eta_K^2 per cell and their sums over the mesh, and the
   * factor 1/(2 mu_K) that turns them into the energy norm of the step.
   */
  struct ErrorEstimate
  {
    /** @name Squares of the terms per active cell (0 on cells not owned) */
    /** @{ */
    /** h_K^2 |f0 - rho/k (w_n - w_{n-1}) + div sigma_h|^2_K */
    Vector<double> interior;
    /** 1/2 sum h_E |[sigma_h nu]|^2_E over the interior faces of K */
    Vector<double> jumps;
    /** sum h_E |f2 - sigma_h nu|^2_E over the faces of K off Gamma_1, Gamma_3
     */
    Vector<double> neumann;
    /** sum h_E |f3 - sigma_h nu - xi_h|^2_E over the faces of K on Gamma_3 */
    Vector<double> contact;
    /** @} */

    /** The sums of the four over all cells (all ranks). */
    double interior_sum = 0, jumps_sum = 0, neumann_sum = 0, contact_sum = 0;

    /**
     * 1/(2 mu_K), mu_K the shear modulus of the step's operator
     * (static: mu of B; velocity classes: mu_v, + k mu in the implicit
     * rule): eta^2 = energy_scale (sum of the terms) estimates the error
     * in the energy norm of the step (doc/theory.md 12.1).
     */
    double energy_scale = 1;

    /**
     * The equilibrated estimate's bound of the step's error, its terms
     * added as norms (doc/theory.md 12.5); negative for the residual
     * estimate.
     */
    double bound = -1;

    /**
     * The step's estimate: the bound of the equilibrated estimate, else
     * eta = (energy_scale sum of all terms)^{1/2}.
     */
    double
    total() const
    {
      if (bound >= 0)
        return bound;
      return std::sqrt(energy_scale *
                       (interior_sum + jumps_sum + neumann_sum + contact_sum));
    }

    /** (energy_scale @p sum)^{1/2}: one term's share of total() alone. */
    double
    part(const double sum) const
    {
      return std::sqrt(energy_scale * sum);
    }

    /**
     * eta_K per cell: (energy_scale (interior + jumps + neumann +
     * contact_weight^2 contact))^{1/2}; with @p contact_weight = 1 and
     * @p energy_scale (else 1) the estimate, else the residual refinement
     * indicator.
     */
    Vector<float>
    cell_values(const double contact_weight = 1.,
                const bool   in_energy_norm = true) const;
  };

  /**
   * The residual estimator of doc/theory.md section 12 for the step just
   * solved: sigma_h = A eps(w_n) + B eps(u_n) (static: B eps(u_n)), the
   * inertia rho/k (w_n - w_{n-1}) of the dynamic class, the data f0, f2, f3
   * at the time last set, and on Gamma_3 the piecewise-linear interpolant
   * xi_h of the nodal contact tractions -(K w - b)_i / m_i of the solve.
   */
  template <int dim>
  class ErrorEstimator
  {
  public:
    ErrorEstimator(const Discretization<dim>      &discretization,
                   const DoFHandler<dim>          &dof_handler,
                   const KelvinVoigtMaterial<dim> &material,
                   const StepScheme               &scheme,
                   const ProblemData<dim>         &data,
                   const BoundaryParameters       &boundary);

    /**
     * The estimate of the step with unknown @p w (w_n, static: u_n), the
     * previous @p w_old, displacement @p u and nodal traction @p xi (all
     * ghosted, hanging-node values distributed) and step length @p k.
     */
    ErrorEstimate
    estimate(const TrilinosWrappers::MPI::Vector &w,
             const TrilinosWrappers::MPI::Vector &w_old,
             const TrilinosWrappers::MPI::Vector &u,
             const TrilinosWrappers::MPI::Vector &xi,
             const double                         k,
             MPI_Comm                             comm) const;

  private:
    const Discretization<dim>      &discretization;
    const DoFHandler<dim>          &dof_handler;
    const KelvinVoigtMaterial<dim> &material;
    const StepScheme               &scheme;
    const ProblemData<dim>         &data;
    const BoundaryParameters       &boundary;
  };
} // namespace hemicontact
