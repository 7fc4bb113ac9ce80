#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/law_parameters.h>
#include <hemicontact/laws/normal/exponential_law.h>

#include <cmath>

namespace hemicontact
{
  void
  ExponentialLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(law_name);
    prm.declare_entry("a",
                      "1",
                      Patterns::Double(),
                      "Upper end of dj(0) = [0,a]; the response at the onset "
                      "of penetration. Must satisfy a >= b.");
    prm.declare_entry("b",
                      "0.5",
                      Patterns::Double(),
                      "Asymptotic response for large normal velocity, b >= 0.");
    prm.declare_entry("beta",
                      "10",
                      Patterns::Double(),
                      "Decay rate beta >= 0 of the response from a to b.");
    prm.leave_subsection();
  }

  ExponentialLaw::ExponentialLaw(ParameterHandler &prm)
    : ExponentialLaw(get_law_double(prm, law_name, "a"),
                     get_law_double(prm, law_name, "b"),
                     get_law_double(prm, law_name, "beta"))
  {}

  ExponentialLaw::ExponentialLaw(const double a,
                                 const double b,
                                 const double beta)
    : a(a)
    , b(b)
    , beta(beta)
  {
    require(b >= 0,
            "normal law 'exponential': the parameter b = " + std::to_string(b) +
              " must be non-negative.");
    require(
      a >= b,
      "normal law 'exponential': the parameter a = " + std::to_string(a) +
        " is smaller than b = " + std::to_string(b) +
        "; the law needs a >= b (a response that decreases from a to b).");
    require(beta >= 0,
            "normal law 'exponential': the decay rate beta = " +
              std::to_string(beta) + " must be non-negative.");
  }

  double
  ExponentialLaw::remainder(const double r) const
  {
    return r > 0 ? (a - b) * (std::exp(-beta * r) - 1.) : 0.;
  }

  double
  ExponentialLaw::remainder_derivative(const double r) const
  {
    return r > 0 ? -beta * (a - b) * std::exp(-beta * r) : 0.;
  }

  double
  ExponentialLaw::remainder_primitive(const double r) const
  {
    if (r <= 0)
      return 0.;
    if (beta == 0)
      return 0.;
    // int_0^r (a-b)(e^{-beta s} - 1) ds, with expm1 for accuracy at small r
    return (a - b) * (-std::expm1(-beta * r) / beta - r);
  }
} // namespace hemicontact
