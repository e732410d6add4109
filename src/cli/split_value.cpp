#include <algorithm>
#include <array>
#include <string_view>

#include "cli/commands.hpp"

namespace wobble::cli {

namespace {
// The options of one value that is read with a unit or as an expression, and so may hold a
// space ("--t-end 2 min"); a number option's value has none, and --set, which takes several
// values, says itself what it got instead of NAME=VALUE.
constexpr std::array<std::string_view, 1> kValuesWithSpaces{"--t-end"};

bool takes_spaces(std::string_view word) {
  return std::find(kValuesWithSpaces.begin(), kValuesWithSpaces.end(), word) !=
         kValuesWithSpaces.end();
}

// The option a word gives its value to after '=' ("--t-end=2" -> "--t-end"), else "".
std::string_view glued_option(std::string_view word) {
  for (const std::string_view option : kValuesWithSpaces) {
    if (word.size() > option.size() && word.substr(0, option.size()) == option &&
        word[option.size()] == '=')
      return option;
  }
  return {};
}

bool is_option(const std::string& word) {
  return !word.empty() && word[0] == '-';
}

std::string shell_word(const std::string& word) {
  const bool plain = word.find_first_of(" '\"*?$&|;<>()[]{}\\") == std::string::npos;
  return plain ? word : "'" + word + "'";
}
}  // namespace

std::string value_split_message(const std::vector<std::string>& args,
                                const std::vector<std::string>& extras) {
  if (extras.empty()) return "";
  // The first word left over, right after the value of an option that takes spaces.
  for (std::size_t at = 2; at < args.size(); ++at) {
    if (args[at] != extras.front()) continue;
    const std::string_view glued = glued_option(args[at - 1]);
    if (glued.empty() && (is_option(args[at - 1]) || !takes_spaces(args[at - 2]))) continue;
    const std::string option = glued.empty() ? args[at - 2] : std::string(glued);
    std::string value = glued.empty() ? args[at - 1] : args[at - 1].substr(glued.size() + 1);
    std::size_t end = at;  // the value's words: up to the next option
    for (; end < args.size() && !is_option(args[end]); ++end) value += " " + args[end];
    std::string line = "wobble";
    for (std::size_t i = 1; i < args.size(); ++i) {
      if (i + 1 == at) {
        line += (glued.empty() ? " '" : " " + option + "='") + value + "'";
        i = end - 1;
      } else {
        line += " " + shell_word(args[i]);
      }
    }
    return option + ": the shell parted its value at a space; give it in quotes: " + line;
  }
  return "";
}

}  // namespace wobble::cli
