#pragma once

#include <deal.II/base/point.h>

#include <hemicontact/expressions/expression.h>

#include <memory>
#include <string>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The friction bound F_b(x, t, u_nu) >= 0 of 'data/friction bound': an
   * expression in x, y[, z], t and u_nu, the normal displacement u . nu
   * at the contact node (positive into the foundation). The time loop
   * evaluates it at the start of step n with t_n and the known u_n (the
   * left-point rule), so each step stays a minimisation (doc/theory.md,
   * section 7). Example: mu * cp * pos(u_nu), normal compliance with
   * friction.
   */
  template <int dim>
  class FrictionBound
  {
  public:
    /** Parse @p expression with the user constants of 'data/constants'. */
    FrictionBound(const std::string &expression, const std::string &constants);

    /**
     * F_b at point @p p, time @p t and normal displacement @p u_nu. Throws
     * an InputError naming the expression, the point, the time and u_nu if
     * the value is negative or not finite.
     */
    double
    value(const Point<dim> &p, const double t, const double u_nu) const;

    /** Whether the expression depends on t or u_nu (else: once per mesh). */
    bool
    depends_on_state() const
    {
      return state_dependent;
    }

  private:
    std::string                 text;
    std::unique_ptr<Expression> expression;
    bool                        state_dependent = false;
  };
} // namespace hemicontact
