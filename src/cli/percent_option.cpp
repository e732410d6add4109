#include <charconv>

#include "cli/commands.hpp"
#include "problem/values.hpp"

namespace wobble::cli {

CLI::Validator fraction_or_percent() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        if (const auto fraction = percent_as_fraction(text)) {
          char buf[32];
          const auto written = std::to_chars(buf, buf + sizeof buf, *fraction);
          text.assign(buf, written.ptr);  // the shortest text that reads back as the fraction
        }
        return "";  // anything else is the number's to read, and the option's to refuse
      },
      "", "fraction or percent");
}

}  // namespace wobble::cli
