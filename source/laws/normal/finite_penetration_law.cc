#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/law_parameters.h>
#include <hemicontact/laws/normal/finite_penetration_law.h>
#include <hemicontact/laws/normal/penetration_limit.h>

namespace hemicontact
{
  void
  FinitePenetrationLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(law_name);
    prm.declare_entry("stiffness",
                      "10",
                      Patterns::Double(),
                      "Compliance stiffness c_p >= 0 of the response "
                      "p(r) = c_p r_+ below the penetration limit.");
    declare_penetration_limit(prm, "0.1");
    prm.leave_subsection();
  }

  FinitePenetrationLaw::FinitePenetrationLaw(ParameterHandler &prm)
    : FinitePenetrationLaw(get_law_double(prm, law_name, "stiffness"),
                           get_law_double(prm,
                                          law_name,
                                          penetration_limit_entry))
  {}

  FinitePenetrationLaw::FinitePenetrationLaw(const double stiffness,
                                             const double penetration_limit)
    : stiffness(stiffness)
    , limit(checked_penetration_limit(law_name, penetration_limit))
  {
    require(stiffness >= 0,
            std::string("normal law '") + law_name + "': the 'stiffness' = " +
              std::to_string(stiffness) + " must be non-negative.");
  }
} // namespace hemicontact
