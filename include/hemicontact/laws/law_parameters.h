#pragma once

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace hemicontact
{
  using namespace dealii;

  /**
   * Entry @p key of subsection @p law of the current subsection of @p prm
   * (a normal or friction law's constant, read in the law's constructor);
   * throws an InputError if it is not a finite number.
   */
  double
  get_law_double(ParameterHandler  &prm,
                 const std::string &law,
                 const std::string &key);
} // namespace hemicontact
