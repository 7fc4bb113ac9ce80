#pragma once

#include <deal.II/base/point.h>

#include <hemicontact/expressions/expression_tape.h>
#include <hemicontact/expressions/spatial_cache.h>

#include <string>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /** The variables of an expression in space and time: x, y[, z], t. */
  inline std::vector<std::string>
  space_time_variables(const int dim)
  {
    return dim == 2 ? std::vector<std::string>{"x", "y", "t"} :
                      std::vector<std::string>{"x", "y", "z", "t"};
  }

  /**
   * The expressions of @p tape (variables x, y[, z], t) at every point of
   * @p points at time @p t: n_outputs() results per point, point after
   * point (through @p cache unless it is null).
   */
  template <int dim>
  std::vector<double>
  evaluate_tape(const ExpressionTape          &tape,
                const std::vector<Point<dim>> &points,
                const double                   t,
                SpatialCache                  *cache = nullptr)
  {
    std::vector<double> at(points.size() * (dim + 1));
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        for (int i = 0; i < dim; ++i)
          at[p * (dim + 1) + i] = points[p][i];
        at[p * (dim + 1) + dim] = t;
      }
    std::vector<double> r(points.size() * tape.n_outputs());
    if (cache)
      cache->evaluate(at.data(), dim + 1, points.size(), r.data());
    else
      tape.evaluate(at.data(), dim + 1, points.size(), r.data());
    return r;
  }
} // namespace hemicontact
