#include <hemicontact/laws/law_parameters.h>
#include <hemicontact/laws/normal/penetration_limit.h>
#include <hemicontact/laws/normal/signorini_law.h>

namespace hemicontact
{
  void
  SignoriniLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(law_name);
    declare_penetration_limit(prm, "0");
    prm.leave_subsection();
  }

  SignoriniLaw::SignoriniLaw(ParameterHandler &prm)
    : SignoriniLaw(get_law_double(prm, law_name, penetration_limit_entry))
  {}

  SignoriniLaw::SignoriniLaw(const double penetration_limit)
    : limit(checked_penetration_limit(law_name, penetration_limit))
  {}
} // namespace hemicontact
