#include "symbolic/quantity.hpp"

#include <algorithm>
#include <cctype>
#include <utility>
#include <vector>

#include "core/characters.hpp"
#include "symbolic/dimension_check.hpp"
#include "symbolic/expression_guard.hpp"
#include "symbolic/glued_numbers.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble::sym {

namespace {
bool reads(const SymbolTable& table, const std::string& text, const std::string& field) {
  try {
    (void)table.parse(text, field);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// "2 parsecs": an expression and a word that is no unit; say so, not "undefined symbol". "2 R"
// with a parameter R is a product without its '*': the whole text's message says so.
void refuse_unknown_unit(const SymbolTable& table, const std::string& ascii,
                         const std::string& field) {
  const auto space = ascii.find_last_of(' ');
  if (space == std::string::npos) return;
  const std::string before = ascii.substr(0, space), tail = ascii.substr(space + 1);
  if (tail.empty() || !std::isalpha(static_cast<unsigned char>(tail[0]))) return;
  if (!reads(table, before, field) || reads(table, tail, field)) return;
  (void)parse_unit(tail, field);  // throws its error
}

bool name_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) || c == '_';
}
bool name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}
}  // namespace

// Said so, not "undefined symbol 'deg'"; with the value written where the unit multiplies all of
// it (not "90deg - alpha", alpha in rad).
void refuse_unit_inside(const SymbolTable& table, const std::string& ascii, const std::string& text,
                        const std::string& field, const std::string& si_unit) {
  std::string unit;
  std::vector<std::pair<std::size_t, std::size_t>> spans;  // each of its names: start, end
  for (std::size_t i = 0; i < ascii.size();) {
    const auto digit = [&](std::size_t k) {
      return k < ascii.size() && std::isdigit(static_cast<unsigned char>(ascii[k]));
    };
    if (digit(i) || ascii[i] == '.') {  // a number, with its exponent: "1e5" names nothing
      while (digit(i) || (i < ascii.size() && ascii[i] == '.')) ++i;
      const std::size_t sign = i + 1 < ascii.size() && (ascii[i + 1] == '+' || ascii[i + 1] == '-');
      if (i < ascii.size() && (ascii[i] == 'e' || ascii[i] == 'E') && digit(i + 1 + sign)) {
        i += 1 + sign;
        while (digit(i)) ++i;
      }
      continue;
    }
    if (!name_start(ascii[i])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < ascii.size() && name_char(ascii[j])) ++j;
    const std::string name = ascii.substr(i, j - i);
    if (!table.contains(name) && !is_function_name(name) && name != "pi" && name != "Pi") {
      if (!is_unit(name) || (!unit.empty() && name != unit)) return;
      unit = name;
      spans.emplace_back(i, j);
    }
    i = j;
  }
  if (unit.empty()) return;
  const std::string said = field + ": cannot read \"" + printable(text, 40) + "\": '" + unit +
                           "' is a unit inside the expression; a unit goes once, after the "
                           "whole value";
  // The unit as a symbol, written as a factor where it stands against a number or a bracket.
  SymbolTable with_unit = table;
  const GiNaC::ex u = with_unit.declare(unit, unit, SymbolSign::positive);
  std::string starred, stripped;
  std::size_t from = 0;
  for (const auto& [start, end] : spans) {
    std::size_t before = start;
    while (before > from && ascii[before - 1] == ' ') --before;
    const bool factor = before > 0 && (name_char(ascii[before - 1]) || ascii[before - 1] == ')');
    starred += ascii.substr(from, before - from) + (factor ? "*" : "") + unit;
    stripped += ascii.substr(from, before - from) + (factor ? "" : "1");
    from = end;
  }
  starred += ascii.substr(from);
  stripped += ascii.substr(from);
  // Each term divided by the unit is free of it, as GiNaC writes a product (no normal() or
  // expand(), which would multiply out (M + 2 kg)^150): a term that is not so is no multiple.
  bool whole = false;  // the unit multiplies all of it, and the value reads without it
  try {
    const GiNaC::ex e = with_unit.parse(starred, field);
    const auto multiple = [&](const GiNaC::ex& term) { return !(term / u).has(u); };
    whole = GiNaC::is_a<GiNaC::add>(e) ? std::all_of(e.begin(), e.end(), multiple) : multiple(e);
    (void)table.parse(stripped, field);
    whole = whole && unit_fits(parse_unit(unit, field),
                               si_unit.empty() ? Unit{} : parse_unit(si_unit, field));
  } catch (const InputError&) {  // not so written: said without it
  }
  // The value so written fits on the line, as the text does (40 characters).
  constexpr std::size_t kLongestShown = 60;
  whole = whole && stripped.size() <= kLongestShown;
  throw ExpressionError(said +
                        (whole ? ": \"(" + printable(stripped, kLongestShown) + ") " + unit + "\""
                               : " (\"(90 - 15) deg\")"));
}

std::string quantity_expression(const SymbolTable& table, const std::string& text,
                                const std::string& field, const std::string& si_unit) {
  const std::string ascii = numbers_times_constants(to_ascii(text));
  try {
    (void)table.parse(ascii, field);
    return ascii;
  } catch (const InputError&) {
    // The longest unit after a value that reads: "100*g cm/s^2" with a parameter g is 100 g
    // in cm/s^2. If no value reads ("q*m" with no parameter q), the whole text's message stands.
    const auto splits = value_unit_splits(ascii);
    if (splits.empty()) {
      refuse_unknown_unit(table, ascii, field);
      refuse_unit_inside(table, ascii, text, field, si_unit);
      throw;
    }
    const auto split = std::find_if(splits.begin(), splits.end(),
                                    [&](const auto& s) { return reads(table, s.first, field); });
    if (split == splits.end()) {
      refuse_unit_inside(table, ascii, text, field, si_unit);
      throw;
    }
    const auto& [value, unit] = *split;
    const Unit given = parse_unit(unit, field);
    const Unit wanted = si_unit.empty() ? Unit{} : parse_unit(si_unit, field);
    if (!unit_fits(given, wanted)) {
      const std::string must = unit_wanted_words(wanted, si_unit);
      // As the parser shows a text: 40 characters at most, no control character.
      throw ExpressionError(field + ": '" + printable(text, 40) + "' is in " +
                            printable(given.text, 40) + " (" + given.dimension_words() +
                            "); it must be " + must);
    }
    return "(" + value + ")*(" + given.to_si_exact + ")/(" + wanted.to_si_exact + ")";
  }
}

GiNaC::ex parse_quantity(const SymbolTable& table, const std::string& text,
                         const std::string& field, const std::string& si_unit) {
  GiNaC::ex e;
  try {  // most quantities are expressions: parsed once
    e = table.parse(numbers_times_constants(to_ascii(text)), field);
  } catch (const InputError&) {
    // a value with its unit, or an error that quantity_expression gives again, in its terms
    e = table.parse(quantity_expression(table, text, field, si_unit), field);
  }
  refuse_other_dimension(table, e, text, field, si_unit);
  return e;
}

}  // namespace wobble::sym
