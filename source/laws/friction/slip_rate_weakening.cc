#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/friction/slip_rate_weakening.h>
#include <hemicontact/laws/law_parameters.h>

#include <cmath>

namespace hemicontact
{
  void
  SlipRateWeakeningLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(law_name);
    prm.declare_entry("static coefficient",
                      "0.6",
                      Patterns::Double(),
                      "Static friction coefficient mu_s > 0; 'data/friction "
                      "bound' is the static bound, reached at zero slip "
                      "speed.");
    prm.declare_entry("dynamic coefficient",
                      "0.4",
                      Patterns::Double(),
                      "Dynamic friction coefficient mu_d, 0 < mu_d <= mu_s: "
                      "the bound falls to F_b mu_d/mu_s at high slip speed.");
    prm.declare_entry("characteristic slip speed",
                      "0.1",
                      Patterns::Double(),
                      "Slip speed v0 > 0 over which the friction force decays "
                      "from the static towards the dynamic value "
                      "(exp(-s/v0)).");
    prm.leave_subsection();
  }

  SlipRateWeakeningLaw::SlipRateWeakeningLaw(ParameterHandler &prm)
    : SlipRateWeakeningLaw(get_law_double(prm, law_name, "static coefficient"),
                           get_law_double(prm, law_name, "dynamic coefficient"),
                           get_law_double(prm,
                                          law_name,
                                          "characteristic slip speed"))
  {}

  SlipRateWeakeningLaw::SlipRateWeakeningLaw(
    const double static_coefficient,
    const double dynamic_coefficient,
    const double characteristic_slip_speed)
    : drop(1. - dynamic_coefficient / static_coefficient)
    , v0(characteristic_slip_speed)
  {
    const std::string law = "friction law 'slip rate weakening': ";
    require(static_coefficient > 0,
            law + "the static coefficient " +
              std::to_string(static_coefficient) + " must be positive.");
    require(dynamic_coefficient > 0,
            law + "the dynamic coefficient " +
              std::to_string(dynamic_coefficient) + " must be positive.");
    require(dynamic_coefficient <= static_coefficient,
            law + "the dynamic coefficient " +
              std::to_string(dynamic_coefficient) +
              " exceeds the static coefficient " +
              std::to_string(static_coefficient) +
              "; the law weakens with slip speed, so mu_d <= mu_s.");
    require(v0 > 0,
            law + "the characteristic slip speed " + std::to_string(v0) +
              " must be positive.");
  }

  double
  SlipRateWeakeningLaw::remainder(const double bound, const double s) const
  {
    return s > 0 ? bound * drop * std::expm1(-s / v0) : 0.;
  }

  double
  SlipRateWeakeningLaw::remainder_derivative(const double bound,
                                             const double s) const
  {
    return -bound * drop / v0 * std::exp(-std::max(s, 0.) / v0);
  }

  double
  SlipRateWeakeningLaw::remainder_primitive(const double bound,
                                            const double s) const
  {
    // int_0^s -F_b drop (1 - e^{-t/v0}) dt
    return s > 0 ? -bound * drop * (s + v0 * std::expm1(-s / v0)) : 0.;
  }

  double
  SlipRateWeakeningLaw::relaxed_monotonicity_constant(const double bound) const
  {
    return bound * drop / v0;
  }
} // namespace hemicontact
