#pragma once

#include <map>
#include <string>

namespace hemicontact
{
  /**
   * The user constants of 'data/constants' ("a=1, b=2") plus pi, _pi and
   * _e; a malformed entry throws an InputError.
   */
  std::map<std::string, double>
  parse_constants(const std::string &text);
} // namespace hemicontact
