#include <fmt/format.h>

#include <filesystem>

#include "cli/commands.hpp"
#include "core/input_error.hpp"
#include "io/atomic_write.hpp"
#include "problem/values.hpp"
#include "render/render.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"
#include "web/motion.hpp"
#include "web/page_file.hpp"
#include "web/problem_view.hpp"

namespace wobble::cli {

void setup_page(CLI::App& app, PageOptions& opt) {
  app.add_option("problem", opt.problem, "Problem id (see `wobble list`) or a .toml file")
      ->required();
  app.add_option("--variant", opt.variant, "Per-student values: variant N (1, 2, ...)")
      ->transform(whole_number());
  app.add_flag("--key", opt.key, "Show the answers too (an instructor's page)");
  app.add_flag("--no-hints", opt.no_hints, "Leave out the parts' hints (folded under each part)");
  app.add_option("--out", opt.out, "The HTML file to write")->required();
  app.add_flag("--force", opt.force, "Replace the file if it exists");
}

int run_page(const PageOptions& opt) {
  const std::filesystem::path out = opt.out;
  if (out.extension() != ".html" && out.extension() != ".htm") {
    throw InputError("--out: " + opt.out + ": the page is HTML; name it FILE.html");
  }
  refuse_to_replace("--out", out, opt.force);
  // A device or link is never replaced, and an unwritable folder is found before the work.
  require_writable(out);
  const Problem problem = find_problem(opt.problem);
  const std::vector<std::string> assignments = with_variant(problem, opt.variant, {});
  Key key = solve(problem, parameter_values(problem, assignments));
  key.variant = opt.variant;
  const std::string view =
      web::student_view_json(problem, key, opt.variant, assignments, !opt.no_hints);
  const std::string motion =
      web::has_motion(problem) ? web::problem_motion_json(problem, assignments) : "";
  const std::string html =
      web::self_contained_page(view, motion, opt.key ? render_json(key) : std::string());
  write_atomically(out, html);
  fmt::print("wobble page: {} ({} KB{}{})\n", opt.out, (html.size() + 512) / 1024,
             motion.empty() ? ", no motion" : ", with its motion", opt.key ? ", with the key" : "");
  return kExitOk;
}

}  // namespace wobble::cli
