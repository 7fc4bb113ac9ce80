#include <deal.II/base/numbers.h>
#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/expressions/constants.h>
#include <hemicontact/expressions/expression.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  namespace
  {
    /** Why @p name cannot be a constant of 'data/constants' ("" if it can):
     *  not a name, or a name the expressions already give a meaning. */
    std::string
    reserved_because(const std::string &name)
    {
      if (!(std::isalpha(static_cast<unsigned char>(name[0])) ||
            name[0] == '_') ||
          !std::all_of(name.begin(), name.end(), [](const char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
          }))
        return "is not a name (letters, digits and '_', not starting with "
               "a digit)";
      static const std::set<std::string> variables = {
        "x", "y", "z", "t", "u_nu", "w_nu"};
      if (variables.count(name) != 0)
        return "is a variable of the expressions (x, y, z, t, and u_nu, "
               "w_nu in the friction bound)";
      if (name == "pi" || name == "_pi" || name == "_e")
        return "is a predefined constant";
      // muparser's functions besides those of the grammar
      // (Expression::function_names()), kept free for its users
      static const std::set<std::string> parser_functions = {
        "asin", "acos", "asinh", "acosh", "atanh",     "log2",  "log10", "ln",
        "rint", "sum",  "avg",   "if",    "int",       "ceil",  "floor", "cot",
        "csc",  "sec",  "erfc",  "rand",  "rand_seed", "atan2", "fmod"};
      const auto &functions = Expression::function_names();
      if (parser_functions.count(name) != 0 ||
          std::find(functions.begin(), functions.end(), name) !=
            functions.end())
        return "is a function of the expressions";
      return "";
    }
  } // namespace

  std::map<std::string, double>
  parse_constants(const std::string &text)
  {
    std::map<std::string, double>      constants;
    std::map<std::string, std::string> definition; // name -> its entry
    for (const std::string &item : Utilities::split_string_list(text, ','))
      {
        const std::vector<std::string> kv =
          Utilities::split_string_list(item, '=');
        require(kv.size() == 2 && !kv[0].empty(),
                "data: 'constants' entry '" + item +
                  "' is not of the form name=value.");
        const std::string &name = kv[0];
        const std::string  why  = reserved_because(name);
        require(why.empty(),
                "data: the constant '" + name + "' of 'constants' " + why +
                  "; choose another name.");
        const auto earlier = definition.find(name);
        if (earlier != definition.end())
          throw InputError("data: 'constants' defines '" + name + "' twice: '" +
                           earlier->second + "' and '" + item +
                           "'; keep one (neither is chosen silently).");
        double value;
        try
          {
            value = Utilities::string_to_double(kv[1]);
          }
        catch (...)
          {
            throw InputError("data: 'constants' entry '" + item +
                             "' does not give a number.");
          }
        require(std::isfinite(value),
                "data: 'constants' entry '" + item +
                  "' is not a finite number.");
        constants[name]  = value;
        definition[name] = item;
      }
    constants["pi"]  = numbers::PI;
    constants["_pi"] = numbers::PI;
    constants["_e"]  = numbers::E;
    return constants;
  }
} // namespace hemicontact
