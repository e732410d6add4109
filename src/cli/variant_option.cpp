#include "cli/commands.hpp"
#include "problem/variants.hpp"

namespace wobble::cli {

std::vector<std::string> with_variant(const Problem& problem, std::optional<long> variant,
                                      const std::vector<std::string>& sets) {
  std::vector<std::string> out;
  if (variant) out = variant_assignments(problem, *variant);
  out.insert(out.end(), sets.begin(), sets.end());
  return out;
}

}  // namespace wobble::cli
