#include "problem/problem.hpp"

namespace wobble {

bool Interval::contains(double x) const {
  const bool above = lo_open ? x > lo : x >= lo;
  const bool below = hi_open ? x < hi : x <= hi;
  return above && below;
}

const Parameter& Problem::parameter(const std::string& name) const {
  std::string known;
  for (const auto& p : parameters) {
    if (p.name == name) return p;
    known += (known.empty() ? "" : ", ") + p.name;
  }
  throw InputError("unknown parameter '" + name + "' for problem " + id + " (known: " + known +
                   ")");
}

sym::SymbolTable Problem::symbol_table() const {
  sym::SymbolTable table;
  for (const auto& p : parameters) {
    const bool positive = p.range.lo > 0.0 || (p.range.lo == 0.0 && p.range.lo_open);
    table.declare(p.name, p.latex, positive ? sym::SymbolSign::positive : sym::SymbolSign::real);
  }
  return table;
}

const std::string& MotionSpec::at(const std::string& key) const {
  const auto it = exprs.find(key);
  if (it == exprs.end()) throw std::logic_error("motion: no key '" + key + "'");
  return it->second;
}

}  // namespace wobble
