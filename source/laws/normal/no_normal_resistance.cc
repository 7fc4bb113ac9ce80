#include <hemicontact/laws/normal/no_normal_resistance.h>

namespace hemicontact
{
  void
  NoNormalResistance::declare_parameters(ParameterHandler &)
  {}

  NoNormalResistance::NoNormalResistance(ParameterHandler &)
  {}
} // namespace hemicontact
