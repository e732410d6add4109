#pragma once
// A problem solved at its defaults, with its symbols, for judging answers against its key.
#include <stdexcept>
#include <string>
#include <vector>

#include "check/judge.hpp"
#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"

namespace wobble::test {

struct CheckFixture {
  Problem problem;
  sym::Values values;
  Key key;
  sym::SymbolTable table;
  /// At the defaults, or with `sets` as `--set` gives them ("theta0=90deg").
  explicit CheckFixture(const std::string& id, const std::vector<std::string>& sets = {})
      : problem(find_problem(id)),
        values(parameter_values(problem, sets)),
        key(solve(problem, values)),
        table(problem.symbol_table()) {}
  const Answer& answer(const std::string& name) const {
    for (const auto& p : key.parts) {
      for (const auto& a : p.answers) {
        if (a.name == name) return a;
      }
    }
    throw std::logic_error("no answer " + name);
  }
  check::Verdict check(const std::string& name, const std::string& text,
                       check::Options o = {}) const {
    return check::judge({key, table, values}, answer(name), text, o);
  }
};

}  // namespace wobble::test
