#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <optional>

#include "cli/commands.hpp"
#include "cli/terminal_width.hpp"
#include "core/word_wrap.hpp"
#include "io/atomic_write.hpp"
#include "problem/values.hpp"
#include "render/figure.hpp"
#include "render/handout.hpp"
#include "render/render.hpp"
#include "render/simulation_output.hpp"
#include "simulate/cross_check.hpp"
#include "solvers/catalog.hpp"
#include "solvers/registry.hpp"
#include "solvers/solve.hpp"

namespace wobble::cli {

void setup_solve(CLI::App& app, SolveOptions& opt) {
  app.add_option("problem", opt.problem, "Problem id (see `wobble list`) or a .toml file")
      ->required();
  app.add_option("--set", opt.sets,
                 "Parameter value NAME=VALUE, in SI or with a unit (R=5 cm, theta0=30deg, as a key "
                 "prints it); repeatable")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--format", opt.format, "Output format")
      ->check(CLI::IsMember({"text", "markdown", "latex", "json"}));
  app.add_option("--part", opt.part, "Print only this part (its id, e.g. b)");
  app.add_option("--figure", opt.figure,
                 "Write the sketch of e3, w, L and the cones as .svg, .png or .pdf (solvers that "
                 "draw one: `wobble list --solvers`); a LaTeX key includes it");
  app.add_flag("--force", opt.force, "Overwrite an existing --figure file");
  app.add_option("--variant", opt.variant, "Per-student values: variant N (1, 2, ...)")
      ->transform(whole_number());
  app.add_flag("--handout", opt.handout,
               "Print the handout (statement and values, no answers) instead of the key");
  app.add_flag("--cross-check", opt.cross_check,
               "Recompute the dynamic answers by simulation and compare (torque-free tops)");
}

int run_solve(const SolveOptions& opt) {
  const Problem problem = find_problem(opt.problem);
  const std::vector<std::string> assignments = with_variant(problem, opt.variant, opt.sets);
  const sym::Values values = parameter_values(problem, assignments);
  const auto start = std::chrono::steady_clock::now();
  Key key = solve_at(problem, values, opt.sets);
  key.variant = opt.variant;
  const double key_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const SolverInfo& solver = solver_info(problem.solver);
  std::optional<CrossCheck> check;
  if (opt.cross_check) {
    if (!solver.cross_checked_by_simulation) {
      throw InputError("--cross-check: problem " + problem.id + " (solver " + solver.name +
                       ") has no simulation cross-check; see `wobble list --solvers`");
    }
    check = cross_check_torque_free(problem, values, key);
  }
  if (!opt.part.empty()) {
    std::string known;
    for (const auto& p : key.parts) {
      if (p.id == opt.part) {
        key.parts = {p};
        known.clear();
        break;
      }
      known += (known.empty() ? "" : ", ") + p.id;
    }
    if (!known.empty()) {
      throw InputError(fmt::format("--part: problem {} has no part '{}' (parts: {})", problem.id,
                                   opt.part, known));
    }
  }
  if (!opt.figure.empty()) {
    if (solver.sketch == nullptr) {
      throw InputError("--figure: problem " + problem.id + " (solver " + solver.name +
                       ") has no sketch; see `wobble list --solvers`");
    }
    // A device or link is never replaced, and an unwritable folder is found before the work.
    require_writable(opt.figure);
    const std::string ext = std::filesystem::path(opt.figure).extension().string();
    if (ext != ".svg" && ext != ".png" && ext != ".pdf") {
      throw InputError("--figure: " + opt.figure + ": the file must end in .svg, .png or .pdf");
    }
    if (opt.format == "latex" && ext == ".svg") {
      throw InputError("--figure: " + opt.figure +
                       ": pdflatex includes .pdf or .png, not .svg (the LaTeX key includes the "
                       "sketch)");
    }
    refuse_to_replace("--figure", opt.figure, opt.force);
    write_top_sketch(solver.sketch(problem, values), opt.figure);
    key.figure = opt.figure;
  }
  if (opt.handout) {
    const auto shown = shown_values(problem, assignments);
    if (opt.format == "json") throw InputError("--handout: text, markdown or latex; not json");
    fmt::print("{}", opt.format == "latex" ? render_handout_latex(key, shown, opt.variant)
                     : opt.format == "markdown"
                         ? render_handout(key, shown, opt.variant)
                         : reflowed(render_handout_text(key, shown, opt.variant, true),
                                    terminal_columns()));
    return kExitOk;
  }
  if (check) {
    if (opt.format != "text") {
      throw InputError("--cross-check: prints text only; drop --format " + opt.format);
    }
    fmt::print("{}: the dynamic answers, closed form against simulation\n{}", problem.id,
               cross_check_text(*check, key_time));
    return kExitOk;
  }
  // At a terminal the text key's prose breaks at spaces; to a file or a pipe it is as stored.
  fmt::print("{}", render(key, format_from_name(opt.format), terminal_columns()));
  return kExitOk;
}

}  // namespace wobble::cli
