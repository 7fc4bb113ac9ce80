#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/normal/penetration_limit.h>

#include <cmath>

namespace hemicontact
{
  void
  declare_penetration_limit(ParameterHandler  &prm,
                            const std::string &default_value)
  {
    prm.declare_entry(
      penetration_limit_entry,
      default_value,
      Patterns::Double(),
      "The rigid wall behind the law: the normal displacement u_nu (positive "
      "into the foundation) may not exceed g >= 0. In the velocity classes "
      "the wall bounds the step's velocity, w_nu <= (g - u_nu)/k "
      "(doc/theory.md section 10).");
  }

  double
  checked_penetration_limit(const std::string &law_name, const double g)
  {
    require(std::isfinite(g) && g >= 0,
            "normal law '" + law_name +
              "': the 'penetration limit' g = " + std::to_string(g) +
              " must be a finite number >= 0: the wall stands at or behind "
              "the foundation's surface, where the body touches it in the "
              "reference configuration (u_nu = 0). For a law without a wall "
              "choose another law; see doc/laws.md.");
    return g;
  }
} // namespace hemicontact
