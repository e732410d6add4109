#include "symbolic/units.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "symbolic/unicode_notation.hpp"

namespace wobble {

namespace {
struct Named {
  double to_si;
  std::array<int, 3> dim;
  bool angle;
  std::string exact;  ///< to_si as a constant expression
};

// The units by name, in the order a message lists them.
const std::vector<std::pair<std::string, Named>>& units_in_order() {
  static const std::vector<std::pair<std::string, Named>> n{
      {"kg", {1.0, {1, 0, 0}, false, "1"}},
      {"g", {1e-3, {1, 0, 0}, false, "1/1000"}},
      {"m", {1.0, {0, 1, 0}, false, "1"}},
      {"cm", {1e-2, {0, 1, 0}, false, "1/100"}},
      {"mm", {1e-3, {0, 1, 0}, false, "1/1000"}},
      {"s", {1.0, {0, 0, 1}, false, "1"}},
      {"ms", {1e-3, {0, 0, 1}, false, "1/1000"}},
      {"min", {60.0, {0, 0, 1}, false, "60"}},
      {"h", {3600.0, {0, 0, 1}, false, "3600"}},
      // Days, as a key's notes print long periods (the Earth's wobble): 86400 s.
      {"day", {86400.0, {0, 0, 1}, false, "86400"}},
      // Weeks, 604800 s: a long period as people count it (Euler's period of the Earth, 43 weeks).
      {"week", {604800.0, {0, 0, 1}, false, "604800"}},
      // The sidereal day, one turn of the Earth against the stars (IERS: 86164.0905 s), as the
      // Earth's Euler period is counted in turns of its spin (about 304.5 sidereal days).
      {"sidereal day", {86164.0905, {0, 0, 1}, false, "861640905/10000"}},
      // The Julian year, 365.25 days, as astronomy's periods are given (the Chandler wobble).
      {"yr", {31557600.0, {0, 0, 1}, false, "31557600"}},
      {"rad", {1.0, {0, 0, 0}, true, "1"}},
      {"deg", {M_PI / 180, {0, 0, 0}, true, "pi/180"}},
      // Minutes and seconds of arc, as the Earth's wobble is measured (about 0.2 arcsec).
      {"arcmin", {M_PI / 10800, {0, 0, 0}, true, "pi/10800"}},
      {"arcsec", {M_PI / 648000, {0, 0, 0}, true, "pi/648000"}},
      {"rev", {2 * M_PI, {0, 0, 0}, true, "2*pi"}},
      {"J", {1.0, {1, 2, -2}, false, "1"}},
      {"N", {1.0, {1, 1, -2}, false, "1"}},
      {"Hz", {2 * M_PI, {0, 0, -1}, true, "2*pi"}},
      {"rpm", {2 * M_PI / 60, {0, 0, -1}, true, "2*pi/60"}},
      // Revolutions per second, as a motor's or a spinning wheel's rate is given.
      {"rps", {2 * M_PI, {0, 0, -1}, true, "2*pi"}},
  };
  return n;
}

const std::map<std::string, Named>& names() {
  static const std::map<std::string, Named> n(units_in_order().begin(), units_in_order().end());
  return n;
}

// "kJ", "mN", "km", "µs" (read as "mus"), "mrad", "kHz": an SI prefix on a unit that takes one,
// where the whole name is no unit of its own ("mm", "ms", "min" are). nullopt if it is none.
std::optional<Named> prefixed(const std::string& name) {
  struct Prefix {
    std::string letters;
    double factor;
    std::string exact;
  };
  static const std::array<Prefix, 7> kPrefixes{{{"G", 1e9, "10^9"},
                                                {"M", 1e6, "10^6"},
                                                {"k", 1e3, "10^3"},
                                                {"m", 1e-3, "10^(-3)"},
                                                {"mu", 1e-6, "10^(-6)"},
                                                {"u", 1e-6, "10^(-6)"},
                                                {"n", 1e-9, "10^(-9)"}}};
  static const std::array<std::string, 7> kTakesPrefix{"g", "m", "s", "J", "N", "Hz", "rad"};
  for (const auto& p : kPrefixes) {
    const std::string& letters = p.letters;
    if (name.size() <= letters.size() || name.compare(0, letters.size(), letters) != 0) continue;
    const std::string base = name.substr(letters.size());
    if (std::find(kTakesPrefix.begin(), kTakesPrefix.end(), base) == kTakesPrefix.end()) continue;
    // An angle is never given in kilo-, mega- or gigaradians: "Grad" is German for degrees (and
    // a calculator's gradians), "krad" and "Mrad" are doses of radiation.
    if (base == "rad" && p.factor > 1.0) continue;
    const Named& b = names().at(base);
    return Named{p.factor * b.to_si, b.dim, b.angle, "(" + p.exact + ")*(" + b.exact + ")"};
  }
  return std::nullopt;
}

// "kg, g, m, ...": every unit's name, for a message.
const std::string& unit_list() {
  static const std::string list = [] {
    std::string l;
    for (const auto& [name, unit] : units_in_order()) l += (l.empty() ? "" : ", ") + name;
    return l;
  }();
  return list;
}

// The names written out as students write them ("0.78 radians", "3 seconds"): each the unit it
// spells, plural or not.
const std::map<std::string, std::string>& spellings() {
  static const std::map<std::string, std::string> n{
      {"kilogram", "kg"},
      {"kilograms", "kg"},
      // The plural and capitals a hurried hand writes; none is another unit here (no kelvin).
      {"kgs", "kg"},
      {"Kg", "kg"},
      {"Kgs", "kg"},
      {"KG", "kg"},
      {"gram", "g"},
      {"grams", "g"},
      {"meter", "m"},
      {"meters", "m"},
      {"metre", "m"},
      {"metres", "m"},
      {"second", "s"},
      {"seconds", "s"},
      {"sec", "s"},
      {"secs", "s"},
      {"minute", "min"},
      {"minutes", "min"},
      {"mins", "min"},
      {"hour", "h"},
      {"hours", "h"},
      {"hr", "h"},
      {"hrs", "h"},
      {"radian", "rad"},
      {"radians", "rad"},
      {"rads", "rad"},
      {"degree", "deg"},
      {"degrees", "deg"},
      {"degs", "deg"},
      {"revolution", "rev"},
      {"revolutions", "rev"},
      {"revs", "rev"},
      {"turn", "rev"},  // ISO 80000-3's other name of the revolution
      {"turns", "rev"},
      {"cycle", "rev"},  // "cycles per second", as Hz is told
      {"cycles", "rev"},
      {"joule", "J"},
      {"joules", "J"},
      {"newton", "N"},
      {"newtons", "N"},
      {"RPM", "rpm"},
      {"RPS", "rps"},
      {"days", "day"},
      {"weeks", "week"},
      {"wk", "week"},
      {"wks", "week"},
      {"year", "yr"},
      {"years", "yr"},
      {"yrs", "yr"},
      {"arcminute", "arcmin"},
      {"arcminutes", "arcmin"},
      {"arcsecond", "arcsec"},
      {"arcseconds", "arcsec"},
  };
  return n;
}

// `word` as unit names, each with its power's digits after it, the shortest name first ("ms"
// -> "m s": "Nms" is a newton metre second more often than a newton millisecond); "" if none.
// Tried only on a short word: the splits of "mmmm..." grow as Fibonacci's numbers.
constexpr std::size_t kLongestRun = 16;
std::string names_in_a_row(const std::string& word) {
  for (std::size_t i = 1; i < word.size(); ++i) {
    std::size_t end = i;
    while (end < word.size() && std::isdigit(static_cast<unsigned char>(word[end]))) ++end;
    if (!names().count(word.substr(0, i))) continue;
    if (end == word.size()) return word;
    if (const std::string rest = names_in_a_row(word.substr(end)); !rest.empty())
      return word.substr(0, end) + " " + rest;
  }
  return names().count(word) ? word : "";
}
}  // namespace

std::string units_apart(const std::string& word) {
  if (word.size() > kLongestRun) return "";
  // One name, with its power's digits or not ("mm", "m2"), is itself.
  const std::size_t digits = word.find_last_not_of("0123456789") + 1;
  if (digits > 0 && names().count(word.substr(0, digits))) return word;
  return names_in_a_row(word);
}

bool units_run_together(const std::string& word) {
  return !units_apart(word).empty() && !is_unit(word);
}

std::string Unit::dimension_words() const {
  static const char* word[] = {"mass", "length", "time"};
  std::string num, den;
  for (int i = 0; i < 3; ++i) {
    if (dim[i] == 0) continue;
    std::string w = word[i];
    const int p = std::abs(dim[i]);
    if (p != 1) w += "^" + std::to_string(p);
    std::string& side = dim[i] > 0 ? num : den;
    side += (side.empty() ? "" : " × ") + w;
  }
  if (num.empty() && den.empty()) return angle ? "an angle" : "a pure number";
  if (num.empty()) num = "1";
  // In the key's notation, as its units are printed: "mass × length² / time".
  return sym::to_unicode(den.empty() ? num : num + " / " + den);
}

Unit parse_unit(const std::string& text, const std::string& field) {
  // "[kg m^2]", "(rad/s)": a unit in brackets, as a table's heading or the worksheet's prompt
  // writes it; one pair, around the whole unit.
  if (text.size() > 2 && ((text.front() == '[' && text.back() == ']') ||
                          (text.front() == '(' && text.back() == ')'))) {
    const std::string inner = text.substr(1, text.size() - 2);
    if (inner.find_first_of("[]()") == std::string::npos) return parse_unit(inner, field);
  }
  Unit u;
  u.text = text;
  const auto fail = [&](const std::string& why) -> Unit {
    throw InputError(
        // At most a line's worth of it: a long answer's tail may be taken for its unit.
        field + ": cannot read the unit '" + printable(text, 60) + "': " + why +
        " (units: " + unit_list() +
        "; SI prefixes G M k m µ n on g, m, s, J, N, Hz, and m µ n on rad; e.g. 'kg m^2', "
        "'rad/s')");
  };
  bool denominator = false, any = false, after_denominator = false;
  static const std::string kUnitAfterDivision = "a unit after each '/' or 'per'";
  // A '/' or "per" (`sign`): what follows is in the denominator. "m/s/s", as "metres per second
  // per second" is said: each after the first divides too (m/s² = m/(s s)), the only reading of
  // it. What is missing ("a unit before 'per'"), or "".
  const auto divide = [&](const std::string& sign) -> std::string {
    if (!any) return "a unit before " + sign;
    if (denominator && !after_denominator) return kUnitAfterDivision;
    denominator = true;
    after_denominator = false;
    return "";
  };
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == ' ' || c == '*') {
      ++i;
      continue;
    }
    // "kg.m^2/s", "kg-m^2/s": a dot or a hyphen between two units multiplies, as "kg m^2/s".
    if ((c == '.' || c == '-') && any && i + 1 < text.size() &&
        std::isalpha(static_cast<unsigned char>(text[i + 1]))) {
      ++i;
      continue;
    }
    // "1/s": a reciprocal unit (a growth rate).
    if (c == '1' && !any && !denominator &&
        text.find_first_not_of(' ', i + 1) != std::string::npos &&
        text[text.find_first_not_of(' ', i + 1)] == '/') {
      denominator = true;
      i = text.find_first_not_of(' ', i + 1) + 1;
      continue;
    }
    if (c == '/') {
      if (const std::string missing = divide("the '/'"); !missing.empty()) return fail(missing);
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && std::isalpha(static_cast<unsigned char>(text[j]))) ++j;
    if (j == i) {
      return fail("unexpected " + (static_cast<unsigned char>(c) < 0x80
                                       ? "'" + std::string(1, c) + "'"
                                       : character_name(text, i)));
    }
    std::string name = text.substr(i, j - i);
    // "sidereal days": two words, one unit.
    if (ascii_lower(name) == "sidereal") {
      std::size_t k = j;
      while (k < text.size() && text[k] == ' ') ++k;
      std::size_t end = k;
      while (end < text.size() && std::isalpha(static_cast<unsigned char>(text[end]))) ++end;
      const std::string day = ascii_lower(text.substr(k, end - k));
      if (k == j || (day != "day" && day != "days"))
        return fail("'sidereal' is read before day or days only");
      name = "sidereal day";
      j = end;
    }
    // "rads^-1", "rads⁻¹": rad s^-1, as written without its space; the plural "rads" takes no
    // power (1/rad is meant by no one who writes it so).
    if (name == "rads" && j < text.size() &&
        (text[j] == '^' || text[j] == '-' || std::isdigit(static_cast<unsigned char>(text[j])))) {
      name = "rad";
      --j;  // the s, with its power, is the next unit
    }
    if (name == "per") {  // "radians per second", "metres per second per second"
      if (!any && !denominator) {  // "4 per second", as "4/s" is said: a reciprocal unit
        denominator = true;
        i = j;
        continue;
      }
      if (const std::string missing = divide("'per'"); !missing.empty()) return fail(missing);
      i = j;
      continue;
    }
    // "Days", "SECONDS", "Rad": a word in capitals, as a sentence or a table's heading starts
    // it. Three letters or more, so that no prefixed symbol ("Ms", megaseconds) is read so.
    if (const std::string lower = ascii_lower(name);
        lower != name && lower.size() >= 3 && !names().count(name) && !prefixed(name) &&
        (names().count(lower) || spellings().count(lower)))
      name = lower;
    if (const auto spelled = spellings().find(name); spelled != spellings().end())
      name = spelled->second;
    const auto it = names().find(name);
    const std::optional<Named> with_prefix =
        it == names().end() ? prefixed(name) : std::optional<Named>{};
    if (it == names().end() && !with_prefix) {
      // "30 Grad", as German writes degrees; "grad" and "gon", a calculator's gradians.
      const std::string lower = ascii_lower(name);
      if (lower == "grad") {
        return fail("'" + name + "' is degrees in German and gradians (400 to a turn) on a " +
                    "calculator; write deg for degrees (gradians are not read)");
      }
      if (lower == "gon" || lower == "gons" || lower == "gradian" || lower == "gradians") {
        return fail("'" + name + "' is gradians (400 to a turn), which are not read; write deg " +
                    "or rad");
      }
      if (lower == "month" || lower == "months" || lower == "mo" || lower == "mos") {
        return fail(
            "a month has no one length (28 to 31 days); give the time in days, weeks or "
            "yr");
      }
      // The SI's symbol for the day, but a distance's name in problems (the molecule's bond d):
      // "2 d^2" would read as days squared where it is a length.
      if (name == "d") return fail("'d' is not read as days (problems name lengths d); write day or days");
      const std::string apart = units_apart(name);
      return fail("unknown unit '" + name + "'" +
                  (apart.empty() ? "" : " ('" + apart + "', with spaces?)"));
    }
    const Named& unit = with_prefix ? *with_prefix : it->second;
    int power = 1;
    if (j < text.size() && text[j] == '^') {
      // "s^-1", or "s^(-1)" as the answer reader writes a signed exponent (and "s⁻¹").
      std::size_t k = j + 1;
      const bool bracketed = k < text.size() && text[k] == '(';
      if (bracketed) ++k;
      const bool neg = k < text.size() && text[k] == '-';
      if (neg || (k < text.size() && text[k] == '+')) ++k;
      const std::size_t start = k;
      while (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) ++k;
      if (k == start || k - start > 2) return fail("a power must be a small whole number");
      power = std::stoi(text.substr(start, k - start)) * (neg ? -1 : 1);
      if (bracketed && (k >= text.size() || text[k++] != ')')) return fail("a ')' after the power");
      j = k;
    } else if (j < text.size() && (std::isdigit(static_cast<unsigned char>(text[j])) ||
                                   (text[j] == '-' && j + 1 < text.size() &&
                                    std::isdigit(static_cast<unsigned char>(text[j + 1]))))) {
      // "kg m2 s-1": the SI's powers without a caret, as a PDF's m² pastes.
      const bool neg = text[j] == '-';
      std::size_t k = neg ? j + 1 : j;
      const std::size_t start = k;
      while (k < text.size() && std::isdigit(static_cast<unsigned char>(text[k]))) ++k;
      if (k - start > 1) return fail("a power must be a small whole number");
      power = (text[start] - '0') * (neg ? -1 : 1);
      j = k;
    }
    if (denominator) {
      power = -power;
      after_denominator = true;
    }
    u.to_si *= std::pow(unit.to_si, power);
    if (unit.exact != "1") u.to_si_exact += "*(" + unit.exact + ")^(" + std::to_string(power) + ")";
    for (int d = 0; d < 3; ++d) u.dim[d] += unit.dim[d] * power;
    u.angle = u.angle || unit.angle;
    any = true;
    i = j;
  }
  if (!any) return fail("no unit");
  if (denominator && !after_denominator) return fail(kUnitAfterDivision);
  return u;
}

std::vector<std::pair<std::string, std::string>> value_unit_splits(const std::string& text) {
  const std::string t = trim(text);
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t k = 1; k < t.size(); ++k) {
    const auto c = static_cast<unsigned char>(t[k]), before = static_cast<unsigned char>(t[k - 1]);
    const bool word = std::isalpha(c) && !std::isalpha(before) && before != '_';
    const bool reciprocal_or_bracketed = (c == '1' || c == '[' || c == '(') && before == ' ';
    if (!word && !reciprocal_or_bracketed) continue;
    std::string value = trim(t.substr(0, k)), unit = trim(t.substr(k));
    if (!value.empty() && is_unit(unit)) out.emplace_back(std::move(value), std::move(unit));
  }
  return out;
}

std::pair<std::string, std::string> split_value_unit(const std::string& text) {
  auto splits = value_unit_splits(text);
  return splits.empty() ? std::pair{trim(text), std::string()} : std::move(splits.front());
}

bool unit_fits(const Unit& given, const Unit& wanted) {
  const bool angle_for_number = given.angle && !wanted.angle && wanted.dim == std::array{0, 0, 0};
  return given.same_dimension(wanted) && !angle_for_number;
}

std::string unit_wanted_words(const Unit& wanted, const std::string& si_unit) {
  if (wanted.dim != std::array{0, 0, 0})
    return "in " + si_unit + " (" + wanted.dimension_words() + ")";
  return wanted.angle ? "an angle (rad, deg or rev)" : "a pure number";
}

bool is_unit(const std::string& text) {
  try {
    (void)parse_unit(text, "");
    return true;
  } catch (const InputError&) {
    return false;
  }
}

namespace {
// A count of minutes or seconds of arc as written: 60 or more would carry into the place above,
// which no one writes; it is a slip, and 30°75′ could have meant 30°57′ or 31°15′.
void below_sixty(const std::string& count, const char* place, const std::string& field) {
  // from_chars, not stod: "." and a run of digits past double's range are not to throw here
  // (the reading after reports them), and no locale's decimal comma applies.
  double value = 0.0;
  const std::errc error = std::from_chars(count.data(), count.data() + count.size(), value).ec;
  if ((error == std::errc() && value >= 60) || error == std::errc::result_out_of_range) {
    const char* mark = place[0] == 'm' ? "′" : "″";
    throw InputError(field + ": " + count + mark +
                     " in an angle: a degree has 60 minutes of arc and a minute 60 seconds; "
                     "carry the " +
                     place + " over into the " + (place[0] == 'm' ? "degrees" : "minutes"));
  }
}
}  // namespace

std::string sexagesimal_degrees(const std::string& ascii, const std::string& field) {
  std::size_t i = 0;
  const auto spaces = [&] {
    while (i < ascii.size() && ascii[i] == ' ') ++i;
  };
  const auto number = [&]() -> std::string {
    spaces();
    const std::size_t start = i;
    while (i < ascii.size() && (is_digit(ascii[i]) || ascii[i] == '.')) ++i;
    return ascii.substr(start, i - start);
  };
  const auto mark = [&](std::initializer_list<const char*> marks) {
    spaces();
    for (const std::string m : marks) {
      if (ascii.compare(i, m.size(), m) == 0) {
        i += m.size();
        return true;
      }
    }
    return false;
  };
  spaces();
  const std::string sign = i < ascii.size() && (ascii[i] == '-' || ascii[i] == '+')
                               ? std::string(1, ascii[i++])
                               : std::string();
  const std::string degrees = number();
  if (degrees.empty() || !mark({"deg"})) return ascii;
  const std::string minutes = number();
  if (minutes.empty() || !mark({"arcmin", "'"})) return ascii;
  const std::string seconds = number();
  if (!seconds.empty() && !mark({"arcsec", "''", "\""})) return ascii;
  spaces();
  if (i != ascii.size()) return ascii;
  below_sixty(minutes, "minutes", field);
  if (!seconds.empty()) below_sixty(seconds, "seconds", field);
  return sign + "(" + degrees + " + " + minutes + "/60" +
         (seconds.empty() ? "" : " + " + seconds + "/3600") + ") deg";
}

std::string si_unit_text(const Unit& unit) {
  static const std::array<const char*, 3> names{"kg", "m", "s"};
  std::string text = unit.angle ? "rad" : "";
  for (std::size_t k = 0; k < 3; ++k) {
    if (unit.dim[k] == 0) continue;
    text += (text.empty() ? "" : " ") + std::string(names[k]) +
            (unit.dim[k] == 1 ? "" : "^" + std::to_string(unit.dim[k]));
  }
  return text;
}

std::string compound_quantity(const std::string& ascii) {
  std::size_t i = 0;
  const auto spaces = [&] {
    while (i < ascii.size() && ascii[i] == ' ') ++i;
  };
  const auto run = [&](auto accepts) {
    spaces();
    const std::size_t start = i;
    while (i < ascii.size() && accepts(ascii[i])) ++i;
    return ascii.substr(start, i - start);
  };
  spaces();
  const std::string sign = i < ascii.size() && (ascii[i] == '-' || ascii[i] == '+')
                               ? std::string(1, ascii[i++])
                               : std::string();
  std::vector<std::pair<std::string, Unit>> parts;
  while (true) {
    spaces();
    if (i >= ascii.size()) break;
    const std::string number = run([](char c) { return is_digit(c) || c == '.'; });
    const std::string name = run([](char c) { return is_letter(c); });
    if (number.empty() || name.empty() || !is_unit(name)) return ascii;
    const Unit unit = parse_unit(name, "");
    // One dimension, the largest first: "1 h 30 min", never "30 min 1 h", nor an angle's
    // parts (sexagesimal_degrees has those) or a unit per part of different kinds.
    if (unit.angle) return ascii;
    if (!parts.empty() &&
        (!unit.same_dimension(parts.back().second) || !(unit.to_si < parts.back().second.to_si))) {
      return ascii;
    }
    parts.emplace_back(number, unit);
  }
  if (parts.size() < 2) return ascii;
  std::string sum;
  for (const auto& [number, unit] : parts)
    sum += (sum.empty() ? "" : " + ") + number + "*(" + unit.to_si_exact + ")";
  return sign + "(" + sum + ") " + si_unit_text(parts.front().second);
}

}  // namespace wobble
