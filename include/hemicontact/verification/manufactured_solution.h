#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <hemicontact/expressions/expression.h>
#include <hemicontact/expressions/expression_tape.h>
#include <hemicontact/expressions/spatial_cache.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/friction_bound.h>
#include <hemicontact/laws/friction_law.h>
#include <hemicontact/laws/normal_law.h>
#include <hemicontact/memory/normal_memory_kernel.h>
#include <hemicontact/memory/relaxation_kernel.h>
#include <hemicontact/model/kelvin_voigt.h>
#include <hemicontact/model/problem_data.h>
#include <hemicontact/model/step_scheme.h>
#include <hemicontact/verification/manufactured_temperature.h>

#include <memory>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * A manufactured solution u(x,t) given as expressions, with everything
   * derived from it exactly: w = du/dt, dw/dt, grad u, grad w and the second
   * derivatives in Div sigma are differentiated symbolically once
   * (Expression::derivative()) and evaluated in doubles, all of them in one
   * pass with their common subexpressions shared (ExpressionTape), hence
   *   f0 = rho dw/dt - Div sigma,  f2 = sigma nu,
   *   f3 = sigma nu + xi_nu nu + xi_tau  (doc/theory.md, section 4),
   * with xi_nu in dj(w_nu), xi_tau in dphi(w_tau) (the friction law's force
   * F(|w_tau|) w_tau/|w_tau| with the bound F_b(x, t, u_nu) of the exact
   * state) and the given multiplier choices where those sets are intervals
   * (w_nu = 0, w_tau = 0). In the static class (doc/theory.md 9.7) the
   * laws act on u, which takes the place of w here ("w" is u), and the
   * material has no viscosity: f0 = -Div B eps(u).
   *
   * With a relaxation kernel (doc/theory.md, section 11.11) sigma gains the
   * exact memory integral M(t) = int_0^t R(t - s) eps(u(s)) ds, in f0, f2
   * and f3, by composite Gauss-Legendre quadrature in s. With a normal
   * memory kernel b, f3 gains N(t) nu, N(t) = int_0^t b(t - s) (u_nu(s))_+
   * ds, and the contact pressure p_nu of the bound is xi_nu + N; a bound in
   * s_tau reads the exact slip S(t) = int_0^t |du_tau/ds| ds (the same
   * quadrature; doc/theory.md 11.11).
   *
   * With 'temperature/enabled', theta(x, t) of 'exact temperature'
   * (ManufacturedTemperature) adds the thermal stress -c_e theta I to
   * sigma in f0, f2 and f3, and gives the heat data (doc/theory.md 13.6).
   */
  template <int dim>
  class ManufacturedSolution
  {
  public:
    /** The exact fields at one point and time. */
    struct Values
    {
      Tensor<1, dim> u, w, w_dot, div_sigma;
      Tensor<2, dim> grad_u, grad_w;
    };

    ManufacturedSolution(const Parameters  &parameters,
                         const NormalLaw   &law,
                         const FrictionLaw &friction);

    /** u, w, their gradients, dw/dt and Div sigma at (p, t). */
    Values
    evaluate(const Point<dim> &p, const double t) const;

    /** Only u, w and their gradients (first derivatives: cheaper). */
    Values
    evaluate_fields(const Point<dim> &p, const double t) const;

    /** evaluate() at all @p points in one batch (cheaper per point). */
    std::vector<Values>
    evaluate(const std::vector<Point<dim>> &points, const double t) const;

    /**
     * evaluate_fields() at all @p points in one batch; a loop that visits
     * the same batches at every step passes a @p cache of its own
     * (make_fields_cache()).
     */
    std::vector<Values>
    evaluate_fields(const std::vector<Point<dim>> &points,
                    const double                   t,
                    SpatialCache                  *cache = nullptr) const;

    /** A cache for evaluate_fields() (SpatialCache). */
    std::unique_ptr<SpatialCache>
    make_fields_cache() const;

    /** sigma = A eps(w) + B eps(u), the instantaneous part. */
    SymmetricTensor<2, dim>
    stress(const Values &v) const;

    /** The memory part M(t) = int_0^t R(t - s) eps(u(p, s)) ds of sigma at
     *  (p, t); zero without a relaxation kernel. */
    SymmetricTensor<2, dim>
    memory_stress(const Point<dim> &p, const double t) const;

    /** N(t) = int_0^t b(t - s) (u(p, s) . nu)_+ ds, the memory of the
     *  normal response at (p, t) for the normal @p normal; zero without a
     *  normal memory kernel. */
    double
    normal_memory_pressure(const Point<dim>     &p,
                           const Tensor<1, dim> &normal,
                           const double          t) const;

    /** S(t) = int_0^t |du_tau/ds (p, s)| ds, the slip accumulated at p up
     *  to t (the total variation of u_tau in the load parameter in the
     *  static class), u_tau = u - (u . nu) nu. */
    double
    accumulated_slip(const Point<dim>     &p,
                     const Tensor<1, dim> &normal,
                     const double          t) const;

    /** f0 = rho dw/dt - Div sigma (quasistatic: -Div sigma, doc/theory.md
     *  9.7), sigma with its memory part. */
    Tensor<1, dim>
    body_force(const Point<dim> &p, const double t) const;

    /** f0 at all @p points in one batch, with an optional @p cache
     *  (make_force_cache()). */
    std::vector<Tensor<1, dim>>
    body_force(const std::vector<Point<dim>> &points,
               const double                   t,
               SpatialCache                  *cache = nullptr) const;

    /** A cache for body_force() (SpatialCache). */
    std::unique_ptr<SpatialCache>
    make_force_cache() const;

    /** f2 = sigma nu (sigma with its memory part, as below). */
    Tensor<1, dim>
    surface_traction(const Point<dim>     &p,
                     const Tensor<1, dim> &normal,
                     const double          t) const;

    /** f3 = sigma nu + xi_nu nu + xi_tau. */
    Tensor<1, dim>
    contact_traction(const Point<dim>     &p,
                     const Tensor<1, dim> &normal,
                     const double          t) const;

    /** Whether the solution has a temperature (ManufacturedTemperature). */
    bool
    has_temperature() const
    {
      return temperature != nullptr;
    }

    /** theta and its derivatives at @p points at @p t (has_temperature()). */
    std::vector<typename ManufacturedTemperature<dim>::Values>
    temperature_values(const std::vector<Point<dim>> &points,
                       const double                   t) const;

    /**
     * The problem data: derived f0, f2, f3, u0, w0, the friction bound
     * of the parameter file and, with a temperature, the heat data. The
     * returned data refer to this object.
     */
    ProblemData<dim>
    make_problem_data() const;

  private:
    /** The exact fields and the multipliers at a point of Gamma_3. */
    struct ContactResponse
    {
      Values v;
      /** xi_nu + N: the normal multiplier with the normal memory */
      double pressure = 0;
      /** xi_tau */
      Tensor<1, dim> xi_tau;
    };

    /** The response at (@p p, @p t) with the outward @p normal. */
    ContactResponse
    contact_response(const Point<dim>     &p,
                     const Tensor<1, dim> &normal,
                     const double          t) const;

    /** c_e theta at (@p p, @p t); zero without a temperature. */
    double
    thermal_stress(const Point<dim> &p, const double t) const;

    /** The heat data of make_problem_data(). */
    HeatData<dim>
    make_heat_data() const;

    /** w_dot and Div sigma from the force tape's outputs at @p r. */
    void
    unpack_second_derivatives(const double *r, Values &v) const;

    /** The nodes s and weights of the quadrature of [0, t] in the memory
     *  integral (doc/theory.md, section 11.11). */
    std::vector<std::pair<double, double>>
    memory_quadrature(const double t) const;

    /** Div M(t) at @p points (zero without a relaxation kernel). */
    std::vector<Tensor<1, dim>>
    memory_stress_divergence(const std::vector<Point<dim>> &points,
                             const double                   t) const;

    const NormalLaw         &law;
    const FrictionLaw       &friction;
    KelvinVoigtMaterial<dim> material;
    /** rho in f0: the density (dynamic) or 0 (quasistatic). */
    double                  inertia_density;
    std::vector<Expression> displacement;
    /** @name The derivatives of u, one expression per component */
    /** @{ */
    std::vector<Expression> velocity;              ///< w_c = du_c/dt
    std::vector<Expression> acceleration;          ///< dw_c/dt
    std::vector<Expression> displacement_gradient; ///< [c dim + i]: du_c/dx_i
    std::vector<Expression> velocity_gradient;     ///< [c dim + i]: dw_c/dx_i
    /** [(c dim + i) dim + j]: d^2 u_c/dx_i dx_j (and of w_c) */
    std::vector<Expression> displacement_hessian, velocity_hessian;
    /** @} */
    /** u, w and their gradients in one pass (evaluate_fields()). */
    std::unique_ptr<ExpressionTape> fields_tape;
    /** dw/dt and the second derivatives with j >= i (body_force()). */
    std::unique_ptr<ExpressionTape> force_tape;
    /** The fields tape's outputs, then the force tape's (evaluate()). */
    std::unique_ptr<ExpressionTape>           all_tape;
    std::unique_ptr<Expression>               normal_multiplier;
    std::vector<Expression>                   tangential_multiplier;
    std::shared_ptr<const FrictionBound<dim>> friction_bound;
    /** The relaxation kernel R, or null without memory. */
    std::unique_ptr<RelaxationKernel> relaxation;
    /** The kernel b of the normal memory, or null without it. */
    std::unique_ptr<NormalMemoryKernel> normal_memory;
    /** du_c/dt (also in the static class, where w is u), for the slip. */
    std::vector<Expression> displacement_rate;
    /** theta, or null without 'temperature/enabled'. */
    std::unique_ptr<ManufacturedTemperature<dim>> temperature;
  };
} // namespace hemicontact
