#pragma once

#include <deal.II/base/function.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/expressions/constants.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/friction_bound.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The heat data a manufactured solution derives (doc/theory.md 13.6):
   * those set replace the expressions of the 'temperature' subsection.
   */
  template <int dim>
  struct HeatData
  {
    /** theta_0, q and theta_D (time from set_time()) */
    std::shared_ptr<Function<dim>> initial_temperature, heat_source,
      prescribed_temperature;
    /** A scalar that depends on the outward normal: (point, normal, t). */
    using NormalScalar =
      std::function<double(const Point<dim> &, const Tensor<1, dim> &, double)>;
    /** q_N on the flux ids */
    NormalScalar heat_flux;
    /** A heat source on Gamma_3, by nodal quadrature as the contact heat
     *  law's terms */
    NormalScalar contact_heat_source;
  };

  /**
   * The data of the contact problem as Function objects: f0, f2, f3 and
   * the initial fields (dim components each), and the friction bound F_b
   * (an expression that may depend on the normal displacement). Built from the
   * expressions of the parameter file; a manufactured solution replaces them
   * with derived functions.
   */
  template <int dim>
  struct ProblemData
  {
    std::unique_ptr<Function<dim>>            body_force;
    std::unique_ptr<Function<dim>>            surface_traction;
    std::unique_ptr<Function<dim>>            contact_traction;
    std::unique_ptr<Function<dim>>            initial_displacement;
    std::unique_ptr<Function<dim>>            initial_velocity;
    std::shared_ptr<const FrictionBound<dim>> friction_bound;

    /**
     * Tractions that depend on the outward normal (point, normal, time),
     * e.g. sigma nu of a manufactured solution. When set, they replace
     * surface_traction / contact_traction.
     */
    using NormalTraction = std::function<
      Tensor<1, dim>(const Point<dim> &, const Tensor<1, dim> &, double)>;
    NormalTraction surface_traction_with_normal;
    NormalTraction contact_traction_with_normal;
    /** The derived heat data (none without a manufactured temperature). */
    HeatData<dim> heat;

    /** The time last passed to set_time(). */
    double time = 0;

    /** Set the time of every time-dependent function. */
    void
    set_time(const double t);

    /**
     * f2 (@p on_traction) or f3 at the quadrature points of a boundary face
     * with their outward normals, at the time last set: the normal-dependent
     * form if there is one, else the Function.
     */
    void
    boundary_traction(const bool                         on_traction,
                      const std::vector<Point<dim>>     &points,
                      const std::vector<Tensor<1, dim>> &normals,
                      std::vector<Vector<double>>       &values) const;
  };

  /**
   * Build ProblemData from the expressions in @p data. A malformed
   * expression or a wrong number of components throws an InputError that
   * names the parameter.
   */
  template <int dim>
  ProblemData<dim>
  make_problem_data(const DataParameters &data);

  /**
   * An ExpressionFunction for one parameter, with the variables x, y[, z], t
   * and the user constants (plus pi, _pi, _e). @p n_components expressions are expected;
   * a single number is broadcast to every component. @p parameter_name is
   * used in error messages. Numbers only give a Functions::ConstantFunction
   * (a Functions::ZeroFunction if all are zero), which the load assembly
   * skips.
   */
  template <int dim>
  std::unique_ptr<Function<dim>>
  parse_function(const std::string &expression,
                 const unsigned int n_components,
                 const std::string &constants,
                 const std::string &parameter_name);
} // namespace hemicontact
