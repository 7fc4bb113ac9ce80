#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/number_list.h>

#include <cmath>

namespace hemicontact
{
  std::vector<double>
  get_number_list(const dealii::ParameterHandler &prm,
                  const std::string              &subsection,
                  const std::string              &entry)
  {
    std::vector<double> numbers;
    for (const std::string &item :
         dealii::Utilities::split_string_list(prm.get(entry), ','))
      {
        double value;
        try
          {
            value = dealii::Utilities::string_to_double(item);
          }
        catch (...)
          {
            throw InputError(subsection + ": '" + entry + "' entry '" + item +
                             "' is not a number.");
          }
        require(std::isfinite(value),
                subsection + ": '" + entry + "' entry '" + item +
                  "' is not a finite number.");
        numbers.push_back(value);
      }
    return numbers;
  }

  std::vector<unsigned int>
  get_id_list(const dealii::ParameterHandler &prm, const std::string &entry)
  {
    std::vector<unsigned int> ids;
    for (const int i : dealii::Utilities::string_to_int(
           dealii::Utilities::split_string_list(prm.get(entry), ',')))
      ids.push_back(static_cast<unsigned int>(i));
    return ids;
  }

  std::vector<std::string>
  split_at_top_level_commas(const std::string &text)
  {
    std::vector<std::string> items;
    if (dealii::Utilities::trim(text).empty())
      return items;
    std::string item;
    int         depth = 0;
    for (const char c : text)
      {
        depth += (c == '(') - (c == ')');
        if (c == ',' && depth == 0)
          {
            items.push_back(dealii::Utilities::trim(item));
            item.clear();
          }
        else
          item += c;
      }
    items.push_back(dealii::Utilities::trim(item));
    return items;
  }
} // namespace hemicontact
