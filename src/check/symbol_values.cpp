#include "check/symbol_values.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <utility>

#include "symbolic/plain_text.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble::check {

namespace {
// A typed number equal to a parameter's value: the value printed to 10 digits and typed back
// differs from the double by a few parts in 1e11, a different number by far more.
constexpr double kSameValue = 1e-9;
constexpr double kPi = 3.14159265358979323846;

bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }
bool in_name(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// The end of the number starting at `at`: digits, a decimal point, an exponent "e-3".
std::size_t number_end(const std::string& s, std::size_t at) {
  std::size_t i = at;
  while (i < s.size() && (digit(s[i]) || s[i] == '.')) ++i;
  if (i + 1 < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t k = i + 1;
    if (s[k] == '+' || s[k] == '-') ++k;
    if (k < s.size() && digit(s[k])) {
      while (k < s.size() && digit(s[k])) ++k;
      i = k;
    }
  }
  return i;
}

// Half a unit in the last digit of a number as typed: 0.00005 for "0.2618", 0.5 for "150",
// 5e-7 for "2.62e-6".
double half_unit_of(const std::string& number) {
  const std::size_t e = std::min(number.find_first_of("eE"), number.size());
  const std::size_t point = number.find('.');
  const long decimals = point < e ? static_cast<long>(e - point - 1) : 0;
  const long exponent = e < number.size() ? std::strtol(number.c_str() + e + 1, nullptr, 10) : 0;
  return 0.5 * std::pow(10.0, static_cast<double>(exponent - decimals));
}

// The significant digits of a number as typed: 4 for "0.2618", 3 for "150".
int significant_digits(const std::string& number) {
  int n = 0;
  bool leading = true;
  for (const char c : number) {
    if (c == 'e' || c == 'E' || !(digit(c) || c == '.')) break;
    if (c == '.') continue;
    leading = leading && c == '0';
    n += leading ? 0 : 1;
  }
  return n;
}

// Whether the previous character other than a space is '^': the number is an exponent.
bool after_power(const std::string& s, std::size_t at) {
  while (at > 0 && s[at - 1] == ' ') --at;
  return at > 0 && s[at - 1] == '^';
}
// The start of the first number at or after `from` that stands alone: not a digit of a name
// ("R2"), not after a decimal point, not an exponent ("R^2"); s.size() if none.
std::size_t next_number(const std::string& s, std::size_t from) {
  for (std::size_t i = from; i < s.size(); ++i) {
    const bool starts = digit(s[i]) || (s[i] == '.' && i + 1 < s.size() && digit(s[i + 1]));
    if (starts && !(i > 0 && (in_name(s[i - 1]) || s[i - 1] == '.')) && !after_power(s, i))
      return i;
  }
  return s.size();
}
}  // namespace

const ParameterValue* parameter_named(const Key& key, const std::string& name) {
  const auto p = std::find_if(key.parameters.begin(), key.parameters.end(),
                              [&](const ParameterValue& q) { return q.name == name; });
  return p == key.parameters.end() ? nullptr : &*p;
}

std::string shown_of(const ParameterValue& p) {
  const std::string shown = math_to_unicode(p.latex.empty() ? p.name : p.latex);
  return shown == p.name ? shown : shown + " (" + p.name + ")";
}

std::vector<NumberForSymbol> numbers_for_symbols(const Key& key, const std::string& typed) {
  const std::string s = sym::to_ascii(typed);
  std::vector<NumberForSymbol> found;
  for (std::size_t i = next_number(s, 0); i < s.size(); i = next_number(s, i)) {
    const std::size_t start = i;
    std::size_t end = number_end(s, i);
    std::string number = s.substr(i, end - i);
    const double x = std::strtod(number.c_str(), nullptr);
    const double half_unit = half_unit_of(number);  // before "°" is added
    const bool single_digit = number.size() == 1;
    std::size_t unit = end;
    while (unit < s.size() && s[unit] == ' ') ++unit;
    const bool degrees =
        s.compare(unit, 3, "deg") == 0 && (unit + 3 == s.size() || !in_name(s[unit + 3]));
    if (degrees) {
      number += "°";
      end = unit + 3;
    }
    i = end;
    // "2" in "m R^2/2" or "(1/2)" is a coefficient far more often than a parameter's value.
    if (single_digit && !degrees) continue;
    NumberForSymbol found_here{number, {}, false, start, end - start};
    for (const auto& p : key.parameters) {
      // In the unit typed; an angle's degrees also where the mark is missing ("cos 15").
      const bool unmarked = !degrees && p.unit == "rad" && significant_digits(number) >= 2;
      for (int pass = 0; pass < (unmarked ? 2 : 1); ++pass) {
        const bool in_degrees = degrees || pass == 1;
        const double v = in_degrees ? p.value * 180 / kPi : p.value;
        const double off = std::abs(x - v);
        const bool same = off <= kSameValue * std::abs(v);
        const bool as_rounded = significant_digits(number) >= 3 && off <= half_unit;
        if (v == 0.0 || !(same || as_rounded)) continue;
        found_here.rounded = found_here.rounded || !same;
        found_here.candidates.push_back({p.name, shown_of(p), in_degrees && !degrees});
        break;
      }
    }
    if (!found_here.candidates.empty()) found.push_back(std::move(found_here));
  }
  return found;
}

std::vector<NumberForSymbol> symbols_sharing_values(const Key& key, const std::string& typed) {
  const std::string s = sym::to_ascii(typed);
  std::vector<NumberForSymbol> found;
  for (std::size_t i = 0; i < s.size();) {
    if (digit(s[i]) || s[i] == '.') {  // a number whole, "2" in "2thetadot" and "2e5" too
      i = std::max(number_end(s, i), i + 1);
      continue;
    }
    if (!in_name(s[i])) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < s.size() && in_name(s[i])) ++i;
    const std::string name = s.substr(start, i - start);
    const ParameterValue* self = parameter_named(key, name);
    if (self == nullptr || self->value == 0.0) continue;
    NumberForSymbol here{shown_of(*self), {}, false, start, i - start};
    for (const auto& p : key.parameters) {
      if (p.name != name && std::abs(p.value - self->value) <= kSameValue * std::abs(self->value))
        here.candidates.push_back({p.name, shown_of(p)});
    }
    if (!here.candidates.empty()) found.push_back(std::move(here));
  }
  return found;
}

std::vector<NumberForSymbol> numbers_as_degrees(const std::string& typed) {
  const std::string s = sym::to_ascii(typed);
  std::vector<NumberForSymbol> found;
  for (std::size_t i = next_number(s, 0); i < s.size(); i = next_number(s, i)) {
    const std::size_t start = i;
    i = number_end(s, i);
    const std::string number = s.substr(start, i - start);
    std::size_t next = i;
    while (next < s.size() && s[next] == ' ') ++next;
    const bool marked = s.compare(next, 3, "deg") == 0;
    const double x = std::strtod(number.c_str(), nullptr);
    if (marked || significant_digits(number) < 2 ||
        number.find_first_of("eE") != std::string::npos || !(x > 0.0 && x <= 360.0))
      continue;
    found.push_back({number, {{"(" + number + "*pi/180)", number + "°"}}, false, start, i - start});
  }
  return found;
}

std::string with_symbols(const std::string& typed, const std::vector<NumberForSymbol>& numbers,
                         const std::vector<std::size_t>& choice) {
  std::string s = sym::to_ascii(typed);
  // From the last, so that the places before stay where they were.
  for (std::size_t k = numbers.size(); k-- > 0;) {
    const NumberForSymbol& n = numbers[k];
    if (choice.at(k) < n.candidates.size()) s.replace(n.at, n.length, n.candidates[choice[k]].name);
  }
  return s;
}

}  // namespace wobble::check
