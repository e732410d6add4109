#include <fmt/format.h>

#include "cli/commands.hpp"
#include "solvers/catalog.hpp"
#include "problem/scene.hpp"
#include "render/solver_list.hpp"

namespace wobble::cli {

void setup_list(CLI::App& app, ListOptions& opt) {
  app.add_flag("--solvers", opt.solvers,
               "List the solvers instead: their [motion] keys and quantities (kind, frame, unit, "
               "meaning), the names a problem file's answers use");
  app.footer(
      "Problems are the files problems/ID.toml, scenes the files scenes/ID.toml, in the data "
      "folder: --data-dir, else $WOBBLE_PROBLEMS and $WOBBLE_SCENES (or $WOBBLE_DATA_DIR), else "
      "share/wobble next to the program, else the source tree.");
}

int run_list(const ListOptions& opt) {
  if (opt.solvers) {
    fmt::print("{}", solver_list_text(solver_registry()));
    return kExitOk;
  }
  const auto problems = load_catalog();
  std::size_t width = 0;
  for (const auto& p : problems) width = std::max(width, p.id.size());
  const auto scenes = load_scenes();
  for (const auto& s : scenes) width = std::max(width, s.model.id.size());
  fmt::print("problems (wobble solve ID):\n");
  for (const auto& p : problems) fmt::print("  {:<{}}  {}\n", p.id, width, p.title);
  fmt::print("scenes (wobble simulate ID):\n");
  for (const auto& s : scenes) fmt::print("  {:<{}}  {}\n", s.model.id, width, s.model.title);
  return kExitOk;
}

}  // namespace wobble::cli
