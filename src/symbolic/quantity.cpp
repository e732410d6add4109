#include "symbolic/quantity.hpp"

#include <algorithm>
#include <cctype>

#include "core/characters.hpp"
#include "symbolic/dimension_check.hpp"
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
}  // namespace

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
      throw;
    }
    const auto split = std::find_if(splits.begin(), splits.end(),
                                    [&](const auto& s) { return reads(table, s.first, field); });
    if (split == splits.end()) throw;
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
