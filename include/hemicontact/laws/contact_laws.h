#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hemicontact/laws/friction_law.h>
#include <hemicontact/laws/normal_law.h>

#include <memory>

namespace hemicontact
{
  using namespace dealii;

  /** The two laws on Gamma_3: the normal damped response and friction. */
  struct ContactLaws
  {
    std::unique_ptr<NormalLaw>   normal;
    std::unique_ptr<FrictionLaw> friction;
  };

  /**
   * The laws selected in subsections "normal law" and "friction law" of
   * @p prm; throws an InputError naming a law whose constants are invalid.
   */
  ContactLaws
  create_contact_laws(ParameterHandler &prm);
} // namespace hemicontact
