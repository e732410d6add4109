#include <fmt/format.h>

#include <charconv>

#include "cli/commands.hpp"
#include "problem/problem.hpp"
#include "problem/values.hpp"

namespace wobble::cli {

CLI::Validator fraction_or_percent() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (const auto fraction = percent_as_fraction(text)) {
          // Refused here, where the percentage is still as typed: after the rewrite "200%" would
          // be shown as the fraction 2, which nobody typed.
          if (!(*fraction > 0.0 && *fraction < 1.0))
            return "'" + text + "' must be between 0% and 100% (1% is 0.01)";
          if (const std::string why =
                  tolerance_too_fine(*fraction, fmt::format("'{}' ({:g})", text, *fraction));
              !why.empty())
            return why;
          char buf[32];
          const auto written = std::to_chars(buf, buf + sizeof buf, *fraction);
          text.assign(buf, written.ptr);  // the shortest text that reads back as the fraction
        }
        return "";  // anything else is the number's to read, and the option's to refuse
      },
      "", "fraction or percent");
}

}  // namespace wobble::cli
