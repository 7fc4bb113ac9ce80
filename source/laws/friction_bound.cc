#include <hemicontact/base/exceptions.h>
#include <hemicontact/expressions/constants.h>
#include <hemicontact/laws/friction_bound.h>

#include <cmath>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    std::vector<std::string>
    bound_variables(const int dim)
    {
      return dim == 2 ?
               std::vector<std::string>{
                 "x", "y", "t", "u_nu", "w_nu", "p_nu", "s_tau"} :
               std::vector<std::string>{
                 "x", "y", "z", "t", "u_nu", "w_nu", "p_nu", "s_tau"};
    }
  } // namespace

  template <int dim>
  FrictionBound<dim>::FrictionBound(const std::string &expression_text,
                                    const std::string &constants)
    : text(expression_text)
  {
    const std::map<std::string, double> values = parse_constants(constants);
    try
      {
        expression = std::make_unique<Expression>(text,
                                                  bound_variables(dim),
                                                  values,
                                                  "friction bound");
      }
    catch (const InputError &e)
      {
        throw InputError(
          std::string("data: ") + e.what() + " The variables are " +
          (dim == 2 ? "x, y" : "x, y, z") +
          ", t, u_nu (the normal displacement), w_nu (the normal "
          "velocity), p_nu (the contact pressure) and s_tau (the "
          "accumulated slip).");
      }
    state_dependent =
      expression->uses_variable(dim) || expression->uses_variable(dim + 1) ||
      expression->uses_variable(dim + 2) ||
      expression->uses_variable(dim + 3) || expression->uses_variable(dim + 4);
  }

  template <int dim>
  double
  FrictionBound<dim>::value(const Point<dim> &p,
                            const double      t,
                            const double      u_nu,
                            const double      w_nu,
                            const double      p_nu,
                            const double      s_tau) const
  {
    std::vector<double> at(dim + 5);
    for (int d = 0; d < dim; ++d)
      at[d] = p[d];
    at[dim]        = t;
    at[dim + 1]    = u_nu;
    at[dim + 2]    = w_nu;
    at[dim + 3]    = p_nu;
    at[dim + 4]    = s_tau;
    const double v = expression->evaluate(at);
    if (!(v >= 0) || !std::isfinite(v))
      {
        std::ostringstream s;
        s << "data: 'friction bound' = " << quoted_expression(text) << " is "
          << (std::isfinite(v) ? "negative" : "not a finite number") << " ("
          << v << ") at the contact node x = (" << p << "), t = " << t
          << ", u_nu = " << u_nu << ", w_nu = " << w_nu << ", p_nu = " << p_nu;
        if (uses_slip())
          s << ", s_tau = " << s_tau;
        s << "; F_b must be a finite number >= 0.";
        throw InputError(s.str());
      }
    return v;
  }

  template class FrictionBound<2>;
  template class FrictionBound<3>;
} // namespace hemicontact
