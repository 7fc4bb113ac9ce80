/**
 * The subsection 'wear': Archard wear on a foundation moving tangentially
 * (WearParameters, include/hemicontact/input/parameters.h).
 */
#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/number_list.h>
#include <hemicontact/input/parameters.h>

#include <cmath>
#include <sstream>
#include <string>

namespace hemicontact
{
  void
  WearParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("wear");
    prm.declare_entry(
      "wear coefficient",
      "0",
      Patterns::Anything(),
      "Archard wear of the foundation (doc/theory.md, section 11.12): the "
      "wear depth omega = k_w int_0^t p |slip - v*| ds at each contact node, "
      "p = (-sigma_nu)_+ the contact pressure, moves the foundation away: "
      "in the static class the normal law acts on u_nu - omega and a wall "
      "is u_nu <= g + omega, in the velocity classes the wall is "
      "w_nu <= (g + omega - u_nu)/k and the law on w_nu is unchanged. The "
      "integral is the left-rectangle sum over the states before the step, "
      "omega_n = k_w sum_{j<n} k_j p_j |w_tau,j - v*| (velocity classes) or "
      "k_w sum_{j<n} p_j |u_tau,j - u_tau,j-1 - k_j v*| (static class). "
      "k_w >= 0, a finite number; 0: no wear. Adapted meshes carry the "
      "wear; not with manufactured solutions or the error estimate.");
    prm.declare_entry(
      "foundation velocity",
      "",
      Patterns::Anything(),
      "The velocity v* of the foundation, comma-separated finite numbers, "
      "one per space dimension (empty: at rest). Only its tangential part "
      "at each contact node enters the wear (the part along the node's "
      "normal is dropped); the friction law acts on the body's own slip.");
    prm.leave_subsection();
  }

  void
  WearParameters::parse(ParameterHandler &prm, const unsigned int dimension)
  {
    prm.enter_subsection("wear");
    const std::string coefficient_text = prm.get("wear coefficient");
    try
      {
        coefficient = Utilities::string_to_double(coefficient_text);
      }
    catch (...)
      {
        throw InputError("wear: 'wear coefficient' = '" + coefficient_text +
                         "' is not a number; give k_w >= 0 (0: no wear).");
      }
    foundation_velocity = get_number_list(prm, "wear", "foundation velocity");
    prm.leave_subsection();

    std::ostringstream value;
    value << coefficient;
    require(std::isfinite(coefficient) && coefficient >= 0,
            "wear: 'wear coefficient' = " + value.str() +
              " must be a finite number >= 0 (the Archard coefficient k_w; "
              "0: no wear).");
    if (foundation_velocity.empty())
      foundation_velocity.assign(dimension, 0.);
    require(foundation_velocity.size() == dimension,
            "wear: 'foundation velocity' has " +
              std::to_string(foundation_velocity.size()) +
              " components; give one per space dimension (" +
              std::to_string(dimension) + "), comma-separated.");
  }
} // namespace hemicontact
