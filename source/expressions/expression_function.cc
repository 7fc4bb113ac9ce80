#include <hemicontact/expressions/expression_function.h>

#include <memory>

namespace hemicontact
{
  namespace
  {
    /** The tape of the expressions @p texts in the variables of
     *  ExpressionFunction<dim>, with t uniform. */
    template <int dim>
    ExpressionTape
    make_tape(const std::vector<std::string>      &texts,
              const std::map<std::string, double> &constants,
              const std::string                   &parameter_name)
    {
      std::vector<std::unique_ptr<Expression>> expressions;
      std::vector<const Expression *>          pointers;
      for (const std::string &text : texts)
        {
          expressions.push_back(std::make_unique<Expression>(
            text,
            ExpressionFunction<dim>::variable_names(),
            constants,
            parameter_name));
          pointers.push_back(expressions.back().get());
        }
      return ExpressionTape(pointers, {dim});
    }
  } // namespace

  template <int dim>
  ExpressionFunction<dim>::ExpressionFunction(
    const std::vector<std::string>      &expressions,
    const std::map<std::string, double> &constants,
    const std::string                   &parameter_name)
    : dealii::AutoDerivativeFunction<dim>(1e-8, expressions.size())
    , tape(make_tape<dim>(expressions, constants, parameter_name))
  {}

  template <int dim>
  std::vector<std::string>
  ExpressionFunction<dim>::variable_names()
  {
    if (dim == 2)
      return {"x", "y", "t"};
    return {"x", "y", "z", "t"};
  }

  template <int dim>
  void
  ExpressionFunction<dim>::evaluate(
    const std::vector<dealii::Point<dim>> &points,
    std::vector<double>                   &results) const
  {
    // per thread: deal.II evaluates Functions from several threads
    thread_local std::vector<double> variables;
    variables.resize(points.size() * (dim + 1));
    const double t = this->get_time();
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        for (unsigned int d = 0; d < dim; ++d)
          variables[p * (dim + 1) + d] = points[p][d];
        variables[p * (dim + 1) + dim] = t;
      }
    results.resize(points.size() * this->n_components);
    tape.evaluate(variables.data(), dim + 1, points.size(), results.data());
  }

  template <int dim>
  double
  ExpressionFunction<dim>::value(const dealii::Point<dim> &p,
                                 const unsigned int        component) const
  {
    AssertIndexRange(component, this->n_components);
    thread_local std::vector<double> results;
    evaluate(std::vector<dealii::Point<dim>>{p}, results);
    return results[component];
  }

  template <int dim>
  void
  ExpressionFunction<dim>::vector_value(const dealii::Point<dim> &p,
                                        dealii::Vector<double>   &values) const
  {
    AssertDimension(values.size(), this->n_components);
    thread_local std::vector<double> results;
    evaluate(std::vector<dealii::Point<dim>>{p}, results);
    for (unsigned int c = 0; c < this->n_components; ++c)
      values[c] = results[c];
  }

  template <int dim>
  void
  ExpressionFunction<dim>::value_list(
    const std::vector<dealii::Point<dim>> &points,
    std::vector<double>                   &values,
    const unsigned int                     component) const
  {
    AssertIndexRange(component, this->n_components);
    AssertDimension(values.size(), points.size());
    thread_local std::vector<double> results;
    evaluate(points, results);
    for (unsigned int p = 0; p < points.size(); ++p)
      values[p] = results[p * this->n_components + component];
  }

  template <int dim>
  void
  ExpressionFunction<dim>::vector_value_list(
    const std::vector<dealii::Point<dim>> &points,
    std::vector<dealii::Vector<double>>   &values) const
  {
    AssertDimension(values.size(), points.size());
    thread_local std::vector<double> results;
    evaluate(points, results);
    for (unsigned int p = 0; p < points.size(); ++p)
      for (unsigned int c = 0; c < this->n_components; ++c)
        values[p][c] = results[p * this->n_components + c];
  }

  template class ExpressionFunction<2>;
  template class ExpressionFunction<3>;
} // namespace hemicontact
