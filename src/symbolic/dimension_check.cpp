#include "symbolic/dimension_check.hpp"

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "core/characters.hpp"
#include "symbolic/units.hpp"

namespace wobble::sym {

namespace {
using Dimensions = std::map<std::string, SymbolTable::Dimension>;

// New sizes of the units of mass, length and time for the dimension test: no product of small
// powers of one is another's, so a wrong power of any shows when all three change at once, and
// when one changes at a time, a quantity of one dimension changes by an integer power of it.
constexpr std::array<double, 3> kUnitScale{1.7, 0.6, 2.3};
// How near the test's ratios must be: the values are evaluated at 40 digits and rounded to
// double, so a true power is within a few eps of its own; a sum of unlike terms, m + R, is far
// off.
constexpr double kScaleTolerance = 1e-9;

// Whether `e` names a symbol: a constant (2*pi, a value with its unit) has no dimension to tell,
// as its unit is not written.
bool names_a_symbol(const SymbolTable& table, const GiNaC::ex& e) {
  for (const auto& name : table.names()) {
    if (e.has(table.at(name))) return true;
  }
  return false;
}

Values probe_values(const Dimensions& dims) {
  Values probe;
  for (const auto& [name, d] : dims) probe[name] = d.probe;
  return probe;
}

// `e` at the probe values with the units' sizes changed by `scale` (powers of kg, m, s).
double scaled_value(const SymbolTable& table, const GiNaC::ex& e, const Dimensions& dims,
                    const std::array<double, 3>& scale, const std::string& field) {
  Values scaled = probe_values(dims);
  for (const auto& [name, d] : dims) {
    for (std::size_t k = 0; k < 3; ++k) scaled[name] *= std::pow(scale[k], d.powers[k]);
  }
  return evaluate(e, substitution(table, scaled), field);
}

// Whether `e` has the dimension `powers` as far as its value tells, with every unit's size
// changed at once: one evaluation besides the probe's (which the solver takes too, at the
// defaults). True where nothing can be told: no symbol, a value of zero or none there.
bool scales_as(const SymbolTable& table, const Dimensions& dims, const GiNaC::ex& e,
               const std::array<int, 3>& powers, const std::string& field) {
  if (!names_a_symbol(table, e)) return true;
  try {
    const double here = evaluate(e, substitution(table, probe_values(dims)), field);
    if (here == 0.0) return true;
    double expected = here;
    for (std::size_t k = 0; k < 3; ++k) expected *= std::pow(kUnitScale[k], powers[k]);
    const double there = scaled_value(table, e, dims, kUnitScale, field);
    return std::abs(there - expected) <= kScaleTolerance * std::abs(expected);
  } catch (const InputError&) {
    return true;  // asin(m/R) out of its domain once m and R scale apart
  }
}

// The dimension of `e`, powers of kg, m and s, from how its value at the symbols' probe values
// changes as each unit's size does; nullopt where it has none to find: no symbol, a value of
// zero or none there, a sum of unlike terms, or one with a number (m + 0.05, a mass in kg and a
// grams' worth: a number's unit is not written, so the sum is not refused).
std::optional<std::array<int, 3>> dimension_of(const SymbolTable& table, const Dimensions& dims,
                                               const GiNaC::ex& e, const std::string& field) {
  if (!names_a_symbol(table, e)) return std::nullopt;
  std::array<int, 3> powers{0, 0, 0};
  try {
    const double here = evaluate(e, substitution(table, probe_values(dims)), field);
    if (here == 0.0) return std::nullopt;
    for (std::size_t k = 0; k < 3; ++k) {
      std::array<double, 3> one{1.0, 1.0, 1.0};
      one[k] = kUnitScale[k];
      const double ratio = scaled_value(table, e, dims, one, field) / here;
      const double power = std::log(ratio) / std::log(kUnitScale[k]);
      if (!(ratio > 0.0) || std::abs(power - std::round(power)) > kScaleTolerance)
        return std::nullopt;
      powers[k] = static_cast<int>(std::lround(power));
    }
  } catch (const InputError&) {
    return std::nullopt;
  }
  return powers;
}

std::string dimension_text(const std::array<int, 3>& powers) {
  Unit unit;
  unit.dim = powers;
  return powers == std::array{0, 0, 0}
             ? "a pure number"
             : "in " + si_unit_text(unit) + " (" + unit.dimension_words() + ")";
}

}  // namespace

void refuse_other_dimension(const SymbolTable& table, const GiNaC::ex& e, const std::string& text,
                            const std::string& field, const std::string& si_unit) {
  const Dimensions dims = table.dimensions();
  if (dims.empty()) return;
  const Unit wanted = si_unit.empty() ? Unit{} : parse_unit(si_unit, field);
  // A file's quantity is read again for each variant and each solve of it (an export solves
  // hundreds): one that passed at these probe values passes again, unevaluated.
  std::ostringstream key;
  key.precision(17);
  key << si_unit << '|' << e;
  for (const auto& [name, d] : dims)
    key << '|' << name << d.powers[0] << ',' << d.powers[1] << ',' << d.powers[2] << '@' << d.probe;
  thread_local std::set<std::string> passed;
  if (passed.count(key.str()) != 0) return;
  if (scales_as(table, dims, e, wanted.dim, field)) {
    passed.insert(key.str());
    return;
  }
  const std::string must = wanted.dim == std::array{0, 0, 0}
                               ? "a pure number" + std::string(wanted.angle ? " (an angle)" : "")
                               : "in " + si_unit + " (" + wanted.dimension_words() + ")";
  const auto found = dimension_of(table, dims, e, field);
  if (found && *found != wanted.dim) {
    throw ExpressionError(field + ": '" + printable(text, 40) + "' is " + dimension_text(*found) +
                          " by its parameters' units; it must be " + must);
  }
  if (found || !GiNaC::is_a<GiNaC::add>(e)) return;  // mixed: not told apart from m + 0.05
  for (const GiNaC::ex& term : e) {
    const auto term_found = dimension_of(table, dims, term, field);
    if (!term_found || *term_found == wanted.dim) continue;
    std::ostringstream term_text;
    term_text << term;
    throw ExpressionError(field + ": '" + printable(text, 40) + "' has a term, " +
                          printable(term_text.str(), 40) + ", " + dimension_text(*term_found) +
                          " by its parameters' units; it must be " + must);
  }
}

}  // namespace wobble::sym
