#include <fmt/format.h>
#include <unistd.h>

#include <iostream>

#include "check/worksheet.hpp"
#include "cli/commands.hpp"
#include "cli/line_editor.hpp"
#include "cli/terminal_width.hpp"
#include "problem/values.hpp"
#include "render/handout.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"

namespace wobble::cli {

void setup_worksheet(CLI::App& app, WorksheetOptions& opt) {
  app.add_option("problem", opt.problem, "Problem id (see `wobble list`) or a .toml file")
      ->required();
  app.add_option("--variant", opt.variant, "Your variant's values (as on your handout)")
      ->transform(whole_number());
  app.add_option("--set", opt.sets, "Parameter value NAME=VALUE, as for solve")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

int run_worksheet(const WorksheetOptions& opt) {
  const Problem problem = find_problem(opt.problem);
  const std::vector<std::string> assignments = with_variant(problem, opt.variant, opt.sets);
  const sym::Values values = parameter_values(problem, assignments);
  const Key key = solve_at(problem, values, opt.sets);
  const auto shown = shown_values(problem, assignments);
  // The handout without its list of questions: the worksheet asks them one by one.
  const std::string intro = render_handout_text(key, shown, opt.variant, false);
  const sym::SymbolTable table = problem.symbol_table();
  // At a terminal, a line editor; piped, plain lines echoed so that the transcript reads well.
  const bool terminal = ::isatty(STDIN_FILENO) != 0;
  const check::ReadLine read =
      terminal ? terminal_lines() : check::stream_lines(std::cin, std::cout, true);
  (void)check::run_worksheet(read, std::cout, intro + "\n", problem, {key, table, values}, {},
                             terminal_columns());
  return kExitOk;
}

}  // namespace wobble::cli
