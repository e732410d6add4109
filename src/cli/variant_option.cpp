#include "cli/commands.hpp"
#include "problem/values.hpp"
#include "solvers/solve.hpp"

namespace wobble::cli {

std::vector<std::string> with_variant(const Problem& problem, std::optional<long> variant,
                                      const std::vector<std::string>& sets) {
  require_each_set_once(sets);
  std::vector<std::string> out;
  if (variant) out = variant_for(problem, *variant);
  out.insert(out.end(), sets.begin(), sets.end());
  return out;
}

std::vector<std::pair<std::string, std::string>> shown_values(
    const std::vector<std::string>& assignments) {
  std::vector<std::pair<std::string, std::string>> shown;
  for (const auto& a : assignments) {
    const auto eq = a.find('=');
    shown.emplace_back(a.substr(0, eq), a.substr(eq + 1));
  }
  return shown;
}

}  // namespace wobble::cli
