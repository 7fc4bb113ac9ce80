#pragma once

#include <deal.II/base/auto_derivative_function.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/expressions/expression.h>
#include <hemicontact/expressions/expression_tape.h>

#include <map>
#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * A dealii::Function with one Expression (doc/parameters.md, Expressions)
   * per component in the variables x, y[, z] and t, compiled into one
   * ExpressionTape with t uniform. Evaluation is thread-safe: the tape is
   * read only and its registers are per thread. Gradients are difference
   * quotients (step 1e-8), as dealii::FunctionParser gives them.
   */
  template <int dim>
  class ExpressionFunction : public dealii::AutoDerivativeFunction<dim>
  {
  public:
    /**
     * Parse @p expressions (one per component) with the @p constants.
     * Throws the InputError of Expression, which names @p parameter_name.
     */
    ExpressionFunction(const std::vector<std::string>      &expressions,
                       const std::map<std::string, double> &constants,
                       const std::string                   &parameter_name);

    /** The variable names x, y[, z], t, in the order of evaluation. */
    static std::vector<std::string>
    variable_names();

    double
    value(const dealii::Point<dim> &p,
          const unsigned int        component = 0) const override;

    void
    vector_value(const dealii::Point<dim> &p,
                 dealii::Vector<double>   &values) const override;

    void
    value_list(const std::vector<dealii::Point<dim>> &points,
               std::vector<double>                   &values,
               const unsigned int component = 0) const override;

    void
    vector_value_list(
      const std::vector<dealii::Point<dim>> &points,
      std::vector<dealii::Vector<double>>   &values) const override;

  private:
    /** The values of all components at @p points into results (n_points
     *  times n_components, by point). */
    void
    evaluate(const std::vector<dealii::Point<dim>> &points,
             std::vector<double>                   &results) const;

    ExpressionTape tape;
  };
} // namespace hemicontact
