#include <hemicontact/laws/contact_laws.h>

namespace hemicontact
{
  ContactLaws
  create_contact_laws(ParameterHandler &prm)
  {
    ContactLaws laws;
    laws.normal   = create_normal_law(prm);
    laws.friction = create_friction_law(prm);
    return laws;
  }
} // namespace hemicontact
