#include <deal.II/base/function_lib.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/expressions/expression.h>
#include <hemicontact/expressions/expression_function.h>
#include <hemicontact/model/problem_data.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    bool
    is_number(const std::string &s)
    {
      try
        {
          Utilities::string_to_double(s);
          return true;
        }
      catch (...)
        {
          return false;
        }
    }
  } // namespace


  template <int dim>
  std::unique_ptr<Function<dim>>
  parse_function(const std::string &expression,
                 const unsigned int n_components,
                 const std::string &constants_text,
                 const std::string &parameter_name)
  {
    std::vector<std::string> expressions =
      Utilities::split_string_list(expression, ';');
    if (expressions.size() == 1 && n_components > 1 &&
        is_number(expressions[0]))
      expressions.assign(n_components, expressions[0]);
    require(expressions.size() == n_components,
            "data: '" + parameter_name +
              "' = " + quoted_expression(expression) + " has " +
              std::to_string(expressions.size()) +
              " components separated by ';' but needs " +
              std::to_string(n_components) + ".");
    for (const std::string &e : expressions)
      require(!e.empty(),
              "data: '" + parameter_name + "' has an empty component in " +
                quoted_expression(expression) + ".");

    // constant data (e.g. the default zero body force) need no expression:
    // a ZeroFunction lets the assembly skip the integral
    if (std::all_of(expressions.begin(), expressions.end(), is_number))
      {
        std::vector<double> values;
        for (const std::string &e : expressions)
          values.push_back(Utilities::string_to_double(e));
        if (std::all_of(values.begin(), values.end(), [](const double v) {
              return v == 0;
            }))
          return std::make_unique<Functions::ZeroFunction<dim>>(n_components);
        return std::make_unique<Functions::ConstantFunction<dim>>(values);
      }

    const std::map<std::string, double> constants =
      parse_constants(constants_text);
    for (unsigned int c = 0; c < n_components; ++c)
      try
        {
          const Expression check(expressions[c],
                                 ExpressionFunction<dim>::variable_names(),
                                 constants,
                                 parameter_name);
        }
      catch (const InputError &e)
        {
          // the reason after Expression's "cannot parse 'name' = 'text': "
          const std::string prefix =
            "cannot parse '" + parameter_name +
            "' = " + quoted_expression(expressions[c]) + ": ";
          const std::string what = e.what();
          const std::string reason =
            what.compare(0, prefix.size(), prefix) == 0 ?
              what.substr(prefix.size()) :
              what;
          throw InputError(
            "data: cannot parse '" + parameter_name +
            "' = " + quoted_expression(expression) +
            (n_components > 1 ? " in its component " + std::to_string(c + 1) :
                                std::string()) +
            " (variables " + (dim == 2 ? "x, y, t" : "x, y, z, t") +
            " and the constants): " + reason);
        }
    auto function = std::make_unique<ExpressionFunction<dim>>(expressions,
                                                              constants,
                                                              parameter_name);
    return function;
  }

  template <int dim>
  void
  ProblemData<dim>::set_time(const double t)
  {
    time = t;
    for (Function<dim> *f : {body_force.get(),
                             surface_traction.get(),
                             contact_traction.get(),
                             initial_displacement.get(),
                             initial_velocity.get()})
      if (f != nullptr)
        f->set_time(t);
  }

  template <int dim>
  void
  ProblemData<dim>::boundary_traction(
    const bool                         on_traction,
    const std::vector<Point<dim>>     &points,
    const std::vector<Tensor<1, dim>> &normals,
    std::vector<Vector<double>>       &values) const
  {
    const NormalTraction &with_normal =
      on_traction ? surface_traction_with_normal : contact_traction_with_normal;
    if (!with_normal)
      {
        (on_traction ? surface_traction : contact_traction)
          ->vector_value_list(points, values);
        return;
      }
    for (unsigned int q = 0; q < points.size(); ++q)
      {
        const Tensor<1, dim> g = with_normal(points[q], normals[q], time);
        for (unsigned int c = 0; c < dim; ++c)
          values[q](c) = g[c];
      }
  }

  template <int dim>
  ProblemData<dim>
  make_problem_data(const DataParameters &data)
  {
    ProblemData<dim>   result;
    const std::string &c = data.constants;
    result.body_force =
      parse_function<dim>(data.body_force, dim, c, "body force");
    result.surface_traction =
      parse_function<dim>(data.surface_traction, dim, c, "surface traction");
    result.contact_traction =
      parse_function<dim>(data.contact_traction, dim, c, "contact traction");
    result.friction_bound =
      std::make_shared<FrictionBound<dim>>(data.friction_bound, c);
    result.initial_displacement = parse_function<dim>(data.initial_displacement,
                                                      dim,
                                                      c,
                                                      "initial displacement");
    result.initial_velocity =
      parse_function<dim>(data.initial_velocity, dim, c, "initial velocity");
    return result;
  }

  template struct ProblemData<2>;
  template struct ProblemData<3>;
  template ProblemData<2>
  make_problem_data<2>(const DataParameters &);
  template ProblemData<3>
  make_problem_data<3>(const DataParameters &);
  template std::unique_ptr<Function<2>>
  parse_function<2>(const std::string &,
                    const unsigned int,
                    const std::string &,
                    const std::string &);
  template std::unique_ptr<Function<3>>
  parse_function<3>(const std::string &,
                    const unsigned int,
                    const std::string &,
                    const std::string &);
} // namespace hemicontact
