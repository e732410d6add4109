#pragma once
/// @file
/// A solver's quantities as a table: each row its registry entry (name, unit, kind, frame, sign,
/// description) and the small function that computes it from the solver's context. The solver
/// builds its SolverInfo from the rows, and computes an answer by looking its row up, so the
/// registry and the computation cannot drift apart.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "solvers/key.hpp"
#include "solvers/registry.hpp"

namespace wobble {

/// The units a registered unit allows: itself, or its alternatives ("rad/s or 1/s": a rate that
/// is a frequency or a growth rate, by the values).
inline std::vector<std::string> unit_alternatives(const std::string& registered) {
  std::vector<std::string> out;
  const std::string sep = " or ";
  for (std::size_t from = 0;;) {
    const std::size_t to = registered.find(sep, from);
    out.push_back(registered.substr(from, to == std::string::npos ? to : to - from));
    if (to == std::string::npos) return out;
    from = to + sep.size();
  }
}

/// Whether `unit` is the registered one, or one of its alternatives.
inline bool registered_unit(const std::string& registered, const std::string& unit) {
  const auto units = unit_alternatives(registered);
  return std::find(units.begin(), units.end(), unit) != units.end();
}

template <class Context>
struct QuantityRow {
  QuantityInfo info;
  /// Computes the answer; gets the quantity's name (one function may serve a pair of rows).
  Computed (*compute)(Context& context, const std::string& quantity);
};

/// The registry entries of `rows`.
template <class Context>
std::vector<QuantityInfo> quantity_infos(const std::vector<QuantityRow<Context>>& rows) {
  std::vector<QuantityInfo> out;
  for (const auto& r : rows) out.push_back(r.info);
  return out;
}

/// Computes `quantity` by its row and stamps the row's kind, frame, sign and unit (as asked: with
/// its alternatives) on the answer.
/// @throws std::logic_error for a quantity without a row (the loader refuses those, so this is a
///         bug), an answer whose unit is not the row's, or names for entries it does not have.
template <class Context>
Computed compute_quantity(const std::vector<QuantityRow<Context>>& rows, Context& context,
                          const std::string& quantity) {
  for (const auto& r : rows) {
    if (r.info.name != quantity) continue;
    Computed c = r.compute(context, quantity);
    if (!c.exists) {
      // Asked for all the same ("none" is its answer): in its unit, as where it exists.
      c.answer.asked_unit = r.info.unit;
      return c;
    }
    if (!registered_unit(r.info.unit, c.answer.unit)) {
      throw std::logic_error(quantity + ": computed in '" + c.answer.unit + "', registered in '" +
                             r.info.unit + "'");
    }
    if (!c.answer.named_entries.empty() &&
        c.answer.named_entries.size() != c.answer.value.data.size()) {
      throw std::logic_error(quantity + ": names for " +
                             std::to_string(c.answer.named_entries.size()) + " entries, has " +
                             std::to_string(c.answer.value.data.size()));
    }
    c.answer.quantity = quantity;
    c.answer.kind = r.info.kind;
    c.answer.frame = r.info.frame;
    c.answer.sign = r.info.sign;
    c.answer.asked_unit = r.info.unit;
    return c;
  }
  throw std::logic_error("no quantity row for '" + quantity + "'");
}

}  // namespace wobble
