#include "symbolic/glued_numbers.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "core/characters.hpp"

namespace wobble::sym {

namespace {

// The functions an expression may call, by every name it reads (expression_guard.cpp).
bool is_function(const std::string& name) {
  static const std::array<std::string, 20> kNames{
      "sqrt",   "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "arcsin",    "arccos",
      "arctan", "exp", "log", "ln",  "sinh", "cosh", "tanh", "abs",   "EllipticK", "EllipticE"};
  return std::find(kNames.begin(), kNames.end(), name) != kNames.end();
}
}  // namespace

bool ends_in_number(const std::string& text) {
  std::size_t k = text.size();
  while (k > 0 && (is_digit(text[k - 1]) || text[k - 1] == '.')) --k;
  return k < text.size() && (k == 0 || !(is_letter(text[k - 1]) || text[k - 1] == '_'));
}

bool starts_exponent(const std::string& s, std::size_t at) {
  const auto digit_at = [&](std::size_t j) { return j < s.size() && is_digit(s[j]); };
  return (s[at] == 'e' || s[at] == 'E') &&
         (digit_at(at + 1) ||
          (at + 1 < s.size() && (s[at + 1] == '+' || s[at + 1] == '-') && digit_at(at + 2)));
}

std::string name_at(const std::string& s, std::size_t at) {
  std::size_t end = at;
  while (end < s.size() && (std::isalnum(static_cast<unsigned char>(s[end])) || s[end] == '_'))
    ++end;
  return s.substr(at, end - at);
}

std::string numbers_times_constants(const std::string& ascii) {
  std::string out;
  for (std::size_t i = 0; i < ascii.size(); ++i) {
    // Letters only: the number before is looked for where a name starts, not at each digit.
    const bool after_factor =
        is_letter(ascii[i]) &&
        (ends_in_number(out) ? !starts_exponent(ascii, i) : !out.empty() && out.back() == ')');
    if (after_factor) {
      const std::string name = name_at(ascii, i);
      if (name == "pi" || name == "Pi" || is_function(name)) out += '*';
    }
    out += ascii[i];
  }
  return out;
}

}  // namespace wobble::sym
