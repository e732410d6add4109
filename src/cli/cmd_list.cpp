#include <fmt/format.h>

#include "cli/commands.hpp"
#include "problem/load.hpp"

namespace wobble::cli {

void setup_list(CLI::App& app, ListOptions&) {
  app.footer("Problems are the files problems/ID.toml ($WOBBLE_PROBLEMS overrides the folder).");
}

int run_list(const ListOptions&) {
  const auto problems = load_catalog();
  std::size_t width = 0;
  for (const auto& p : problems) width = std::max(width, p.id.size());
  for (const auto& p : problems) fmt::print("{:<{}}  {}\n", p.id, width, p.title);
  return kExitOk;
}

}  // namespace wobble::cli
