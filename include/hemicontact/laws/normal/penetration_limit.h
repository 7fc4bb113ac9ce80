#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace hemicontact
{
  using namespace dealii;

  /** The entry name of a law's wall: "penetration limit". */
  inline constexpr const char *penetration_limit_entry = "penetration limit";

  /** Declare "penetration limit" (g >= 0) in the current subsection. */
  void
  declare_penetration_limit(ParameterHandler  &prm,
                            const std::string &default_value);

  /**
   * @p g if it is a finite number >= 0; otherwise an InputError naming
   * the law @p law_name and the parameter.
   */
  double
  checked_penetration_limit(const std::string &law_name, const double g);
} // namespace hemicontact
