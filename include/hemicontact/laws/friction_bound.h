#pragma once

#include <deal.II/base/point.h>

#include <hemicontact/expressions/expression.h>

#include <memory>
#include <string>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The friction bound F_b(x, t, u_nu, w_nu, p_nu) >= 0 of 'data/friction
   * bound': an expression in x, y[, z], t, u_nu, the normal displacement
   * u . nu at the contact node (positive into the foundation), w_nu, the
   * normal velocity (velocity classes), p_nu, the contact pressure
   * -sigma_nu at the node, and s_tau, the slip accumulated up to the state
   * before the step (doc/theory.md, section 11.10). In the velocity classes
   * u_nu is the displacement held when the step starts and p_nu the pressure of
   * the step before (doc/theory.md, sections 7 and 9.9); a bound in w_nu, and
   * in the static class a bound in u_nu or p_nu, depends on the step's own
   * unknown and is found by fixed-point iterations (sections 9.8, 9.9).
   * Examples: mu * cp * pos(u_nu), normal compliance with friction;
   * mu * pos(p_nu), Coulomb friction.
   */
  template <int dim>
  class FrictionBound
  {
  public:
    /** Parse @p expression with the user constants of 'data/constants'. */
    FrictionBound(const std::string &expression, const std::string &constants);

    /**
     * F_b at point @p p, time @p t, normal displacement @p u_nu, normal
     * velocity @p w_nu, contact pressure @p p_nu and accumulated slip
     * @p s_tau. Throws an InputError
     * naming the expression, the point, the time and the state if the
     * value is negative or not finite.
     */
    double
    value(const Point<dim> &p,
          const double      t,
          const double      u_nu,
          const double      w_nu,
          const double      p_nu,
          const double      s_tau = 0) const;

    /**
     * Whether it depends on t, u_nu, w_nu, p_nu or s_tau (else: once per
     * mesh).
     */
    bool
    depends_on_state() const
    {
      return state_dependent;
    }

    /** Whether the expression uses u_nu. */
    bool
    uses_normal_displacement() const
    {
      return expression->uses_variable(dim + 1);
    }
    /** Whether the expression uses w_nu. */
    bool
    uses_normal_velocity() const
    {
      return expression->uses_variable(dim + 2);
    }
    /** Whether the expression uses p_nu. */
    bool
    uses_contact_pressure() const
    {
      return expression->uses_variable(dim + 3);
    }
    /** Whether the expression uses s_tau. */
    bool
    uses_slip() const
    {
      return expression->uses_variable(dim + 4);
    }

  private:
    std::string                 text;
    std::unique_ptr<Expression> expression;
    bool                        state_dependent = false;
  };
} // namespace hemicontact
