#include <charconv>
#include <cmath>

#include "cli/commands.hpp"

namespace wobble::cli {

CLI::Validator whole_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        const char* end = text.data() + text.size();
        const auto [rest, error] = std::from_chars(text.data(), end, value);
        if (error != std::errc() || rest != end) return "";  // not a number: the option says so
        // Beyond 2^53 a double no longer holds every whole number: 1e17 may not be what was typed.
        constexpr double kExactWhole = 0x1p53;
        if (value != std::floor(value)) return "'" + text + "' is not a whole number";
        if (std::abs(value) > kExactWhole) return "'" + text + "' is too large a count";
        text = std::to_string(static_cast<long long>(value));
        return "";
      },
      "", "whole number");
}

}  // namespace wobble::cli
