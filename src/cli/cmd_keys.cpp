#include <fmt/format.h>

#include "cli/commands.hpp"
#include "keys/golden.hpp"
#include "problem/load.hpp"

namespace wobble::cli {

void setup_keys(CLI::App& app, KeysOptions& opt) {
  auto* check = app.add_flag("--check", opt.check,
                             "Recompute every key and compare with solutions/ (exit 1 on any "
                             "difference)");
  auto* update = app.add_flag("--update", opt.update, "Rewrite solutions/ from the program");
  check->excludes(update);
  app.require_option(1);
  app.footer("$WOBBLE_SOLUTIONS overrides the solutions/ folder.");
}

int run_keys(const KeysOptions& opt) {
  const auto problems = load_catalog();
  const auto dir = solutions_dir();
  if (opt.update) {
    const auto changed = update_keys(problems, dir);
    for (const auto& f : changed) fmt::print("wrote {}\n", f);
    fmt::print("{} keys, {} files changed\n", problems.size(), changed.size());
    return kExitOk;
  }
  const auto differences = check_keys(problems, dir);
  for (const auto& d : differences) fmt::print("{}\n", d);
  if (!differences.empty()) {
    fmt::print("keys: {} difference(s); review them, then run `wobble keys --update`\n",
               differences.size());
    return kExitDifference;
  }
  fmt::print("keys: all {} keys match {}\n", problems.size(), dir.string());
  return kExitOk;
}

}  // namespace wobble::cli
