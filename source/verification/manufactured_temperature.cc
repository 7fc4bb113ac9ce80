#include <hemicontact/base/exceptions.h>
#include <hemicontact/model/problem_data.h>
#include <hemicontact/verification/manufactured_temperature.h>
#include <hemicontact/verification/tape_at_points.h>

#include <cmath>
#include <utility>

namespace hemicontact
{
  template <int dim>
  ManufacturedTemperature<dim>::ManufacturedTemperature(
    const Parameters &all_parameters)
    : parameters(all_parameters.temperature)
    , isotropic(!all_parameters.temperature.anisotropic())
  {
    const auto constants = parse_constants(all_parameters.data.constants);
    const std::vector<std::string> variables = space_time_variables(dim);
    const auto parse = [&](const std::string &text, const std::string &name) {
      return Expression(text, variables, constants, name);
    };
    // theta, dtheta/dt, d_i theta, d_i d_j theta, c_theta, c_e, d_i c_e
    // [, kappa, d_i kappa]: t is variable number dim
    expressions.push_back(parse(all_parameters.manufactured.exact_temperature,
                                "manufactured solution/exact temperature"));
    expressions.push_back(expressions[0].derivative(dim));
    for (int i = 0; i < dim; ++i)
      expressions.push_back(expressions[0].derivative(i));
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j)
        expressions.push_back(expressions[2 + i].derivative(j));
    expressions.push_back(
      parse(parameters.heat_capacity, "temperature/heat capacity"));
    Expression c_e = parse(parameters.thermal_stress_coefficient,
                           "temperature/thermal stress coefficient");
    for (int i = 0; i < dim; ++i)
      expressions.push_back(c_e.derivative(i));
    expressions.push_back(std::move(c_e));
    if (isotropic)
      {
        Expression kappa =
          parse(parameters.conductivity[0], "temperature/conductivity");
        for (int i = 0; i < dim; ++i)
          expressions.push_back(kappa.derivative(i));
        expressions.push_back(std::move(kappa));
      }
    else
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          conductivity_tensor[i][j] =
            std::stod(parameters.conductivity[i * dim + j]);
    std::vector<const Expression *> outputs;
    for (const Expression &e : expressions)
      outputs.push_back(&e);
    tape =
      std::make_unique<ExpressionTape>(outputs, std::vector<unsigned int>{dim});

    std::vector<std::string> contact_variables = variables;
    contact_variables.push_back("u_nu");
    exchange_coefficient =
      std::make_unique<Expression>(parameters.exchange_coefficient,
                                   contact_variables,
                                   constants,
                                   "temperature/exchange coefficient");
    foundation_temperature =
      std::make_unique<Expression>(parameters.foundation_temperature,
                                   variables,
                                   constants,
                                   "temperature/foundation temperature");
  }

  template <int dim>
  std::vector<typename ManufacturedTemperature<dim>::Values>
  ManufacturedTemperature<dim>::evaluate(const std::vector<Point<dim>> &points,
                                         const double                   t) const
  {
    const std::vector<double> r = evaluate_tape(*tape, points, t);
    std::vector<Values>       values(points.size());
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        // in the order of the constructor's expressions
        const double *e = r.data() + p * tape->n_outputs();
        Values       &v = values[p];
        v.theta         = *e++;
        v.theta_dot     = *e++;
        for (int i = 0; i < dim; ++i)
          v.grad_theta[i] = *e++;
        Tensor<2, dim> hessian;
        for (int i = 0; i < dim; ++i)
          for (int j = 0; j < dim; ++j)
            hessian[i][j] = *e++;
        v.c_theta = *e++;
        Tensor<1, dim> grad_c_e;
        for (int i = 0; i < dim; ++i)
          grad_c_e[i] = *e++;
        v.c_e                 = *e++;
        v.grad_thermal_stress = v.theta * grad_c_e + v.c_e * v.grad_theta;
        if (isotropic)
          {
            Tensor<1, dim> grad_kappa;
            for (int i = 0; i < dim; ++i)
              grad_kappa[i] = *e++;
            const double kappa = *e++;
            v.conductivity     = kappa * unit_symmetric_tensor<dim>();
            v.div_flux = grad_kappa * v.grad_theta + kappa * trace(hessian);
          }
        else
          {
            v.conductivity = conductivity_tensor;
            v.div_flux     = scalar_product(conductivity_tensor, hessian);
          }
      }
    return values;
  }

  template <int dim>
  std::vector<double>
  ManufacturedTemperature<dim>::heat_source(
    const std::vector<Point<dim>> &points,
    const std::vector<double>     &div_w,
    const double                   t) const
  {
    const std::vector<Values> v = evaluate(points, t);
    std::vector<double>       q(points.size());
    for (unsigned int p = 0; p < points.size(); ++p)
      q[p] =
        v[p].c_theta * v[p].theta_dot - v[p].div_flux + v[p].c_e * div_w[p];
    return q;
  }

  template <int dim>
  double
  ManufacturedTemperature<dim>::normal_flux(const Point<dim>     &p,
                                            const Tensor<1, dim> &normal,
                                            const double          t) const
  {
    const Values v = evaluate(std::vector<Point<dim>>{p}, t)[0];
    return (v.conductivity * v.grad_theta) * normal;
  }

  template <int dim>
  double
  ManufacturedTemperature<dim>::contact_heat_source(
    const Point<dim>     &p,
    const Tensor<1, dim> &normal,
    const double          t,
    const double          u_nu,
    const double          frictional_power) const
  {
    const Values        v = evaluate(std::vector<Point<dim>>{p}, t)[0];
    std::vector<double> at(p.begin_raw(), p.end_raw());
    at.push_back(t);
    const double theta_F = foundation_temperature->evaluate(at);
    at.push_back(u_nu);
    const double k_e = exchange_coefficient->evaluate(at);
    return (v.conductivity * v.grad_theta) * normal -
           k_e * (theta_F - v.theta) -
           parameters.frictional_heat_fraction * frictional_power;
  }

  template class ManufacturedTemperature<2>;
  template class ManufacturedTemperature<3>;
} // namespace hemicontact
