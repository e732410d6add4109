#include "problem/problem.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble {

namespace {
std::string without(std::string s, const std::string& chars) {
  s.erase(std::remove_if(s.begin(), s.end(),
                         [&](char c) { return chars.find(c) != std::string::npos; }),
          s.end());
  return s;
}

// Whether `typed` spells p: a spelling is tried only when no parameter has it as its identifier
// (Problem::parameter), so "theta_0" cannot take another parameter's place.
bool spells(const Parameter& p, const std::string& typed) {
  const std::string ascii = sym::to_ascii(typed);
  if (ascii == p.name) return true;
  if (without(typed, "_") == p.name) return true;
  // "ω₁", "omega_1" for w1 whose LaTeX is \omega_1.
  if (!p.latex.empty() && without(ascii, "_ ") == sym::typed_spelling(p.latex)) return true;
  const std::string latex = without(typed, "$ ");
  return !p.latex.empty() && (latex == p.latex || without(latex, "{}") == without(p.latex, "{} "));
}
}  // namespace

bool Interval::contains(double x) const {
  const bool above = lo_open ? x > lo : x >= lo;
  const bool below = hi_open ? x < hi : x <= hi;
  return above && below;
}

const std::string& Problem::hint(const std::string& part_id) const {
  static const std::string none;
  for (const auto& spec : parts) {
    if (spec.id == part_id) return spec.hint;
  }
  return none;
}

const Parameter& Problem::parameter(const std::string& name) const {
  std::string known;
  for (const auto& p : parameters) {
    if (p.name == name) return p;
    known += (known.empty() ? "" : ", ") + p.name;
  }
  for (const auto& p : parameters) {
    if (spells(p, name)) return p;
  }
  // "of heavy-top": a scene's parameters are a problem's too (scene.hpp), so no kind is named.
  throw InputError("unknown parameter '" + name + "' of " + id + " (known: " + known + ")");
}

std::string tolerance_too_fine(double tolerance, const std::string& shown) {
  if (tolerance >= kMinRelativeTolerance) return "";
  return fmt::format(
      "{} is below {:g}, where the key's own answers, printed to ten significant digits, would "
      "be judged wrong",
      shown.empty() ? fmt::format("{:g}", tolerance) : shown, kMinRelativeTolerance);
}

sym::SymbolTable Problem::symbol_table() const {
  sym::SymbolTable table;
  for (const auto& p : parameters) {
    const bool positive = p.range.lo > 0.0 || (p.range.lo == 0.0 && p.range.lo_open);
    table.declare(p.name, p.latex, positive ? sym::SymbolSign::positive : sym::SymbolSign::real);
    // The unit was read when the file loaded (SI, toml_reader.cpp); the default is a value in
    // the parameter's range, where the file's expressions have values.
    const std::array<int, 3> powers =
        p.unit.empty() ? std::array<int, 3>{0, 0, 0} : parse_unit(p.unit, p.name).dim;
    table.set_dimension(p.name, {powers, p.default_value});
  }
  return table;
}

const std::string& MotionSpec::at(const std::string& key) const {
  const auto it = exprs.find(key);
  if (it == exprs.end()) throw std::logic_error("motion: no key '" + key + "'");
  return it->second;
}

}  // namespace wobble
