#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>

#include "check/absent_answer.hpp"
#include "check/answer_choice.hpp"
#include "check/judge.hpp"
#include "check/submission.hpp"
#include "cli/commands.hpp"
#include "cli/terminal_width.hpp"
#include "core/characters.hpp"
#include "core/input_error.hpp"
#include "core/word_wrap.hpp"
#include "export/gradescope.hpp"
#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"

namespace wobble::cli {

void setup_check(CLI::App& app, CheckOptions& opt) {
  app.add_option("problem", opt.problem, "Problem id (see `wobble list`) or a .toml file")
      ->required();
  auto* part =
      app.add_option("part", opt.part,
                     "Part id (a, b, ...), or the answer's name (I0), or both with the answer as "
                     "one line, 'I0 = 0.00072 kg m^2'; may be left out with --name (the answer in "
                     "its place)");
  auto* answer_word =
      app.add_option("answer", opt.answer_after_part,
                     "Your answer, as with --answer (an expression that starts with '-' after --)");
  auto* answer = app.add_option(
      "--answer", opt.answer,
      "Your answer: 0.21 kg m^2, 3.1 rad/s, 12 deg, [1, 0, 2], [[..],[..],[..]], m*a^2/6, "
      "m·a²/6 or \\frac{m a^2}{6}");
  answer->excludes(answer_word)->each([&opt](const std::string&) { opt.answer_by_option = true; });
  auto* answers = app.add_option(
      "--answers", opt.answers,
      "A file with every answer, one per line (NAME = ANSWER; `variant = N` for your values), "
      "or - for standard input");
  app.add_option("--format", opt.format, "With --answers: text, json or gradescope")
      ->needs(answers)
      ->check(CLI::IsMember({"text", "json", "gradescope"}));
  answers->excludes(answer)->excludes(part)->excludes(answer_word);
  app.add_option("--name", opt.name,
                 "Which answer (needed when the part has several; names its part)");
  // One value per --set: CLI11's vector options take every word that follows, and here the
  // answer may follow ("--set R=5cm 0.00072").
  app.add_option("--set", opt.sets, "Parameter value NAME=VALUE, as for solve")
      ->expected(1)
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--variant", opt.variant, "Your variant's values (as on your handout)")
      ->transform(whole_number());
  app.add_option("--tolerance", opt.tolerance,
                 fmt::format("Relative tolerance for numbers, 0.02 or 2% (default: the "
                             "problem's, else {:g})",
                             check::kDefaultRelativeTolerance))
      ->transform(fraction_or_percent());
  app.add_option("--sigfigs", opt.sigfigs, "Accept a number that rounds correctly to N digits");
}

check::Options judge_options(std::optional<double> tolerance, std::optional<int> sigfigs) {
  if (tolerance && !(*tolerance > 0.0 && *tolerance < 1.0)) {
    throw InputError(
        fmt::format("--tolerance: {} must be between 0 and 1 (0.01 is 1%)", *tolerance));
  }
  if (const std::string why = tolerance ? tolerance_too_fine(*tolerance) : ""; !why.empty())
    throw InputError("--tolerance: " + why);
  if (sigfigs && (*sigfigs < 1 || *sigfigs > 15)) {
    throw InputError(fmt::format("--sigfigs: {} must be from 1 to 15", *sigfigs));
  }
  check::Options o;
  if (tolerance) {
    o.rel_tol = *tolerance;
    o.rel_tol_given = true;
  }
  o.sigfigs = sigfigs;
  return o;
}

namespace {
int check_submission(const CheckOptions& opt, const check::Options& o) {
  const std::string text = read_text_file(opt.answers, "--answers");
  const Problem problem = find_problem(opt.problem);
  std::optional<long> variant = check::submission_variant(text);
  if (variant && opt.variant && *variant != *opt.variant) {
    throw InputError(fmt::format("--variant: {} differs from the submission's variant {}",
                                 *opt.variant, *variant));
  }
  if (!variant) variant = opt.variant;
  const sym::Values values = parameter_values(problem, with_variant(problem, variant, opt.sets));
  const Key key = solve_at(problem, values, opt.sets);
  const sym::SymbolTable table = problem.symbol_table();
  const auto result = check::judge_submission({key, table, values}, text, o);
  if (opt.format == "gradescope") {
    fmt::print("{}", exports::gradescope_results(result));
  } else if (opt.format == "json") {
    nlohmann::json answers = nlohmann::json::array();
    for (const auto& a : result.answers) {
      answers.push_back({{"part", a.part},
                         {"name", a.name},
                         {"answered", a.answered},
                         {"correct", a.verdict.correct},
                         {"verdict", a.verdict.line},
                         {"feedback", a.verdict.feedback}});
    }
    fmt::print("{}\n", nlohmann::json{{"problem", problem.id},
                                      {"variant", variant ? nlohmann::json(*variant) : nlohmann::json()},
                                      {"answers", answers},
                                      {"problems", result.problems}}
                           .dump(2));
  } else {
    const std::size_t width = terminal_columns();
    for (const auto& a : result.answers) {
      fmt::print("{}", word_wrapped(a.verdict.line, width, "(" + a.part + ") ", "    "));
      for (const auto& f : a.verdict.feedback)
        fmt::print("{}", word_wrapped(f, width, "  ", "    "));
    }
    for (const auto& p : result.problems) fmt::print("{}\n", p);
  }
  return result.all_correct() ? kExitOk : kExitDifference;
}
// Whether `word` is one of the problem's part ids or answer names.
bool names_part_or_answer(const Problem& problem, const std::string& word) {
  for (const auto& part : problem.parts) {
    if (part.id == word) return true;
    for (const auto& answer : part.answers) {
      if (answer.name == word) return true;
    }
  }
  return false;
}

// Where one word is a line "NAME = ANSWER" or "NAME: ANSWER" (as the worksheet prompts and a
// submission file is written, read as a submission's line: check/submission.hpp), what it
// names and the answer after the '=': an answer's name, as the key writes or prints it ("I₀");
// a part's id ("b = 1.772 1/s"; the id may be a symbol too: box-corner's part a); a name of no
// answer as typed, to be refused as one ("J0 = .."). Nothing where there is no '=' or ':', or
// the left is not one word.
// @throws InputError for a part or answer with nothing after its '=' ("rate_axis2 =").
std::optional<std::pair<std::string, std::string>> named_line(const Key& key,
                                                              const std::string& word) {
  const auto line = check::answer_line(word);
  if (!line || line->name.empty() || line->name.find_first_of(" \t") != std::string::npos)
    return std::nullopt;
  std::string named = line->name;
  bool known = false;  // a part's id or an answer's name
  const std::string name = check::name_in_key(key, line->name);
  for (const auto& part : key.parts) {
    known = known || part.id == named;
    // Those that do not exist at these values too: "phidot_slow =" is as empty there.
    for (const auto& asked : part.asked_names()) {
      if (asked == name) named = name;
      known = known || asked == name;
    }
  }
  if (line->answer.empty() && known) {
    throw InputError(check::nothing_after(named, line->separator, trim(word)));
  }
  return std::pair{named, line->answer};
}

// Whether one word typed where the part goes, with nothing after it and no name before an '=',
// is an answer rather than a misspelt name: a number, an expression or a list ("[[13/3, -1/2,
// ..]]", "4.33 kg m^2", "m*a^2/6"). Not a LaTeX name ("\\dot{\\phi}") nor a part in
// parentheses ("(a)").
bool reads_as_value(const Key& key, const std::string& word) {
  if (word.empty()) return false;
  for (const auto& part : key.parts) {
    if (word == "(" + part.id + ")") return false;
  }
  const char first = word.front();
  return is_digit(first) || first == '-' || first == '.' ||
         word.find_first_of(" []()=,;+*/") != std::string::npos;
}

// The part and the answer typed. "wobble check P --name N ANSWER": --name lets the part go,
// so the one word after the problem is the answer unless it names a part or an answer.
// "wobble check P 'N = ANSWER'": one word, a key's line, names the answer or the part
// (named_line).
std::pair<std::string, std::string> part_and_answer(const CheckOptions& opt, const Problem& problem,
                                                    const Key& key) {
  const std::string& typed = opt.answer_after_part.empty() ? opt.answer : opt.answer_after_part;
  if (typed.empty() && opt.name.empty() && !names_part_or_answer(problem, opt.part)) {
    if (auto named = named_line(key, opt.part)) return *named;
    // "omega3_min 118.8 rad/s": a first word that names an answer labels the rest (an answer
    // alone where the part goes is refused, so the word can be no factor here).
    if (const auto spaced = check::spaced_answer_line(opt.part)) {
      const std::string name = check::name_in_key(key, spaced->name);
      if (asks_for(key, name)) return {name, spaced->answer};
    }
  }
  if (opt.name.empty() || opt.part.empty() || !typed.empty() ||
      names_part_or_answer(problem, opt.part)) {
    return {opt.part, typed};
  }
  return {"", opt.part};
}

// The judge's refusals name --answer; an answer typed in its own place (after the part, or as
// "NAME = ANSWER") is named by the answer's name instead: "rate_axis2: empty; ..".
check::Verdict judged_as_typed(const check::Context& ctx, const Answer& answer,
                               const std::string& typed, const check::Options& o, bool by_option) {
  try {
    return check::judge(ctx, answer, typed, o);
  } catch (const InputError& e) {
    if (by_option) throw;
    throw InputError(answer.name + ": " + check::without_option(e.what()));
  }
}
}  // namespace

std::string answer_quoted(const std::vector<std::string>& args, const CheckOptions& opt) {
  // The answer's first word: --answer's value, else (with --name) the word in the part's place
  // where it names no part or answer, else the word after the part.
  std::string first = !opt.answer.empty() ? opt.answer : opt.answer_after_part;
  if (opt.answer.empty() && !opt.name.empty() && !opt.part.empty()) {
    try {
      if (!names_part_or_answer(find_problem(opt.problem), opt.part)) first = opt.part;
    } catch (const InputError&) {
      return "";
    }
  }
  if (first.empty() || first.find('\'') != std::string::npos) return "";
  std::size_t at = args.size();
  for (std::size_t i = args.size(); i-- > 1;) {
    if (args[i] == first || args[i] == "--answer=" + first) {
      at = i;
      break;
    }
  }
  if (at == args.size()) return "";
  std::size_t end = at + 1;
  while (end < args.size() && !args[end].empty() && args[end][0] != '-') ++end;
  if (end == at + 1) return "";
  std::string answer = first;
  for (std::size_t i = at + 1; i < end; ++i) answer += " " + args[i];
  // "rate_axis2 = 1.772 1/s": the name and its '=' go in the quotes too, one word that is a key's
  // line (part_and_answer reads it so).
  if (first == "=" && opt.answer.empty() && at >= 2 && args[at - 1] == opt.part) {
    --at;
    answer = opt.part + " " + answer;
  }
  std::string line = "wobble";
  for (std::size_t i = 1; i < args.size(); ++i) {
    const bool plain = args[i].find_first_of(" '\"*?$&|;<>()[]{}\\") == std::string::npos;
    if (i == at) {
      line += (args[i].compare(0, 9, "--answer=") == 0 ? " --answer='" : " '") + answer + "'";
      i = end - 1;
    } else {
      line += plain ? " " + args[i] : " '" + args[i] + "'";
    }
  }
  return line;
}

int run_check(const CheckOptions& opt) {
  const check::Options o = judge_options(opt.tolerance, opt.sigfigs);
  if (!opt.answers.empty()) return check_submission(opt, o);
  const Problem problem = find_problem(opt.problem);
  const sym::Values values =
      parameter_values(problem, with_variant(problem, opt.variant, opt.sets));
  const Key key = solve_at(problem, values, opt.sets);
  if (opt.part.empty() && opt.name.empty()) {
    // What there is to check, so that the next command can be typed from this line.
    const auto part = std::find_if(key.parts.begin(), key.parts.end(),
                                   [](const PartKey& p) { return !p.answers.empty(); });
    throw InputError(fmt::format(
        "check: give an answer's name (or its part) and the answer, as wobble check {} {} "
        "ANSWER, or --answers FILE with every answer; {}'s answers: {}",
        opt.problem, part == key.parts.end() ? "NAME" : part->answers.front().name, opt.problem,
        answers_by_part(key)));
  }
  auto [part, typed] = part_and_answer(opt, problem, key);
  const sym::SymbolTable table = problem.symbol_table();
  const check::Context ctx{key, table, values};
  // "dω₁/dt = -0.5 ω₂ω₃, ..": one word that is Euler's equations names no answer by its label
  // (the first equation's); it is the whole answer, to the answer of their coefficients.
  if (opt.name.empty() && opt.answer.empty() && opt.answer_after_part.empty() &&
      !names_part_or_answer(problem, part) && check::name_in_key(key, part) == part) {
    if (const std::string name = check::euler_equations_answer(ctx, opt.part); !name.empty()) {
      part = name;  // an answer's name where the part goes names the answer
      typed = opt.part;
    }
  }
  if (typed.empty() && opt.name.empty() && !names_part_or_answer(problem, part) &&
      check::name_in_key(key, part) == part && reads_as_value(key, part)) {
    // An answer alone: which of the problem's it is for is the student's to say.
    throw InputError(fmt::format(
        "part: '{}' has no name; say whose answer it is, as wobble check {} 'NAME = ANSWER' or "
        "wobble check {} PART ANSWER (answers by part: {})",
        printable(part, 40), opt.problem, opt.problem, answers_by_part(key)));
  }
  // "I₀", "I_0": an answer's name as the statement or a LaTeX handout writes it. A part of
  // several answers with none named: the one the answer's label names, the only one it is right
  // for, or the only one it reads as a value of (check/answer_choice.hpp).
  // An answer that does not exist at these values: "none" is right (check/absent_answer.hpp).
  const auto absent = check::judge_absent(key, part, opt.name, typed, /*with_reason=*/true);
  const check::Verdict v =
      absent
          ? *absent
          : judged_as_typed(ctx, check::answer_for(ctx, part, opt.name, typed, o, "part", "--name"),
                            typed, o, opt.answer_by_option);
  const std::size_t width = terminal_columns();
  fmt::print("{}", word_wrapped(v.line, width, "", "  "));
  for (const auto& f : v.feedback) fmt::print("{}", word_wrapped(f, width, "  ", "    "));
  return v.correct ? kExitOk : kExitDifference;
}

}  // namespace wobble::cli
