#include "check/plus_minus.hpp"

#include <array>
#include <cctype>
#include <string_view>

namespace wobble::check {

namespace {
// A spelling of the sign and whether it is '±' (true) or '∓' (false). Longer spellings first:
// "+/-" before "+-". "-+" is not one: "a -+b" is rare, and "x^-+1" no sign of either.
struct Spelling {
  std::string_view text;
  bool plus_first;
};
// The minus may be U+2212, as a key prints it.
constexpr std::array<Spelling, 10> kSpellings{{{"±", true},
                                               {"∓", false},
                                               {"+/-", true},
                                               {"+/−", true},
                                               {"-/+", false},
                                               {"−/+", false},
                                               {"+-", true},
                                               {"+−", true},
                                               {"\\pm", true},
                                               {"\\mp", false}}};

// Whether a LaTeX command spelt `cmd` at `text[at]` ends there (\pm, not \pmb or \pmod).
bool command_ends(const std::string& text, std::size_t at, std::string_view cmd) {
  const std::size_t end = at + cmd.size();
  return cmd.front() != '\\' || end >= text.size() ||
         !std::isalpha(static_cast<unsigned char>(text[end]));
}
}  // namespace

std::optional<SignReadings> sign_readings(const std::string& text) {
  SignReadings r;
  bool found = false;
  for (std::size_t i = 0; i < text.size();) {
    bool matched = false;
    for (const auto& s : kSpellings) {
      if (text.compare(i, s.text.size(), s.text) == 0 && command_ends(text, i, s.text)) {
        r.plus += s.plus_first ? '+' : '-';
        r.minus += s.plus_first ? '-' : '+';
        i += s.text.size();
        matched = found = true;
        break;
      }
    }
    if (!matched) {
      r.plus += text[i];
      r.minus += text[i];
      ++i;
    }
  }
  if (!found) return std::nullopt;
  return r;
}

}  // namespace wobble::check
