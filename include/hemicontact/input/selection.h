#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hemicontact/base/exceptions.h>

#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  /**
   * The spellings in a parameter file of the values of an enum class, in
   * the order of the Patterns::Selection.
   */
  template <typename Enum>
  using SelectionNames = std::vector<std::pair<std::string, Enum>>;

  /** The pattern "a|b|c" of the spellings @p names. */
  template <typename Enum>
  dealii::Patterns::Selection
  selection_pattern(const SelectionNames<Enum> &names)
  {
    std::string pattern;
    for (const auto &n : names)
      pattern += (pattern.empty() ? "" : "|") + n.first;
    return dealii::Patterns::Selection(pattern);
  }

  /** The value of the selection @p entry of @p prm. */
  template <typename Enum>
  Enum
  get_selection(const dealii::ParameterHandler &prm,
                const std::string              &entry,
                const SelectionNames<Enum>     &names)
  {
    const std::string value = prm.get(entry);
    for (const auto &n : names)
      if (n.first == value)
        return n.second;
    throw InputError("'" + entry + "' = '" + value +
                     "' is none of the values it can take.");
  }
} // namespace hemicontact
