#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/friction/rational_weakening.h>
#include <hemicontact/laws/law_parameters.h>

#include <cmath>

namespace hemicontact
{
  void
  RationalWeakeningLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(law_name);
    prm.declare_entry("characteristic slip",
                      "1",
                      Patterns::Double(),
                      "s0 > 0 of the force F_b/(1 + s/s0) at slip (or slip "
                      "speed) s: the potential F_b s0 ln(1 + s/s0).");
    prm.leave_subsection();
  }

  RationalWeakeningLaw::RationalWeakeningLaw(ParameterHandler &prm)
    : RationalWeakeningLaw(get_law_double(prm, law_name, "characteristic slip"))
  {}

  RationalWeakeningLaw::RationalWeakeningLaw(const double characteristic_slip)
    : s0(characteristic_slip)
  {
    require(s0 > 0,
            "friction law 'rational weakening': the 'characteristic slip' " +
              std::to_string(s0) + " must be positive.");
  }

  double
  RationalWeakeningLaw::remainder(const double bound, const double s) const
  {
    return s > 0 ? -bound * (s / s0) / (1 + s / s0) : 0.;
  }

  double
  RationalWeakeningLaw::remainder_derivative(const double bound,
                                             const double s) const
  {
    const double x = std::max(s, 0.) / s0;
    return -bound / (s0 * (1 + x) * (1 + x));
  }

  double
  RationalWeakeningLaw::remainder_primitive(const double bound,
                                            const double s) const
  {
    // int_0^s -F_b (t/s0)/(1 + t/s0) dt = F_b (s0 ln(1 + s/s0) - s)
    return s > 0 ? bound * (s0 * std::log1p(s / s0) - s) : 0.;
  }

  double
  RationalWeakeningLaw::relaxed_monotonicity_constant(const double bound) const
  {
    return bound / s0;
  }
} // namespace hemicontact
