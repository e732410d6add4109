#include "solvers/named_mistakes.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <optional>

#include "core/input_error.hpp"
#include "problem/values.hpp"
#include "symbolic/unicode_notation.hpp"
#include "symbolic/units.hpp"

namespace wobble {
namespace {

// New sizes of the units of mass, length and time for the dimension test: no product of
// small powers of one is another's, so a wrong power of any shows.
constexpr std::array<double, 3> kUnitScale{1.7, 0.6, 2.3};
// The test's rounding: the expression is evaluated twice at 40 digits and rounded to double.
constexpr double kScaleTolerance = 1e-9;

// A unit's powers of kg, m, s; none for a pure number's "".
std::array<int, 3> dimension_of(const std::string& si_unit, const std::string& field) {
  return si_unit.empty() ? std::array<int, 3>{0, 0, 0} : parse_unit(si_unit, field).dim;
}

double scale_of(const std::array<int, 3>& dim) {
  double s = 1.0;
  for (std::size_t i = 0; i < dim.size(); ++i) s *= std::pow(kUnitScale[i], dim[i]);
  return s;
}

// Whether `e` has the dimension `dim`: with every parameter's value rescaled as its unit's
// dimension says, its value is rescaled by the same powers of kUnitScale. A sum of unlike terms
// or a function of a quantity with a unit (m + R, sin(omega)) is not.
bool scales_as(const GiNaC::ex& e, const Problem& problem, const sym::SymbolTable& table,
               const sym::Values& values, const std::array<int, 3>& dim, const std::string& field) {
  sym::Values scaled = values;
  for (const auto& p : problem.parameters)
    scaled.at(p.name) *= scale_of(dimension_of(p.unit, p.name));
  const double here = sym::evaluate(e, sym::substitution(table, values), field);
  try {
    const double there = sym::evaluate(e, sym::substitution(table, scaled), field);
    const double expected = here * scale_of(dim);
    return std::abs(there - expected) <= kScaleTolerance * std::abs(expected);
  } catch (const InputError&) {
    return false;  // asin(m/R): out of its domain once m and R scale apart
  }
}

bool names_a_parameter(const GiNaC::ex& e, const sym::SymbolTable& table) {
  for (const auto& name : table.names()) {
    if (e.has(table.at(name))) return true;
  }
  return false;
}

void require_dimension(const GiNaC::ex& e, const Problem& problem, const sym::SymbolTable& table,
                       const sym::Values& values, const Answer& answer, const MistakeSpec& m,
                       const std::string& field, const std::string& where) {
  if (scales_as(e, problem, table, values, dimension_of(answer.unit, answer.name), field + where))
    return;
  throw InputError(fmt::format(
      "{}: '{}' is not of {}'s dimension, {}: its value does not scale as the answer's when the "
      "units of mass, length and time do",
      field, m.value, answer.name,
      answer.unit.empty()
          ? "a pure number"
          : fmt::format("{} ({})", parse_unit(answer.unit, answer.name).dimension_words(),
                        answer.unit)));
}

// The mistake's value in the answer's unit (SI): an expression in the parameters at `values`,
// else a constant with its unit, read as a parameter's value is. An expression must have a value
// at the problem's defaults, where its dimension is tested, so that the key refuses a wrong one;
// at other values it may have none (m R²/α at α = 0): nullopt, nothing to name there. Its
// dimension is tested again where it is used, since a value of zero scales as anything
// (m² k at k = 0 by default would pass for a mass).
std::optional<double> mistake_value(const Problem& problem, const sym::Values& values,
                                    const Answer& answer, const MistakeSpec& m,
                                    const std::string& field) {
  const sym::SymbolTable table = problem.symbol_table();
  std::optional<GiNaC::ex> expression;
  try {
    expression = table.parse(sym::to_ascii(m.value), field);
  } catch (const InputError&) {
  }
  if (!expression || !names_a_parameter(*expression, table)) {
    Parameter as_answer;
    as_answer.name = answer.name;
    as_answer.unit = answer.unit;
    as_answer.range = parse_interval("(-inf, inf)", field);
    return parse_parameter_value(as_answer, m.value, field);
  }
  const sym::Values defaults = parameter_values(problem, {});
  require_dimension(*expression, problem, table, defaults, answer, m, field,
                    " (at the problem's defaults)");
  if (values == defaults)
    return sym::evaluate(*expression, sym::substitution(table, values), field);
  double value = 0.0;
  try {
    value = sym::evaluate(*expression, sym::substitution(table, values), field);
  } catch (const InputError&) {
    return std::nullopt;
  }
  if (value != 0.0) require_dimension(*expression, problem, table, values, answer, m, field, "");
  return value;
}

Answer* find_answer(Key& key, const std::string& name) {
  for (auto& part : key.parts) {
    for (auto& answer : part.answers) {
      if (answer.name == name) return &answer;
    }
  }
  return nullptr;
}

}  // namespace

void add_named_mistakes(const Problem& problem, const sym::Values& values, Key& key) {
  for (const auto& part : problem.parts) {
    for (const auto& spec : part.answers) {
      for (const auto& m : spec.mistakes) {
        Answer* answer = find_answer(key, spec.name);
        if (answer == nullptr) continue;  // none at these values: nothing to mistake it for
        const std::string field = problem.file.string() + ": " + m.field + ".value";
        if (answer->value.shape != Value::Shape::scalar) {
          throw InputError(
              fmt::format("{}: '{}' is a number, but {} is a {}; a named mistake is one number",
                          field, m.value, spec.name, shape_name(answer->value.shape)));
        }
        if (const auto value = mistake_value(problem, values, *answer, m, field))
          answer->approximations.push_back({m.what, m.remedy, {*value}, "the answer"});
      }
    }
  }
}

}  // namespace wobble
