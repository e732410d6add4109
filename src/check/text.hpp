#pragma once
/// @file
/// Internal to the check layer: an answer or a worksheet line without surrounding whitespace.
#include <string>

namespace wobble::check {

inline std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

}  // namespace wobble::check
