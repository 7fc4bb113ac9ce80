#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/law_parameters.h>

#include <cmath>

namespace hemicontact
{
  double
  get_law_double(ParameterHandler  &prm,
                 const std::string &law,
                 const std::string &key)
  {
    prm.enter_subsection(law);
    const double value = prm.get_double(key);
    prm.leave_subsection();
    require(std::isfinite(value),
            "'" + law + "/" + key + "' = " + std::to_string(value) +
              " is not a finite number.");
    return value;
  }
} // namespace hemicontact
