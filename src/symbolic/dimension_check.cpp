#include "symbolic/dimension_check.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "core/characters.hpp"
#include "symbolic/canonical_print.hpp"
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

std::string dimension_text(const std::array<int, 3>& powers) {
  Unit unit;
  unit.dim = powers;
  return powers == std::array{0, 0, 0}
             ? "a pure number"
             : "in " + si_unit_text(unit) + " (" + unit.dimension_words() + ")";
}

// A quantity's value at the table's probe values, and as the sizes of the units change. Besides
// the table's symbols it knows three of its own, the units of mass, length and time (1 at the
// probe), by which a bare number in a sum is given its sibling terms' unit (unit_filled).
class Probe {
 public:
  Probe(const SymbolTable& table, Dimensions dims, std::string field)
      : table_(table), dims_(std::move(dims)), field_(std::move(field)) {}

  // `e` at the probe values with the units' sizes changed by `scale` (powers of kg, m, s).
  double value(const GiNaC::ex& e, const std::array<double, 3>& scale) const {
    Values scaled;
    for (const auto& [name, d] : dims_) {
      scaled[name] = d.probe;
      for (std::size_t k = 0; k < 3; ++k) scaled[name] *= std::pow(scale[k], d.powers[k]);
    }
    GiNaC::lst at = substitution(table_, scaled);
    for (std::size_t k = 0; k < 3; ++k) at.append(units_[k] == exact_value(scale[k]));
    return evaluate(e, at, field_);
  }

  // Whether `e` has the dimension `powers` as far as its value tells, with every unit's size
  // changed at once: one evaluation besides the probe's (which the solver takes too, at the
  // defaults). True where nothing can be told: no symbol, a value of zero or none there.
  bool scales_as(const GiNaC::ex& e, const std::array<int, 3>& powers) const {
    if (!names_a_symbol(table_, e)) return true;
    try {
      const double here = value(e, {1.0, 1.0, 1.0});
      if (here == 0.0) return true;
      double expected = here;
      for (std::size_t k = 0; k < 3; ++k) expected *= std::pow(kUnitScale[k], powers[k]);
      const double there = value(e, kUnitScale);
      return std::abs(there - expected) <= kScaleTolerance * std::abs(expected);
    } catch (const InputError&) {
      return true;  // asin(m/R) out of its domain once m and R scale apart
    }
  }

  // The dimension of `e`, powers of kg, m and s, from how its value at the probe values changes
  // as each unit's size does; nullopt where it has none to find: no symbol, a value of zero or
  // none there, a sum of unlike terms, or one with a number not given a unit (unit_filled).
  std::optional<std::array<int, 3>> dimension_of(const GiNaC::ex& e) const {
    if (!names_a_symbol(table_, e)) return std::nullopt;
    std::array<int, 3> powers{0, 0, 0};
    try {
      const double here = value(e, {1.0, 1.0, 1.0});
      if (here == 0.0) return std::nullopt;
      for (std::size_t k = 0; k < 3; ++k) {
        std::array<double, 3> one{1.0, 1.0, 1.0};
        one[k] = kUnitScale[k];
        const double ratio = value(e, one) / here;
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

  // `e` with each bare number in a sum multiplied by the unit of the sum's other terms, where
  // they agree on one (m*(1 + R): 1 is a metre's worth, in SI), so that the whole has a dimension
  // to tell. A number's unit is not written, and whatever the terms beside it are in, it is taken
  // to be in that. Where it is told, a term of a sum inside the quantity in a unit other than its
  // siblings', and a function's argument or an exponent with a unit, are refused at once
  // (`text` as written); the quantity's own sum is left to the caller, which names the term
  // against the field's unit.
  GiNaC::ex unit_filled(const GiNaC::ex& e, const std::string& text, bool top) const {
    if (!names_a_symbol(table_, e)) return e;
    if (GiNaC::is_a<GiNaC::add>(e)) return filled_sum(e, text, top);
    Operands operands(*this, text);
    const GiNaC::ex out = e.map(operands);
    if (GiNaC::is_a<GiNaC::function>(e)) refuse_argument_units(e, out, text);
    if (GiNaC::is_a<GiNaC::power>(e)) {
      const auto exponent = dimension_of(out.op(1));
      if (exponent && *exponent != std::array{0, 0, 0})
        refuse(text, "has an exponent, " + shown(e.op(1)) + ", " + dimension_text(*exponent) +
                         " by its parameters' units; an exponent must be a pure number");
    }
    return out;
  }

  // `e` as written: unit_filled's units of the numbers taken out again.
  GiNaC::ex without_units(const GiNaC::ex& e) const {
    return e.subs(GiNaC::lst{units_[0] == 1, units_[1] == 1, units_[2] == 1});
  }

  // A part of the quantity for a message, as the key prints it (m*(m + 1), the parameters in
  // their declared order, not GiNaC's).
  std::string shown(const GiNaC::ex& e) const { return printable(to_text(e, table_), 40); }

  [[noreturn]] void refuse(const std::string& text, const std::string& what) const {
    throw ExpressionError(field_ + ": '" + printable(text, 40) + "' " + what);
  }

 private:
  GiNaC::ex filled_sum(const GiNaC::ex& e, const std::string& text, bool top) const {
    GiNaC::exvector terms;
    std::optional<std::array<int, 3>> unit;  // the terms' one dimension, where they have one
    bool one = true;
    for (const GiNaC::ex& term : e) {
      terms.push_back(unit_filled(term, text, false));
      const auto found = dimension_of(terms.back());
      if (!found) continue;
      if (unit && *unit != *found) {
        if (top)
          one = false;
        else
          refuse(text, "has a sum, " + shown(e) + ", of terms " +
                           std::min(dimension_text(*unit), dimension_text(*found)) + " and " +
                           std::max(dimension_text(*unit), dimension_text(*found)) +
                           " by its parameters' units");  // GiNaC's order of terms varies
      }
      unit = found;
    }
    GiNaC::ex sum = 0;
    for (const GiNaC::ex& term : terms) {
      if (unit && one && !names_a_symbol(table_, term)) {
        GiNaC::ex u = 1;
        for (std::size_t k = 0; k < 3; ++k) u *= GiNaC::pow(units_[k], (*unit)[k]);
        sum += term * u;
      } else {
        sum += term;
      }
    }
    return sum;
  }

  // unit_filled of each operand, for GiNaC's map.
  struct Operands : GiNaC::map_function {
    Operands(const Probe& probe, const std::string& text) : probe_(probe), text_(text) {}
    GiNaC::ex operator()(const GiNaC::ex& operand) override {
      return probe_.unit_filled(operand, text_, false);
    }
    const Probe& probe_;
    const std::string& text_;
  };

  // abs(x) has x's unit, atan2(y, x) takes two of one unit; any other function a pure number.
  // `filled` is the call with its arguments unit_filled.
  void refuse_argument_units(const GiNaC::ex& call, const GiNaC::ex& filled,
                             const std::string& text) const {
    const std::string name = GiNaC::ex_to<GiNaC::function>(call).get_name();
    if (name == "abs") return;
    std::vector<std::optional<std::array<int, 3>>> dims;
    for (const GiNaC::ex& arg : filled) dims.push_back(dimension_of(arg));
    if (name == "atan2") {
      if (dims[0] && dims[1] && *dims[0] != *dims[1])
        refuse(text, "takes " + shown(call) + " of arguments " + dimension_text(*dims[0]) +
                         " and " + dimension_text(*dims[1]) + " by its parameters' units");
      return;
    }
    for (std::size_t i = 0; i < dims.size(); ++i) {
      if (dims[i] && *dims[i] != std::array{0, 0, 0})
        refuse(text, "takes " + shown(call) + " of " + shown(call.op(i)) + ", " +
                         dimension_text(*dims[i]) +
                         " by its parameters' units; its argument must be a pure number");
    }
  }

  const SymbolTable& table_;
  Dimensions dims_;
  std::string field_;
  std::array<GiNaC::symbol, 3> units_{GiNaC::symbol("unit_of_mass"),
                                      GiNaC::symbol("unit_of_length"),
                                      GiNaC::symbol("unit_of_time")};
};

// dimension_by_form, with the table's dimensions at hand. Where it finds one the probe would find
// the same (the value scales so, exactly), without evaluating the quantity four times at 40
// digits: that was a tenth of `wobble keys --check`.
std::optional<std::array<int, 3>> by_form(const SymbolTable& table, const Dimensions& dims,
                                          const GiNaC::ex& e) {
  using Powers = std::array<int, 3>;
  if (GiNaC::is_a<GiNaC::numeric>(e) || GiNaC::is_a<GiNaC::constant>(e)) return Powers{0, 0, 0};
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    for (const auto& [name, d] : dims)
      if (table.at(name).is_equal(e)) return d.powers;
    return std::nullopt;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    Powers sum{0, 0, 0};
    for (const GiNaC::ex& factor : e) {
      const auto d = by_form(table, dims, factor);
      if (!d) return std::nullopt;
      for (std::size_t k = 0; k < 3; ++k) sum[k] += (*d)[k];
    }
    return sum;
  }
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const auto base = by_form(table, dims, e.op(0));
    if (!base || !GiNaC::is_a<GiNaC::numeric>(e.op(1))) return std::nullopt;
    const GiNaC::numeric exponent = GiNaC::ex_to<GiNaC::numeric>(e.op(1));
    if (!exponent.is_rational()) return std::nullopt;
    Powers out{};
    for (std::size_t k = 0; k < 3; ++k) {
      const GiNaC::numeric power = exponent * (*base)[k];
      // Far past any unit's power (and int's range, which to_int() would leave undefined).
      constexpr int kLargestPower = 1000;
      if (!power.is_integer() || GiNaC::abs(power) > kLargestPower) return std::nullopt;
      out[k] = power.to_int();
    }
    return out;
  }
  if (GiNaC::is_a<GiNaC::add>(e)) {
    std::optional<Powers> one;
    for (const GiNaC::ex& term : e) {
      const auto d = by_form(table, dims, term);
      if (!d || !names_a_symbol(table, term) || (one && *one != *d)) return std::nullopt;
      one = d;
    }
    return one;
  }
  if (GiNaC::is_a<GiNaC::function>(e)) {
    std::vector<Powers> args;
    for (const GiNaC::ex& arg : e) {
      const auto d = by_form(table, dims, arg);
      if (!d) return std::nullopt;
      args.push_back(*d);
    }
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (name == "abs" && args.size() == 1) return args[0];
    if (name == "atan2" && args.size() == 2 && args[0] == args[1]) return Powers{0, 0, 0};
    if (std::all_of(args.begin(), args.end(), [](const Powers& d) { return d == Powers{}; }))
      return Powers{0, 0, 0};
  }
  return std::nullopt;
}
}  // namespace

std::optional<std::array<int, 3>> dimension_by_form(const SymbolTable& table, const GiNaC::ex& e) {
  const Dimensions dims = table.dimensions();
  if (dims.empty()) return std::nullopt;
  return by_form(table, dims, e);
}

void refuse_other_dimension(const SymbolTable& table, const GiNaC::ex& e, const std::string& text,
                            const std::string& field, const std::string& si_unit) {
  const Dimensions dims = table.dimensions();
  if (dims.empty()) return;
  const Unit wanted = si_unit.empty() ? Unit{} : parse_unit(si_unit, field);
  if (by_form(table, dims, e) == wanted.dim) return;
  // A file's quantity is read again for each variant and each solve of it (an export solves
  // hundreds): one that passed at these probe values passes again, unevaluated.
  std::ostringstream key;
  key.precision(17);
  key << si_unit << '|' << e;
  for (const auto& [name, d] : dims)
    key << '|' << name << d.powers[0] << ',' << d.powers[1] << ',' << d.powers[2] << '@' << d.probe;
  thread_local std::set<std::string> passed;
  if (passed.count(key.str()) != 0) return;
  const Probe probe(table, dims, field);
  if (probe.scales_as(e, wanted.dim)) {
    passed.insert(key.str());
    return;
  }
  const GiNaC::ex filled = probe.unit_filled(e, text, true);
  if (probe.scales_as(filled, wanted.dim)) {
    passed.insert(key.str());
    return;
  }
  const std::string must = unit_wanted_words(wanted, si_unit);
  const auto found = probe.dimension_of(filled);
  if (found && *found != wanted.dim)
    probe.refuse(text,
                 "is " + dimension_text(*found) + " by its parameters' units; it must be " + must);
  // Mixed: not told apart from m + 0.05. The terms named are the filled sum's, as judged.
  if (found || !GiNaC::is_a<GiNaC::add>(filled)) return;
  for (const GiNaC::ex& term : filled) {
    const auto term_found = probe.dimension_of(term);
    if (!term_found || *term_found == wanted.dim) continue;
    probe.refuse(text, "has a term, " + probe.shown(probe.without_units(term)) + ", " +
                           dimension_text(*term_found) + " by its parameters' units; it must be " +
                           must);
  }
}

}  // namespace wobble::sym
