#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include <filesystem>

#include "cli/commands.hpp"
#include "core/input_error.hpp"
#include "core/work_budget.hpp"
#include "export/gradescope.hpp"
#include "export/graded_variants.hpp"
#include "export/moodle.hpp"
#include "export/prairielearn.hpp"
#include "io/atomic_write.hpp"
#include "on_demand/on_demand.hpp"
#include "solvers/catalog.hpp"

namespace wobble::cli {

namespace {
namespace fs = std::filesystem;

void add_common(CLI::App& sub, ExportOptions& opt, bool several) {
  // One problem where the system takes one is checked after parsing (single_problem): with
  // CLI11's expected(1), "-o quiz.xml" would leave quiz.xml as a second problem, and the message
  // ("At Most 1 required but received 2") would hide the unknown option.
  sub.add_option("problem", opt.problems,
                 several ? "Problem ids (see `wobble list`) or .toml files"
                         : "Problem id (see `wobble list`) or a .toml file")
      ->required();
  sub.add_flag("--force", opt.force, "Replace files that exist");
  sub.add_option("--tolerance", opt.tolerance,
                 "Relative tolerance of every answer, 0.02 or 2% (default: the problem's, else "
                 "0.01)")
      ->transform(fraction_or_percent());
}

void add_variants(CLI::App& sub, ExportOptions& opt, const std::string& fallback) {
  sub.add_option("--variants", opt.variants,
                 "Variant numbers to draw, e.g. " + fallback +
                     " (an ungradable one is replaced by the next number)")
      ->default_str(fallback);
}

// A file the export would replace without --force, or that is no regular file, refused: before
// the work (drawing a hundred variants takes seconds) and again when writing.
void refuse_to_replace_any(const std::vector<fs::path>& paths, bool force) {
  for (const auto& path : paths) {
    refuse_to_replace("--out", path, force);
    require_regular_or_absent(path);
  }
}

// Files written all or nothing, none replaced without --force.
void write_files(const std::vector<std::pair<fs::path, std::string>>& files, bool force) {
  std::vector<fs::path> paths;
  for (const auto& file : files) paths.push_back(file.first);
  refuse_to_replace_any(paths, force);
  for (const auto& [path, content] : files) {
    if (!path.parent_path().empty()) fs::create_directories(path.parent_path());
  }
  StagedFiles set(/*replace=*/force);
  for (const auto& [path, content] : files) set.stage(path, content);
  throw_if_interrupted();
  set.commit();
}

// How many variants were exported, and the rejected draws grouped by reason.
void print_report(const Problem& p, const exports::VariantSet& set, long first) {
  const long last = set.variants.back().number;
  fmt::print("{}: {} variant{} (numbers {} to {}), {} draw{} rejected{}\n", p.id,
             set.variants.size(), set.variants.size() == 1 ? "" : "s", first, last,
             set.rejected.size(), set.rejected.size() == 1 ? "" : "s",
             set.rejected.empty() ? "" : ":");
  std::vector<std::pair<std::string, std::vector<long>>> kinds;
  for (const auto& r : set.rejected) {
    auto it = std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.first == r.kind; });
    if (it == kinds.end()) it = kinds.insert(kinds.end(), {r.kind, {}});
    it->second.push_back(r.number);
  }
  for (const auto& u : set.untold) {
    fmt::print("  no variant refused for: {} (in {} of the first {} variants drawn)\n", u.kind,
               u.within, u.drawn);
  }
  for (const auto& [kind, numbers] : kinds) {
    fmt::print("  {}: {} (variant{} {})\n", numbers.size(), kind, numbers.size() == 1 ? "" : "s",
               fmt::join(numbers, ", "));
  }
}

std::pair<long, long> range(const ExportOptions& opt, const std::string& fallback) {
  return variant_range(opt.variants.empty() ? fallback : opt.variants, "--variants");
}

exports::VariantSet draw(const Problem& p, const ExportOptions& opt, const std::string& fallback,
                         const check::Options& judge_opt) {
  const auto [first, last] = range(opt, fallback);
  return exports::graded_variants(p, first, last - first + 1, judge_opt);
}

Problem single_problem(const ExportOptions& opt) {
  if (opt.problems.size() != 1) {
    throw InputError(fmt::format("problem: give one problem, not {}", opt.problems.size()));
  }
  return find_problem(opt.problems.front());
}

const std::string kPrairieLearnVariants = "1-200", kMoodleVariants = "1-100";

int export_prairielearn(const ExportOptions& opt, const check::Options& judge_opt) {
  const fs::path out = opt.out;
  // Question folders are created with it; a quiz's or an autograder's folder must exist, as for
  // every file wobble writes (a mistyped folder is no new one). Either is found before the work,
  // which for a hundred variants takes seconds.
  require_folder_can_be_made(out, "--out");
  std::vector<Problem> problems;
  std::vector<fs::path> targets;
  for (const auto& id : opt.problems) {
    problems.push_back(find_problem(id));
    for (const char* name : exports::kPrairieLearnFiles)
      targets.push_back(out / problems.back().id / name);
  }
  refuse_to_replace_any(targets, opt.force);
  std::vector<std::pair<fs::path, std::string>> files;
  std::vector<std::pair<Problem, exports::VariantSet>> done;
  for (const auto& p : problems) {
    auto set = draw(p, opt, kPrairieLearnVariants, judge_opt);
    for (auto& f : exports::prairielearn_question(p, set, judge_opt)) {
      files.emplace_back(out / p.id / f.path, std::move(f.content));
    }
    done.emplace_back(p, std::move(set));
  }
  write_files(files, opt.force);
  const long first = range(opt, kPrairieLearnVariants).first;
  for (const auto& [p, set] : done) print_report(p, set, first);
  fmt::print("wrote {} question folder{} in {}\n", done.size(), done.size() == 1 ? "" : "s",
             out.string());
  return kExitOk;
}

int export_moodle(const ExportOptions& opt, const check::Options& judge_opt) {
  const Problem p = single_problem(opt);
  refuse_to_replace_any({opt.out}, opt.force);
  require_writable(opt.out);
  const auto set = draw(p, opt, kMoodleVariants, judge_opt);
  const auto quiz = exports::moodle_quiz(p, set, judge_opt);
  write_files({{opt.out, quiz.xml}}, opt.force);
  print_report(p, set, range(opt, kMoodleVariants).first);
  for (const auto& l : quiz.left_out) fmt::print("left out: {}\n", l);
  fmt::print("wrote {} questions to {}\n", quiz.questions, opt.out);
  return kExitOk;
}

int export_gradescope(const ExportOptions& opt) {
  const Problem p = single_problem(opt);
  refuse_to_replace_any({opt.out}, opt.force);
  require_writable(opt.out);
  const std::string check_options =
      opt.tolerance ? fmt::format("--tolerance {}", *opt.tolerance) : std::string();
  const auto files = exports::gradescope_autograder(p, opt.deb, check_options);
  write_files({{opt.out, on_demand::load().zip_archive(files)}}, opt.force);
  fmt::print("wrote {} ({} files: setup.sh, run_autograder, {}.toml and {})\n", opt.out,
             files.size(), p.id, fs::path(opt.deb).filename().string());
  return kExitOk;
}
}  // namespace

ExportCommands setup_export(CLI::App& app, ExportOptions& opt) {
  app.require_subcommand(1);
  ExportCommands c;
  c.prairielearn = app.add_subcommand(
      "prairielearn", "A PrairieLearn question folder per problem, graded by wobble's rules");
  add_common(*c.prairielearn, opt, true);
  add_variants(*c.prairielearn, opt, kPrairieLearnVariants);
  c.prairielearn
      ->add_option("--out", opt.out, "Folder for the questions (ID/ inside it; created if missing)")
      ->required();
  c.prairielearn->add_option("--sigfigs", opt.sigfigs,
                             "Grade by N significant figures instead of a tolerance");
  c.moodle = app.add_subcommand("moodle", "A Moodle XML quiz of calculated questions");
  add_common(*c.moodle, opt, false);
  add_variants(*c.moodle, opt, kMoodleVariants);
  c.moodle->add_option("--out", opt.out, "The quiz file (quiz.xml), in a folder that exists")
      ->required();
  c.gradescope = app.add_subcommand(
      "gradescope", "A Gradescope autograder zip grading answer files with `wobble check`");
  add_common(*c.gradescope, opt, false);
  c.gradescope->add_option("--out", opt.out, "The autograder zip, in a folder that exists")
      ->required();
  c.gradescope->add_option("--deb", opt.deb, "The wobble Debian package it installs")
      ->required();
  return c;
}

int run_export(const ExportCommands& c, const ExportOptions& opt) {
  const check::Options judge_opt = judge_options(opt.tolerance, opt.sigfigs);
  if (c.prairielearn->parsed()) return export_prairielearn(opt, judge_opt);
  if (c.moodle->parsed()) return export_moodle(opt, judge_opt);
  return export_gradescope(opt);
}

}  // namespace wobble::cli
