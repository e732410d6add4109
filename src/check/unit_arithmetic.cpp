#include "check/unit_arithmetic.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string_view>
#include <utility>
#include <vector>

#include "check/answer_reading.hpp"
#include "check/brackets.hpp"
#include "check/latex_answer.hpp"
#include "check/latex_vocabulary.hpp"
#include "check/typed_text.hpp"
#include "check/written_forms.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "symbolic/expression_guard.hpp"
#include "symbolic/glued_numbers.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble::check {

namespace {

// A unit's stand-in in the text the reader reads: a name no problem or unit has.
constexpr std::string_view kStandIn = "wobbleunitstandin";

std::string stand_in(std::size_t k) {
  return fmt::format("{}{}", kStandIn, k);
}

// The largest power of a unit a worked-out answer may hold (kg m^2/s has 2): past it a text is
// no quantity of this course, and 2^p stays exact in the test below.
constexpr int kLargestPower = 12;

bool operand_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.';
}

// Where the operand after a '/' at `slash` ends, and whether it is a product written by
// juxtaposition ("303.6 day", not "(303.6 day)" nor "s^2"): at a '*', '/', ',' or a sign (not
// an exponent's) at its own depth, or a bracket that closes one it is inside.
std::pair<std::size_t, bool> denominator_end(const std::string& s, std::size_t slash) {
  int depth = 0;
  bool seen = false, gap = false, juxtaposed = false;
  std::size_t k = slash + 1;
  for (; k < s.size(); ++k) {
    const char c = s[k];
    if (c == '(' || c == '[') {
      juxtaposed = juxtaposed || (depth == 0 && seen && gap);
      ++depth;
      continue;
    }
    if (c == ')' || c == ']') {
      if (depth == 0) break;
      if (--depth == 0) seen = true, gap = false;
      continue;
    }
    if (depth > 0) continue;
    if (c == ' ') {
      gap = seen;
      continue;
    }
    if (c == '*' || c == '/' || c == ',') break;
    if (c == '^') {  // an exponent and its sign: "s^-1"
      if (k + 1 < s.size() && (s[k + 1] == '-' || s[k + 1] == '+')) ++k;
      gap = false;
      continue;
    }
    const bool exponent_sign = k > 1 && (s[k - 1] == 'e' || s[k - 1] == 'E') &&
                               std::isdigit(static_cast<unsigned char>(s[k - 2]));
    if ((c == '+' || c == '-') && seen && !exponent_sign) break;  // a sign first is the operand's
    juxtaposed = juxtaposed || (seen && gap);
    seen = true;
    gap = false;
  }
  return {k, juxtaposed};
}

// Whether the text before `slash` ends in a number written in digits, standing alone: the
// "1" of "1/2 kg".
bool number_before(const std::string& s, std::size_t slash) {
  if (slash == 0) return false;
  std::size_t k = s.find_last_not_of(' ', slash - 1);
  if (k == std::string::npos || !std::isdigit(static_cast<unsigned char>(s[k]))) return false;
  while (k > 0 && (std::isdigit(static_cast<unsigned char>(s[k - 1])) || s[k - 1] == '.')) --k;
  return k == 0 || !operand_char(s[k - 1]);
}

// "2 pi u0 / 303.6 u1" -> "2 pi u0 / (303.6 u1)": a product written by juxtaposition after a
// '/' is all of the denominator, as "J/kg K" is J/(kg K). With `after_numbers` false, not after
// a number in digits: "1/2 kg" as a half of a kilogram.
std::string denominators_grouped(const std::string& s, bool after_numbers) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    out += s[i];
    if (s[i] != '/' || (!after_numbers && number_before(s, i))) continue;
    const auto [end, juxtaposed] = denominator_end(s, i);
    const std::string operand = s.substr(i + 1, end - i - 1);
    if (juxtaposed) {
      const std::size_t first = operand.find_first_not_of(' ');
      const std::size_t last = operand.find_last_not_of(' ');
      out += operand.substr(0, first) + "(" + operand.substr(first, last - first + 1) + ")";
      if (last + 1 < operand.size()) out += ' ';
    } else {
      out += operand;
    }
    i = end - 1;
  }
  return out;
}

// Whether the name at ascii[at] follows a number: "0.12 m", "0.12m".
bool after_number(const std::string& ascii, std::size_t at) {
  const std::size_t before = ascii.find_last_not_of(' ', at == 0 ? 0 : at - 1);
  return at > 0 && before != std::string::npos &&
         (std::isdigit(static_cast<unsigned char>(ascii[before])) || ascii[before] == '.');
}

// The text with each unit's name written as its stand-in, and the units in order; nullopt where
// a name is a symbol of the problem (but one of `as_units` after a number) or no unit, or there
// is no unit. π and functions stay.
struct StandIns {
  std::string text;
  std::vector<Unit> units;
  std::vector<std::string> typed;
};
std::optional<StandIns> units_stood_in(const std::string& ascii, const sym::SymbolTable& table,
                                       const std::string& field,
                                       const std::vector<std::string>& as_units = {}) {
  StandIns out;
  std::size_t from = 0;
  const auto ids = identifiers(ascii);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const auto [at, length] = ids[k];
    std::size_t end = at + length;
    std::string word = ascii.substr(at, length);
    if (word == "pi" || sym::is_function_name(word)) continue;
    const bool as_unit = std::find(as_units.begin(), as_units.end(), word) != as_units.end() &&
                         after_number(ascii, at);
    if ((table.contains(word) && !as_unit) || word.starts_with(kStandIn)) return std::nullopt;
    // "sidereal days": one unit of two words.
    if (word == "sidereal" && k + 1 < ids.size()) {
      const auto [next, next_length] = ids[k + 1];
      const std::string day = ascii.substr(next, next_length);
      if ((day == "day" || day == "days") && ascii.find_first_not_of(' ', end) == next) {
        end = next + next_length;
        word = ascii.substr(at, end - at);
        ++k;
      }
    }
    if (!is_unit(word)) return std::nullopt;
    // "14 deg 59 arcmin", "15 h 303 days": a quantity told in parts, no product; the reader
    // says what is wrong with it.
    if (const std::size_t next = ascii.find_first_not_of(' ', end);
        next != std::string::npos && next > end &&
        (std::isdigit(static_cast<unsigned char>(ascii[next])) || ascii[next] == '.'))
      return std::nullopt;
    out.units.push_back(parse_unit(word, field));
    out.typed.push_back(word);
    out.text += ascii.substr(from, at - from);
    // Apart from a number glued before it or a name after it: "0.05m" is 0.05 times a metre.
    if (at > 0 && operand_char(ascii[at - 1])) out.text += ' ';
    out.text += stand_in(out.units.size() - 1);
    if (end < ascii.size() && operand_char(ascii[end])) out.text += ' ';
    from = end;
  }
  if (out.units.empty()) return std::nullopt;
  out.text += ascii.substr(from);
  return out;
}

// The SI unit of powers of kg, m and s: "kg m^2 s^-1", "" for none.
std::string si_unit(const std::array<int, 3>& dim) {
  constexpr std::array<const char*, 3> kNames{"kg", "m", "s"};
  std::string out;
  for (std::size_t i = 0; i < 3; ++i) {
    if (dim[i] == 0) continue;
    out += (out.empty() ? "" : " ") + std::string(kNames[i]);
    if (dim[i] != 1) out += fmt::format("^{}", dim[i]);
  }
  return out;
}

// `text` with each angle in degrees that degrees_in_expression wrote as radians, "(30*pi/180)",
// in degrees again: "sin(30°)", "cos(1°)" for "cos((1*pi/180))".
std::string degrees_shown(const std::string& text) {
  constexpr std::string_view kRadians = "*pi/180)";
  std::string out = text;
  for (std::size_t at = out.find(kRadians); at != std::string::npos; at = out.find(kRadians, at)) {
    const std::size_t open = out.rfind('(', at);
    const std::string number = open == std::string::npos ? "" : out.substr(open + 1, at - open - 1);
    if (number.empty() || number.find_first_not_of("0123456789.eE+-") != std::string::npos) {
      at += kRadians.size();
      continue;
    }
    // A function's own bracket ("sin(30*pi/180)" for "sin 30 deg") stays a bracket.
    const bool called = open > 0 && operand_char(out[open - 1]);
    const std::string degrees = called ? "(" + number + "°)" : number + "°";
    out.replace(open, at + kRadians.size() - open, degrees);
    at = open + degrees.size();
  }
  return out;
}

// `text` with its units' stand-ins written as the units typed.
std::string units_restored(const std::string& text, const StandIns& s) {
  std::string out = text;
  // The last first: stand_in(1) begins stand_in(10).
  for (std::size_t k = s.typed.size(); k-- > 0;) {
    const std::string name = stand_in(k);
    for (std::size_t at = out.find(name); at != std::string::npos; at = out.find(name, at))
      out.replace(at, name.size(), s.typed[k]);
  }
  return out;
}

// `text` without brackets about one number or name ("((1)/(day))", as LaTeX's \frac is set in
// text, as "1/day"; not a call's, "cos(x)") nor about all of it, and with a number times π as
// "2π" ("2*pi", from "2\pi"): how it was read, as it would be written.
std::string brackets_tidied(const std::string& text) {
  // A letter, digit or point; π and ° (UTF-8, bytes past ASCII) too.
  const auto atom_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '_' ||
           static_cast<unsigned char>(c) >= 0x80;
  };
  std::string out = text;
  for (std::size_t at = out.find("*pi"); at != std::string::npos; at = out.find("*pi", at + 1)) {
    const bool name_goes_on = at + 3 < out.size() && atom_char(out[at + 3]);
    if (at > 0 && std::isdigit(static_cast<unsigned char>(out[at - 1])) && !name_goes_on)
      out.replace(at, 3, "π");
  }
  for (std::size_t open = out.find('('); open != std::string::npos;) {
    const std::size_t close = out.find(')', open);
    if (close == std::string::npos) break;
    const bool atom = close > open + 1 &&
                      std::all_of(out.begin() + static_cast<std::ptrdiff_t>(open + 1),
                                  out.begin() + static_cast<std::ptrdiff_t>(close), atom_char);
    const bool call = open > 0 && atom_char(out[open - 1]) && out[open - 1] != '.';
    if (atom && !call) {
      out.erase(close, 1);
      out.erase(open, 1);
      open = out.rfind('(', open);  // "((1))": the bracket about it may hold one now
      if (open == std::string::npos) open = out.find('(');
    } else {
      open = out.find('(', open + 1);
    }
  }
  if (wrapped(out, '(')) out = out.substr(1, out.size() - 2);
  return out;
}

// The grouped text as typed, its units' names back and its degrees as degrees: "2 π rad
// /(303.6 days)", "cos(1°) * 2π rad / (303.6 days)".
std::string shown(const std::string& grouped, const StandIns& s) {
  std::string out = units_restored(brackets_tidied(degrees_shown(grouped)), s);
  std::string with_pi;
  const auto ids = identifiers(out);
  std::size_t from = 0;
  for (const auto& [at, length] : ids) {
    if (out.compare(at, length, "pi") != 0 || length != 2) continue;
    std::string before = out.substr(from, at - from);
    // "2 pi" as the reader sets it apart: 2π as typed.
    if (before.size() >= 2 && before.back() == ' ' &&
        std::isdigit(static_cast<unsigned char>(before[before.size() - 2])))
      before.pop_back();
    with_pi += before + "π";
    from = at + length;
  }
  return with_pi + out.substr(from);
}

// What an expression in the units' stand-ins works out to: its value in SI, and its powers
// of kg, m, s and of an angle; `one` false where it has no one power of some dimension (unlike
// quantities added, a unit's root, a function of a unit). nullopt where it has no finite real
// value, or a power past kLargestPower.
struct Dimension {
  double value_si = 0;
  std::array<int, 4> power{};
  bool one = true;
};
std::optional<Dimension> dimension_of(const GiNaC::ex& e, const std::vector<GiNaC::ex>& stand_ins,
                                      const std::vector<Unit>& units, const sym::SymbolTable& table,
                                      const std::string& field) {
  // Each unit its SI factor times powers of a mass, a length, a time and an angle (M, L, T, A:
  // a unit's name that counts an angle, rad, deg, rev, Hz, rpm, holds it once).
  const std::array<GiNaC::symbol, 4> axes{GiNaC::symbol("M"), GiNaC::symbol("L"),
                                          GiNaC::symbol("T"), GiNaC::symbol("A")};
  GiNaC::lst dimensioned;
  for (std::size_t k = 0; k < units.size(); ++k) {
    GiNaC::ex with_dimension = table.parse(units[k].to_si_exact, field);
    for (std::size_t i = 0; i < 3; ++i) with_dimension *= GiNaC::pow(axes[i], units[k].dim[i]);
    if (units[k].angle) with_dimension *= axes[3];
    dimensioned.append(stand_ins[k] == with_dimension);
  }
  const GiNaC::ex whole = e.subs(dimensioned);
  const auto at = [&](std::size_t axis, double x) -> std::optional<double> {
    GiNaC::lst point;
    for (std::size_t i = 0; i < axes.size(); ++i) point.append(axes[i] == (i == axis ? x : 1.0));
    const GiNaC::ex v = whole.subs(point).evalf();
    if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
      return std::nullopt;
    const double d = GiNaC::ex_to<GiNaC::numeric>(v).to_double();
    return std::isfinite(d) ? std::optional<double>(d) : std::nullopt;
  };
  Dimension out;
  const std::optional<double> value = at(0, 1);
  if (!value || *value == 0) return std::nullopt;
  out.value_si = *value;
  // The powers read off from the values at x = 2^20 and 3^13 along each axis: one power p gives
  // x^p at both (exactly, for |p| <= kLargestPower); a sum of unlike ones gives neither unless
  // one term outweighs the other by some 10^15. The tolerance is far above the rounding of a
  // few operations and far below a power's step.
  constexpr double kTwos = 20, kThrees = 13, kSameScaling = 1e-9;
  for (std::size_t axis = 0; axis < axes.size(); ++axis) {
    const std::optional<double> by_two = at(axis, std::exp2(kTwos));
    const std::optional<double> by_three = at(axis, std::pow(3.0, kThrees));
    // No value there (exp(1 m) overflows at 2^20 m): no one power of that dimension either.
    bool one_power = by_two && by_three;
    long whole_power = 0;
    if (one_power) {
      const double p = std::log2(*by_two / *value) / kTwos;
      whole_power = std::lround(p);
      const double scaled = std::pow(3.0, kThrees * static_cast<double>(whole_power));
      one_power = std::abs(p - static_cast<double>(whole_power)) < kSameScaling &&
                  std::abs(*by_three / *value - scaled) < kSameScaling * scaled;
    }
    // An angle is a pure number: "cos(0.5 rad)" is no angle, and no refusal.
    constexpr std::size_t kAngle = 3;
    if (!one_power && axis == kAngle) continue;
    if (!one_power) {
      out.one = false;
      return out;
    }
    if (std::abs(whole_power) > kLargestPower) return std::nullopt;
    out.power[axis] = static_cast<int>(whole_power);
  }
  return out;
}

// The unit a worked-out value is written in, from its powers of kg, m, s and an angle: the
// key's SI unit where it is of that dimension (rad/s as the key writes 1/s), else the SI unit
// of the powers; an angle left over in a pure number stays one (rad), as unit_fits requires.
std::string unit_written(const std::array<int, 4>& power, const std::string& key_unit) {
  const std::array<int, 3> dim{power[0], power[1], power[2]};
  if (!key_unit.empty()) {
    const Unit key = parse_unit(key_unit, "key unit");
    // rad/s for kg m²/s's 1/s is no matter (radians are pure numbers), but a pure number
    // with an angle left over is an angle.
    const bool pure = dim == std::array<int, 3>{0, 0, 0};
    if (key.to_si == 1.0 && key.dim == dim && (!pure || power[3] == 0 || key.angle))
      return key_unit;
  }
  const std::string si = si_unit(dim);
  return si.empty() && power[3] != 0 ? "rad" : si;
}

// `latex` with each upright d, \mathrm{d} or \text{d}, as \mathrm{day}, where the problem has
// no symbol d: the SI's day, as the LaTeX reader reads it after a value.
std::string upright_days(const std::string& latex, const sym::SymbolTable& table) {
  if (table.contains("d")) return latex;
  std::string out = latex;
  for (const std::string_view upright : {"\\mathrm{d}", "\\text{d}", "\\textrm{d}"}) {
    for (std::size_t at = out.find(upright); at != std::string::npos;
         at = out.find(upright, at + 1))
      out.replace(at, upright.size(), "\\mathrm{day}");
  }
  return out;
}

// A group set upright in LaTeX, "\\mathrm{rad/s}": where its '\\' is and its '}', the wrapper's
// name ("mathrm") and what is inside ("rad/s").
struct UprightGroup {
  std::size_t at = 0, close = 0;
  std::string wrapper, inside;
};
std::vector<UprightGroup> upright_groups(const std::string& latex) {
  std::vector<UprightGroup> out;
  for (std::size_t at = latex.find('\\'); at != std::string::npos; at = latex.find('\\', at + 1)) {
    std::size_t name_end = at + 1;
    while (name_end < latex.size() && std::isalpha(static_cast<unsigned char>(latex[name_end])))
      ++name_end;
    std::string wrapper = latex.substr(at + 1, name_end - at - 1);
    if (!text_wrappers().count(wrapper) || name_end >= latex.size() || latex[name_end] != '{')
      continue;
    const std::size_t close = latex.find('}', name_end);
    if (close == std::string::npos) break;
    out.push_back(
        {at, close, std::move(wrapper), latex.substr(name_end + 1, close - name_end - 1)});
    at = close;
  }
  return out;
}

// `table` with each unit set upright in `latex` (\mathrm{kg}, \text{days}, the words of
// \mathrm{rad/s}) declared as a name drawn so, where it is no symbol of the problem: the LaTeX
// reader takes an upright unit for the value's only at the end, and so reads "0.5\,\mathrm{kg}
// \cdot (0.05\,\mathrm{m})^2 \cdot 150\,\mathrm{rad/s}" as names, each a unit here.
sym::SymbolTable upright_units_named(const std::string& latex, const sym::SymbolTable& table) {
  sym::SymbolTable out = table;
  for (const UprightGroup& group : upright_groups(latex)) {
    for (const auto& [word_at, length] : identifiers(group.inside)) {
      const std::string word = group.inside.substr(word_at, length);
      if (is_unit(word) && !out.contains(word))
        out.declare(word, "\\mathrm{" + word + "}", sym::SymbolSign::positive);
    }
  }
  return out;
}

// `latex` with each unit set upright that divides ("\mathrm{rad/s}") as one upright word a
// piece ("\mathrm{rad}/\mathrm{s}"): where more follows, the LaTeX reader takes an upright group
// for one name ("rads"), not for the unit it takes after a value.
std::string upright_quotients_split(const std::string& latex) {
  std::string out;
  std::size_t from = 0;
  for (const UprightGroup& group : upright_groups(latex)) {
    if (group.inside.find('/') == std::string::npos) continue;
    const std::string opened = "\\" + group.wrapper + "{";
    std::string split;
    for (const char c : group.inside) split += c == '/' ? "}/" + opened : std::string(1, c);
    out += latex.substr(from, group.at - from) + opened + split + "}";
    from = group.close + 1;
  }
  return out + latex.substr(from);
}

}  // namespace

std::string latex_units_as_text(const std::string& typed, const sym::SymbolTable& table,
                                const std::string& field) {
  const std::string latex = upright_days(typed, table);
  try {
    return latex_as_text(latex, table, field);
  } catch (const InputError&) {
    const std::string split = upright_quotients_split(latex);
    return latex_as_text(split, upright_units_named(split, table), field);
  }
}

namespace {

// "0.5kg*(5cm)^2": each unit's name glued after a number set apart from it, "0.5 kg*(5 cm)^2",
// as identifiers() takes a number whole with what is glued to it. Not a problem's symbol (where
// m is a mass, "2m" is the reader's to decide) unless `symbols_too`; not an exponent ("2e5").
std::string units_apart(const std::string& ascii, const sym::SymbolTable& table, bool symbols_too) {
  const auto digit = [&](std::size_t i) {
    return i < ascii.size() && std::isdigit(static_cast<unsigned char>(ascii[i]));
  };
  std::string out;
  for (std::size_t i = 0; i < ascii.size();) {
    const bool in_name = i > 0 && (std::isalnum(static_cast<unsigned char>(ascii[i - 1])) ||
                                   ascii[i - 1] == '_' || ascii[i - 1] == '.');
    if (in_name || !(digit(i) || (ascii[i] == '.' && digit(i + 1)))) {
      out += ascii[i++];
      continue;
    }
    std::size_t end = i;
    while (digit(end) || (end < ascii.size() && ascii[end] == '.')) ++end;
    if (end < ascii.size() && sym::starts_exponent(ascii, end)) {
      end += (ascii[end + 1] == '+' || ascii[end + 1] == '-') ? 2 : 1;
      while (digit(end)) ++end;
    }
    out += ascii.substr(i, end - i);
    if (end < ascii.size() && std::isalpha(static_cast<unsigned char>(ascii[end]))) {
      const std::string name = sym::name_at(ascii, end);
      if (is_unit(name) && (symbols_too || !table.contains(name))) out += ' ';
    }
    i = end;
  }
  return out;
}

// The answer as the reader reads it for its units ("sin 30°", "cos(1 deg)" with degrees in
// radians first, d after a number as the day where d is no symbol, a unit glued to a number set
// apart: units_apart); LaTeX set as text (latex_units_as_text). @throws InputError where the
// reader refuses it so.
std::string units_read_text(const std::string& typed, const sym::SymbolTable& table,
                            const std::string& field, bool symbols_too = false) {
  const std::string text =
      looks_like_latex(typed) ? latex_units_as_text(typed, table, field) : typed;
  const auto in_expression = [&](const std::string& name) {
    return (table.contains(name) || sym::is_function_name(name)) && !table.contains("deg");
  };
  const auto is_symbol = [&](const std::string& name) { return table.contains(name); };
  return units_apart(
      days_written_d(degrees_in_expression(prepared(text, field), in_expression), is_symbol), table,
      symbols_too);
}

// Whether a worked-out unit ("" for a pure number) is of the key's dimension.
bool same_dimension(const std::string& unit, const std::string& key_unit) {
  return parse_unit(unit.empty() ? "1" : unit, "unit").dim == parse_unit(key_unit, "key unit").dim;
}

// `typed` as units_read_text reads it, with its units stood in (units_stood_in); nullopt where
// the reader refuses it so, or it is not so.
std::optional<StandIns> typed_stood_in(const std::string& typed, const sym::SymbolTable& table,
                                       const std::string& field,
                                       const std::vector<std::string>& as_units = {}) {
  std::string ascii;
  try {
    ascii = units_read_text(typed, table, field, !as_units.empty());
  } catch (const InputError&) {
    return std::nullopt;
  }
  return units_stood_in(ascii, table, field, as_units);
}

// The problem's symbols that are also units' names and follow a number in `typed`: the flying
// plate's m (its mass) in "(0.2 kg)(0.12 m)²/4", written as the metre.
std::vector<std::string> symbols_after_numbers(const std::string& typed,
                                               const sym::SymbolTable& table,
                                               const std::string& field) {
  std::string ascii;
  try {
    ascii = units_read_text(typed, table, field, /*symbols_too=*/true);
  } catch (const InputError&) {
    return {};
  }
  std::vector<std::string> out;
  for (const auto& [at, length] : identifiers(ascii)) {
    const std::string word = ascii.substr(at, length);
    if (table.contains(word) && is_unit(word) && after_number(ascii, at) &&
        std::find(out.begin(), out.end(), word) == out.end())
      out.push_back(word);
  }
  return out;
}

// `table` with the units' stand-ins declared, each a positive name.
sym::SymbolTable with_stand_ins(const sym::SymbolTable& table, const StandIns& stood) {
  sym::SymbolTable out = table;
  for (std::size_t k = 0; k < stood.units.size(); ++k)
    out.declare(stand_in(k), stand_in(k), sym::SymbolSign::positive);
  return out;
}

// Why `e` has no one dimension: where it is a sum of terms each of one, the units they are in
// ("it adds unlike quantities: J and a pure number", a unit left off a term); else what may
// make it so.
std::string why_not_one(const GiNaC::ex& e, const std::vector<GiNaC::ex>& stand_ins,
                        const std::vector<Unit>& units, const sym::SymbolTable& table,
                        const std::string& field, const std::string& key_unit) {
  const std::string unknown =
      "it adds unlike quantities, or takes a root of a unit or a function of one";
  if (!GiNaC::is_a<GiNaC::add>(e)) return unknown;
  std::vector<std::string> seen;
  for (const auto& term : e) {
    const std::optional<Dimension> d = dimension_of(term, stand_ins, units, table, field);
    if (!d || !d->one) return unknown;
    const std::string unit = unit_written(d->power, key_unit);
    const std::string said = unit.empty() ? "a pure number" : sym::to_unicode(unit);
    if (std::find(seen.begin(), seen.end(), said) == seen.end()) seen.push_back(said);
  }
  if (seen.size() < 2) return unknown;
  // In an order of their own (a sum's terms come in GiNaC's, which may change from run to run):
  // the answer's unit first, a pure number last, with what it most often is.
  const std::string kPure = "a pure number";
  const bool pure = std::erase(seen, kPure) != 0;
  const std::string answers = sym::to_unicode(key_unit);
  std::sort(seen.begin(), seen.end(), [&](const std::string& x, const std::string& y) {
    return std::make_pair(x != answers, x) < std::make_pair(y != answers, y);
  });
  if (pure) seen.push_back(kPure);
  const std::string last = seen.back();
  seen.pop_back();
  return fmt::format("it adds unlike quantities: {} and {}{}", fmt::join(seen, ", "), last,
                     pure ? " (a number without its unit?)" : "");
}

// `text`, with its units' stand-ins, worked out (units_worked_out, below).
std::optional<UnitsWorkedOut> worked_out(const std::string& text, const StandIns& stood,
                                         const sym::SymbolTable& table, const std::string& field,
                                         const std::string& key_unit) {
  const sym::SymbolTable with_units = with_stand_ins(table, stood);
  std::vector<GiNaC::ex> symbols;
  for (std::size_t k = 0; k < stood.units.size(); ++k)
    symbols.push_back(with_units.at(stand_in(k)));
  GiNaC::ex e;
  try {
    const ReadAnswer read = read_answer(text, with_units, field);
    if (read.unit || read.value.is_vector || read.value.is_matrix) return std::nullopt;
    e = read.value.entries.at(0);
  } catch (const InputError&) {
    return std::nullopt;
  }
  const std::string as_read = printable(shown(text, stood), kQuotedCharacters);
  const std::optional<Dimension> dimension = dimension_of(e, symbols, stood.units, table, field);
  if (!dimension) return std::nullopt;
  if (!dimension->one) {
    throw InputError(fmt::format("{}: \"{}\" does not work out to one unit: {}", field,
                                 sym::to_unicode(as_read),  // as the line of one that does
                                 why_not_one(e, symbols, stood.units, table, field, key_unit)));
  }
  UnitsWorkedOut out;
  out.grouped = as_read;
  out.unit = unit_written(dimension->power, key_unit);
  out.value_si = dimension->value_si;
  out.text = fmt::format("{:.17g}{}{}", out.value_si, out.unit.empty() ? "" : " ", out.unit);
  return out;
}

}  // namespace

namespace {
// units_worked_out with `as_units` read as units after a number (units_stood_in).
std::optional<UnitsWorkedOut> read_worked_out(const std::string& typed,
                                              const sym::SymbolTable& table,
                                              const std::string& field, const std::string& key_unit,
                                              const std::vector<std::string>& as_units) {
  const std::optional<StandIns> stood = typed_stood_in(typed, table, field, as_units);
  if (!stood) return std::nullopt;
  // A symbol is read as a unit only beside a unit that is no symbol: "2m" alone is two masses
  // or two metres, and refused.
  if (!as_units.empty() &&
      std::all_of(stood->typed.begin(), stood->typed.end(), [&](const auto& w) {
        return std::find(as_units.begin(), as_units.end(), w) != as_units.end();
      }))
    return std::nullopt;
  const std::string grouped = denominators_grouped(stood->text, true);
  std::optional<UnitsWorkedOut> out = worked_out(grouped, *stood, table, field, key_unit);
  // "1/2 kg × (0.05 m)² × 150/s": a half of a kilogram, not 1/(2 kg), where only that reading
  // has the answer's dimension; the line shows which reading was taken.
  const std::string fraction = denominators_grouped(stood->text, false);
  if (out && !key_unit.empty() && fraction != grouped && !same_dimension(out->unit, key_unit)) {
    try {
      if (auto coefficient = worked_out(fraction, *stood, table, field, key_unit);
          coefficient && same_dimension(coefficient->unit, key_unit))
        out = std::move(coefficient);
    } catch (const InputError&) {
      // the grouped reading stands
    }
  }
  return out;
}
}  // namespace

std::optional<UnitsWorkedOut> units_worked_out(const std::string& typed,
                                               const sym::SymbolTable& table,
                                               const std::string& field,
                                               const std::string& key_unit) {
  // "\frac{2\pi\,\mathrm{rad}}{303.6\,\mathrm{days}}", "2π/(303.6 d)".
  std::optional<UnitsWorkedOut> out;
  std::optional<InputError> refused;
  try {
    out = read_worked_out(typed, table, field, key_unit, {});
  } catch (const InputError& e) {
    refused = e;
  }
  // "(0.2 kg)(0.12 m)²/4", "0.2kg*(0.12m)^2/4" where m is the problem's mass: beside a unit
  // that is no symbol, a symbol that names a unit after a number is read as that unit where
  // the text reads no other way, or only that reading gives the answer's dimension (a symbol is
  // otherwise never a unit here), and the line says so.
  if (!key_unit.empty() && (!out || !same_dimension(out->unit, key_unit))) {
    if (const auto as_units = symbols_after_numbers(typed, table, field); !as_units.empty()) {
      try {
        if (auto as_read = read_worked_out(typed, table, field, key_unit, as_units);
            as_read && (!out || same_dimension(as_read->unit, key_unit))) {
          as_read->symbols_as_units = as_units;
          return as_read;
        }
      } catch (const InputError&) {
        // the symbols' reading stands, or its refusal
      }
    }
  }
  if (refused) throw *refused;
  return out;
}

std::string name_beside_units(const std::string& typed, const sym::SymbolTable& table,
                              const std::string& field) {
  if (looks_like_latex(typed)) return "";
  std::string ascii;
  try {
    ascii = units_read_text(typed, table, field);
  } catch (const InputError&) {
    return "";
  }
  std::string other;
  bool unit = false;
  const auto ids = identifiers(ascii);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const std::string word = ascii.substr(ids[k].first, ids[k].second);
    if (word == "pi" || sym::is_function_name(word) || table.contains(word)) continue;
    // "kgm" in "0.09375 kgm^2/s" is units run together (the unit reader says so), not a name.
    if (is_unit(word) || units_run_together(word) || (word == "sidereal" && k + 1 < ids.size())) {
      unit = true;
    } else if (other.empty()) {
      other = word;
    }
  }
  return unit ? other : "";
}

std::optional<std::string> units_refusal(const std::string& typed, const sym::SymbolTable& table,
                                         const std::string& field) {
  if (looks_like_latex(typed)) return std::nullopt;
  const std::optional<StandIns> stood = typed_stood_in(typed, table, field);
  if (!stood) return std::nullopt;
  try {
    (void)read_answer(stood->text, with_stand_ins(table, *stood), field);
  } catch (const InputError& e) {
    std::string restored = units_restored(e.what(), *stood);
    // The text it quotes is the answer as typed (the reader quotes its own reading in part,
    // the stand-ins' length taking the room, and may cut one short).
    const std::size_t open = restored.find('"');
    const std::size_t close = open == std::string::npos ? open : restored.find("\": ", open + 1);
    if (close != std::string::npos)
      restored.replace(open + 1, close - open - 1, printable(typed, kQuotedCharacters));
    if (restored.find(kStandIn.substr(0, 6)) == std::string::npos) return restored;
  }
  return std::nullopt;
}

std::optional<EntriesWorkedOut> entries_worked_out(const std::string& typed,
                                                   const sym::SymbolTable& table,
                                                   const std::string& field,
                                                   const std::string& key_unit) {
  if (looks_like_latex(typed)) return std::nullopt;
  const ListItems list = list_items(trim(typed));
  if (!list.bracketed || list.items.size() < 2) return std::nullopt;
  EntriesWorkedOut out;
  std::vector<std::string> entries;
  for (std::size_t i = 0; i < list.items.size(); ++i) {
    const std::string& entry = list.items[i];
    const std::string entry_field = fmt::format("{}[{}]", field, i);
    // An entry that reads as it is ("0.5 rad/s", "0") stays as typed.
    bool reads = true;
    try {
      (void)read_answer(entry, table, entry_field);
    } catch (const InputError&) {
      reads = false;
    }
    const auto worked =
        reads ? std::nullopt : units_worked_out(entry, table, entry_field, key_unit);
    entries.push_back(worked ? worked->text : entry);
    if (worked) out.worked.emplace_back(i, *worked);
  }
  if (out.worked.empty()) return std::nullopt;
  out.text = fmt::format("({})", fmt::join(entries, ", "));
  return out;
}

}  // namespace wobble::check
