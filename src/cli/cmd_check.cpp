#include <fmt/format.h>
#include <fmt/ranges.h>

#include "check/judge.hpp"
#include "cli/commands.hpp"
#include "solvers/catalog.hpp"
#include "problem/values.hpp"
#include "solvers/solve.hpp"

namespace wobble::cli {

void setup_check(CLI::App& app, CheckOptions& opt) {
  app.add_option("problem", opt.problem, "Problem id (see `wobble list`) or a .toml file")
      ->required();
  app.add_option("part", opt.part, "Part id (a, b, ...)")->required();
  app.add_option("--answer", opt.answer,
                 "Your answer: 0.21 kg m^2, 3.1 rad/s, 12 deg, [1, 0, 2], [[..],[..],[..]], "
                 "m*a^2/6")
      ->required();
  app.add_option("--name", opt.name, "Which answer of the part (needed when it has several)");
  app.add_option("--set", opt.sets, "Parameter value NAME=VALUE, as for solve")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--variant", opt.variant, "Your variant's values (as on your handout)");
  app.add_option("--tolerance", opt.tolerance,
                 fmt::format("Relative tolerance for numbers (default: the problem's, else {:g})",
                             check::kDefaultRelativeTolerance));
  app.add_option("--sigfigs", opt.sigfigs, "Accept a number that rounds correctly to N digits");
}

int run_check(const CheckOptions& opt) {
  if (opt.tolerance && !(*opt.tolerance > 0.0 && *opt.tolerance < 1.0)) {
    throw InputError(
        fmt::format("--tolerance: {} must be between 0 and 1 (0.01 is 1%)", *opt.tolerance));
  }
  if (opt.sigfigs && (*opt.sigfigs < 1 || *opt.sigfigs > 15)) {
    throw InputError(fmt::format("--sigfigs: {} must be from 1 to 15", *opt.sigfigs));
  }
  const Problem problem = find_problem(opt.problem);
  const sym::Values values =
      parameter_values(problem, with_variant(problem, opt.variant, opt.sets));
  const Key key = solve(problem, values);
  const PartKey* part = nullptr;
  std::string parts;
  for (const auto& p : key.parts) {
    if (p.id == opt.part) part = &p;
    parts += (parts.empty() ? "" : ", ") + p.id;
  }
  if (part == nullptr) {
    throw InputError(
        fmt::format("part: problem {} has no part '{}' (parts: {})", problem.id, opt.part, parts));
  }
  if (part->answers.empty()) {
    throw InputError(
        fmt::format("part: part {} of {} has nothing to check at these values ({} "
                    "do not exist; `wobble solve` says why)",
                    opt.part, problem.id, fmt::join(part->absent, ", ")));
  }
  std::string names;
  const Answer* answer = nullptr;
  for (const auto& a : part->answers) {
    names += (names.empty() ? "" : ", ") + a.name;
    if (a.name == opt.name || (opt.name.empty() && part->answers.size() == 1)) answer = &a;
  }
  if (answer == nullptr) {
    throw InputError(
        opt.name.empty()
            ? fmt::format("--name: part {} has several answers; name one ({})", opt.part, names)
            : fmt::format("--name: part {} has no answer '{}' (answers: {})", opt.part, opt.name,
                          names));
  }
  const sym::SymbolTable table = problem.symbol_table();
  check::Options o;
  if (opt.tolerance) {
    o.rel_tol = *opt.tolerance;
    o.rel_tol_given = true;
  }
  o.sigfigs = opt.sigfigs;
  const check::Verdict v = check::judge({key, table, values}, *answer, opt.answer, o);
  fmt::print("{}\n", v.line);
  for (const auto& f : v.feedback) fmt::print("  {}\n", f);
  return v.correct ? kExitOk : kExitDifference;
}

}  // namespace wobble::cli
