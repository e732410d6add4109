#include <algorithm>

#include "check/latex_answer.hpp"
#include "cli/commands.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "problem/values.hpp"
#include "solvers/solve.hpp"

namespace wobble::cli {

std::vector<std::string> with_variant(const Problem& problem, std::optional<long> variant,
                                      const std::vector<std::string>& sets) {
  std::vector<std::string> plain = sets;
  if (!sets.empty()) {
    const sym::SymbolTable table = problem.symbol_table();
    for (auto& s : plain) {
      // Longer than --set reads: refused there, unread.
      if (s.size() <= kMaxSetLength) s = check::latex_assignment_as_text(s, table);
    }
  }
  require_each_set_once(problem, plain);
  std::vector<std::string> out;
  if (variant) out = variant_for(problem, *variant);
  out.insert(out.end(), plain.begin(), plain.end());
  return out;
}

Key solve_at(const Problem& problem, const sym::Values& values,
             const std::vector<std::string>& sets) {
  try {
    return solve(problem, values);
  } catch (const InputError& e) {
    if (sets.empty()) throw;
    std::string typed;
    for (const auto& s : sets) typed += (typed.empty() ? "" : ", ") + printable(s, 60);
    throw InputError(std::string(e.what()) + " (at --set " + typed + ")");
  }
}

std::pair<long, long> variant_range(const std::string& text, const std::string& option) {
  const auto dash = text.find('-');
  try {
    std::size_t used = 0;
    const long a = std::stol(text.substr(0, dash), &used);
    if (used != (dash == std::string::npos ? text.size() : dash)) throw std::invalid_argument("");
    const long b = dash == std::string::npos ? a : std::stol(text.substr(dash + 1), &used);
    if (dash != std::string::npos && used != text.size() - dash - 1)
      throw std::invalid_argument("");
    if (a < 1 || b < a || b - a >= 1000) throw std::invalid_argument("");
    return {a, b};
  } catch (const std::exception&) {
    throw InputError(option + ": '" + text + "' is not a range such as 1-40 (at most 1000)");
  }
}

std::vector<std::pair<std::string, std::string>> shown_values(
    const Problem& problem, const std::vector<std::string>& assignments) {
  std::vector<std::pair<std::string, std::string>> shown;
  for (const auto& text : assignments) {
    // By identifier, however the name was typed ("θ0" is theta0).
    const Assignment a = assignment_of(problem, text);
    shown.emplace_back(a.parameter.name, a.value);
  }
  // The last assignment of a parameter wins, as in parameter_values (a --set after a variant).
  std::reverse(shown.begin(), shown.end());
  return shown;
}

}  // namespace wobble::cli
