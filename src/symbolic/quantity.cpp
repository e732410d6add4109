#include "symbolic/quantity.hpp"

#include <cctype>

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

GiNaC::ex parse_quantity(const SymbolTable& table, const std::string& text,
                         const std::string& field, const std::string& si_unit) {
  const std::string ascii = to_ascii(text);
  try {
    return table.parse(ascii, field);
  } catch (const InputError&) {
    const auto [value, unit] = split_value_unit(ascii);
    if (unit.empty()) {
      refuse_unknown_unit(table, ascii, field);
      throw;
    }
    // The value alone first: if it is no expression either ("q*m" with no parameter q), the
    // whole text's message stands.
    if (!reads(table, value, field)) throw;
    const Unit given = parse_unit(unit, field);
    const Unit wanted = si_unit.empty() ? Unit{} : parse_unit(si_unit, field);
    if (!unit_fits(given, wanted)) {
      const std::string must = wanted.angle ? "an angle (rad, deg or rev)"
                               : si_unit.empty()
                                   ? "a pure number"
                                   : "in " + si_unit + " (" + wanted.dimension_words() + ")";
      throw ExpressionError(field + ": '" + text + "' is in " + given.text + " (" +
                            given.dimension_words() + "); it must be " + must);
    }
    return table.parse("(" + value + ")*(" + given.to_si_exact + ")/(" + wanted.to_si_exact + ")",
                       field);
  }
}

}  // namespace wobble::sym
