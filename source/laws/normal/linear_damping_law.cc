#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/law_parameters.h>
#include <hemicontact/laws/normal/linear_damping_law.h>

namespace hemicontact
{
  void
  LinearDampingLaw::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(law_name);
    prm.declare_entry("coefficient",
                      "1",
                      Patterns::Double(),
                      "Damping coefficient c >= 0 of xi = c r_+.");
    prm.leave_subsection();
  }

  LinearDampingLaw::LinearDampingLaw(ParameterHandler &prm)
    : LinearDampingLaw(get_law_double(prm, law_name, "coefficient"))
  {}

  LinearDampingLaw::LinearDampingLaw(const double coefficient)
    : coefficient(coefficient)
  {
    require(coefficient >= 0,
            "normal law 'linear damping': the coefficient = " +
              std::to_string(coefficient) + " must be non-negative.");
  }
} // namespace hemicontact
