#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "cli/commands.hpp"
#include "core/work_budget.hpp"
#include "keys/golden.hpp"
#include "solvers/catalog.hpp"
#include "problem/values.hpp"
#include "problem/variants.hpp"
#include "io/atomic_write.hpp"
#include "render/render.hpp"
#include "solvers/solve.hpp"

namespace wobble::cli {

void setup_keys(CLI::App& app, KeysOptions& opt) {
  auto* check = app.add_flag("--check", opt.check,
                             "Recompute every key and compare with solutions/ (exit 1 on any "
                             "difference)");
  auto* update = app.add_flag("--update", opt.update, "Rewrite solutions/ from the program");
  auto* variants = app.add_option("--variants", opt.variants,
                                  "Write one key per variant, e.g. 1-40 (with --out DIR)");
  app.add_option("--out", opt.out, "Folder for --variants")->needs(variants);
  app.add_flag("--force", opt.force, "Overwrite existing files in --out")->needs(variants);
  app.add_option("--problem", opt.problems,
                 "Only this problem (an id from `wobble list`, or a problem file); repeatable")
      ->needs(variants)
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  check->excludes(update);
  check->excludes(variants);
  update->excludes(variants);
  // One of --check, --update, --variants: run_keys says so in words (CLI11's own group message
  // reads "Between 1 and 3 of the follow options are required").
  app.footer(
      "Give one of --check (compare solutions/ with the program), --update (rewrite solutions/)\n"
      "or --variants A-B --out DIR [--problem ID]... (a key per student's variant).\n"
      "$WOBBLE_SOLUTIONS overrides the solutions/ folder.");
}

namespace {
int write_variants(const KeysOptions& opt, const std::vector<Problem>& problems) {
  if (opt.out.empty()) throw InputError("--variants: give the folder with --out DIR");
  const auto [first, last] = variant_range(opt.variants, "--variants");
  const std::filesystem::path dir = opt.out;
  require_folder_can_be_made(dir, "--out");
  // Refuse before writing anything, so a refusal leaves the folder as it was.
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  for (const auto& p : problems) {
    for (long n = first; n <= last; ++n) {
      throw_if_interrupted();
      Key key = solve(p, parameter_values(p, variant_for(p, n)));
      key.variant = n;
      const std::string stem = fmt::format("{}-v{}", p.id, n);
      files.emplace_back(dir / (stem + ".md"), render(key, Format::markdown));
      files.emplace_back(dir / (stem + ".json"), render(key, Format::json));
    }
  }
  for (const auto& [path, content] : files) refuse_to_replace("--out", path, opt.force);
  std::filesystem::create_directories(dir);
  // All or nothing: every file is staged before any is put in place, and without --force none
  // replaces a file another run put there meanwhile.
  StagedFiles set(/*replace=*/opt.force);
  for (const auto& [path, content] : files) set.stage(path, content);
  throw_if_interrupted();
  set.commit();
  fmt::print("wrote {} files (variants {} to {} of {} problem{}) to {}\n", files.size(), first,
             last, problems.size(), problems.size() == 1 ? "" : "s", dir.string());
  return kExitOk;
}
// The problems --problem names, each an id from the catalog or a problem file anywhere (as for
// `solve`), each once: one named twice is one; two files of one id would share the keys' names.
std::vector<Problem> chosen_problems(const std::vector<std::string>& named) {
  std::vector<Problem> chosen;
  for (const auto& id_or_file : named) {
    Problem p = [&] {
      try {
        return find_problem(id_or_file);
      } catch (const InputError& e) {
        const std::string what = e.what();
        // An unknown id names the option; a file's own errors name the file and its field.
        if (what.rfind("unknown problem", 0) == 0) throw InputError("--problem: " + what);
        throw;
      }
    }();
    std::error_code ec;
    const auto same =
        std::find_if(chosen.begin(), chosen.end(), [&](const Problem& q) { return q.id == p.id; });
    if (same == chosen.end()) {
      chosen.push_back(std::move(p));
    } else if (!std::filesystem::equivalent(same->file, p.file, ec)) {
      throw InputError(fmt::format(
          "--problem: '{}' and '{}' are both problem '{}'; their keys would share file names",
          same->file.string(), p.file.string(), p.id));
    }
  }
  return chosen;
}

}  // namespace

int run_keys(const KeysOptions& opt) {
  const auto problems = opt.problems.empty() ? load_catalog() : chosen_problems(opt.problems);
  if (!opt.variants.empty()) return write_variants(opt, problems);
  if (!opt.check && !opt.update) throw InputError("keys: give --check, --update or --variants");
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
