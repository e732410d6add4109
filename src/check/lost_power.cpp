#include "check/lost_power.hpp"

#include <array>
#include <cctype>
#include <string_view>

namespace wobble::check {
namespace {

constexpr std::array<std::string_view, 6> kTimesSigns{"*", "x", "X", "×", "·", "⋅"};
constexpr std::array<std::string_view, 3> kMinusSigns{"-", "−", "–"};
constexpr std::size_t kMostExponentDigits = 3;

bool is_digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// Where `text` before `end` ends in a times sign after a number's last digit ("7.2 × "), with
// spaces between.
bool after_number_times(std::string_view text, std::size_t end) {
  while (end > 0 && text[end - 1] == ' ') --end;
  for (const std::string_view sign : kTimesSigns) {
    if (end < sign.size() || text.substr(end - sign.size(), sign.size()) != sign) continue;
    std::size_t before = end - sign.size();
    while (before > 0 && text[before - 1] == ' ') --before;
    return before > 0 && is_digit(text[before - 1]);
  }
  return false;
}

// The length of the minus sign at `at`, 0 for none.
std::size_t minus_at(std::string_view text, std::size_t at) {
  for (const std::string_view sign : kMinusSigns) {
    if (text.substr(at, sign.size()) == sign) return sign.size();
  }
  return 0;
}

}  // namespace

std::optional<LostPower> lost_powers_of_ten(const std::string& text) {
  const std::string_view s = text;
  std::optional<LostPower> found;
  std::string out;
  std::size_t done = 0;
  for (std::size_t at = s.find("10"); at != std::string_view::npos; at = s.find("10", at + 1)) {
    // A whole 10 ("710-4" and "1.10-4" are other numbers) after "7.2 ×".
    if (at > 0 && (is_digit(s[at - 1]) || s[at - 1] == '.')) continue;
    if (!after_number_times(s, at)) continue;
    const std::size_t minus = minus_at(s, at + 2);
    if (minus == 0) continue;
    const std::size_t digits = at + 2 + minus;
    std::size_t end = digits;
    while (end < s.size() && is_digit(s[end])) ++end;
    // "10-4.5", "10-4^2": a difference that goes on as an expression, not an exponent.
    if (end == digits || end - digits > kMostExponentDigits ||
        (end < s.size() && (s[end] == '.' || s[end] == '^')))
      continue;
    const std::string exponent(s.substr(digits, end - digits));
    if (!found) {
      found = LostPower{"", std::string(s.substr(at, end - at)), exponent};
    }
    out.append(s.substr(done, at + 2 - done));
    out += "^-" + exponent;
    done = end;
    at = end - 1;
  }
  if (!found) return std::nullopt;
  found->as_powers = out.append(s.substr(done));
  return found;
}

}  // namespace wobble::check
