#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * The comma-separated numbers of the entry @p entry of the subsection
   * @p subsection (entered already), each a finite number; an InputError
   * "SUBSECTION: 'ENTRY' entry 'ITEM' is not a (finite) number." otherwise.
   */
  std::vector<double>
  get_number_list(const dealii::ParameterHandler &prm,
                  const std::string              &subsection,
                  const std::string              &entry);

  /**
   * The comma-separated boundary ids of the entry @p entry (of the
   * subsection entered already; its pattern checks each is 0..255).
   */
  std::vector<unsigned int>
  get_id_list(const dealii::ParameterHandler &prm, const std::string &entry);

  /**
   * @p text split at the commas outside parentheses (those inside belong
   * to a function's arguments, as in max(x, 1)), each item trimmed.
   */
  std::vector<std::string>
  split_at_top_level_commas(const std::string &text);
} // namespace hemicontact
