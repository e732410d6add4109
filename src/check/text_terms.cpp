#include "check/text_terms.hpp"

#include <algorithm>
#include <cctype>

#include "check/answer_reading.hpp"

namespace wobble::check::detail {

// Whether s has an identifier that is one of the problem's symbols; whether all of its
// identifiers are (and it has one).
bool has_identifier_of(const std::string& s, const sym::SymbolTable& table) {
  for (const auto& [start, length] : identifiers(s)) {
    if (table.contains(s.substr(start, length))) return true;
  }
  return false;
}
bool all_identifiers_of(const std::string& s, const sym::SymbolTable& table) {
  const auto ids = identifiers(s);
  return !ids.empty() && std::all_of(ids.begin(), ids.end(), [&](const auto& id) {
    return table.contains(s.substr(id.first, id.second));
  });
}

// Whether the '+' or '-' at s[i] starts a term: not a leading sign, nor a factor's sign after
// '*', '/', '^' or an exponent's e ("10^-4", "1e-4", "2*-1").
bool starts_term(const std::string& s, std::size_t i) {
  const std::size_t before = i == 0 ? std::string::npos : s.find_last_not_of(' ', i - 1);
  if (before == std::string::npos) return false;
  const char b = s[before];
  const bool exponent = (b == 'e' || b == 'E') && before > 0 &&
                        std::isdigit(static_cast<unsigned char>(s[before - 1]));
  return b != '*' && b != '/' && b != '^' && !exponent;
}

// Whether s is one term: no '+' or '-' at its top level starts another ("[a, b]/2 + 1").
bool is_one_term(const std::string& s) {
  int depth = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    if (c == '(' || c == '[' || c == '{') ++depth;
    if (c == ')' || c == ']' || c == '}') --depth;
    if (depth == 0 && (c == '+' || c == '-') && starts_term(s, i)) return false;
  }
  return true;
}

// Whether X in `before` X `after` (each trimmed) is a factor of the term: not raised to a power
// ("X^2", "2^X") and not divided by ("1/X").
bool is_factor_between(const std::string& before, const std::string& after) {
  const bool power_or_divisor = !before.empty() && (before.back() == '^' || before.back() == '/');
  return !power_or_divisor &&
         (after.empty() || (after[0] != '^' && after.compare(0, 2, "**") != 0));
}

// `before` X `after` with 1 in X's place, joined by '*' where no '*' or '/' joins it: "2 [a, b]"
// is a product where "2 1" would be refused, and "(1 - x)(1)" would read as rows. A sign before
// X is its own ("-(a, b, c)": -1; X is one term, so the sign starts it).
std::string with_one_in_place(const std::string& before, const std::string& after) {
  const auto joins = [](char c) { return c == '*' || c == '/'; };
  const bool sign = !before.empty() && (before.back() == '-' || before.back() == '+');
  return before + (before.empty() || joins(before.back()) || sign ? "" : "*") + "1" +
         (after.empty() || joins(after[0]) ? "" : "*") + after;
}

}  // namespace wobble::check::detail
