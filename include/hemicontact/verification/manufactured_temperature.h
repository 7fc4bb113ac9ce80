#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <hemicontact/expressions/expression.h>
#include <hemicontact/expressions/expression_tape.h>
#include <hemicontact/input/parameters.h>

#include <memory>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The temperature part of a manufactured solution (doc/theory.md,
   * section 13.6): theta(x, t) of 'manufactured solution/exact
   * temperature' with its derivatives, differentiated symbolically once and
   * evaluated in one pass (ExpressionTape), and the coefficients c_theta,
   * c_e, K, k_e, theta_F and gamma of the 'temperature' subsection, which
   * the derived data keep. With w the exact velocity,
   *
   *   thermal stress   c_e theta (in f0 as grad(c_e theta), in f2, f3),
   *   heat source      q   = c_theta dtheta/dt - div(K grad theta)
   *                          + c_e div w,
   *   heat flux        q_N = K grad theta . nu,
   *   contact source   g_3 = K grad theta . nu - k_e (theta_F - theta)
   *                          - gamma |xi_tau . w_tau|   (on Gamma_3).
   */
  template <int dim>
  class ManufacturedTemperature
  {
  public:
    /** theta and the coefficients at one point and time. */
    struct Values
    {
      double         theta = 0, theta_dot = 0, c_theta = 0, c_e = 0;
      Tensor<1, dim> grad_theta;
      /** grad(c_e theta) */
      Tensor<1, dim> grad_thermal_stress;
      /** div(K grad theta) */
      double div_flux = 0;
      /** K at the point */
      Tensor<2, dim> conductivity;
    };

    /** theta of @p parameters' manufactured solution, the coefficients of
     *  its 'temperature' subsection. */
    explicit ManufacturedTemperature(const Parameters &parameters);

    /** theta and its derivatives at every point of @p points at @p t. */
    std::vector<Values>
    evaluate(const std::vector<Point<dim>> &points, const double t) const;

    /** q at @p points at @p t, with the exact div w there (@p div_w). */
    std::vector<double>
    heat_source(const std::vector<Point<dim>> &points,
                const std::vector<double>     &div_w,
                const double                   t) const;

    /** K grad theta . @p normal at (@p p, @p t). */
    double
    normal_flux(const Point<dim>     &p,
                const Tensor<1, dim> &normal,
                const double          t) const;

    /**
     * g_3 at (@p p, @p t) on Gamma_3 with the outward @p normal, the exact
     * normal displacement @p u_nu and frictional power |xi_tau . w_tau|
     * @p frictional_power.
     */
    double
    contact_heat_source(const Point<dim>     &p,
                        const Tensor<1, dim> &normal,
                        const double          t,
                        const double          u_nu,
                        const double          frictional_power) const;

  private:
    TemperatureParameters parameters;
    /** In the order evaluate() reads them (the constructor's). */
    std::vector<Expression>         expressions;
    std::unique_ptr<ExpressionTape> tape;
    /** K of numbers (anisotropic), else the expression kappa's value. */
    Tensor<2, dim>              conductivity_tensor;
    bool                        isotropic = true;
    std::unique_ptr<Expression> exchange_coefficient, foundation_temperature;
  };
} // namespace hemicontact
