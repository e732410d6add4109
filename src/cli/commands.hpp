#pragma once
/// @file
/// The subcommands of `wobble`. Exit codes (README, "Exit codes"): 0 success, 1 a check found a
/// difference, 2 bad usage or input (one line on stderr), 3 an internal error (a bug).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "check/judge.hpp"
#include "problem/problem.hpp"

namespace wobble::cli {

/// The assignments of `variant` (if any) followed by the user's --set ones (which win).
std::vector<std::string> with_variant(const Problem& problem, std::optional<long> variant,
                                      const std::vector<std::string>& sets);

/// The key of `problem` at `values`; where solving refuses them ("lagrangian0: its value, about
/// 3.1e+596, is outside the range of double precision"), the refusal with the user's --set
/// values, which are what to change: ".. (at --set psidot0=1e300)".
Key solve_at(const Problem& problem, const sym::Values& values,
             const std::vector<std::string>& sets);

/// "A-B" or "N" as a range of variant numbers (at most 1000 of them), for `option`.
/// @throws InputError naming `option` and the text.
std::pair<long, long> variant_range(const std::string& text, const std::string& option);

/// A count option's text as a whole number however written: "100000", "1e5", "2.5e3" (as
/// --max-evaluations takes 5e7). A fraction, or more than 2^53, is refused naming the text.
/// For CLI11's transform(): it rewrites an exact whole number in decimal digits.
CLI::Validator whole_number();
/// A relative tolerance's text as a fraction however written: "0.02", or "2%" as it is said.
/// For CLI11's transform(): it rewrites a percentage as its fraction's shortest text.
CLI::Validator fraction_or_percent();
/// "--t-end 2 min": where the first of the `extras` the command line refused is a word of such an
/// option's value that the shell parted at a space, the line saying so with the command to type
/// (`args` as typed); "" otherwise.
std::string value_split_message(const std::vector<std::string>& args,
                                const std::vector<std::string>& extras);

/// An option given the empty value ("--part ''", or "--out $FILE" with FILE unset) would be taken
/// as left out and the command run without it; this refuses it instead, naming the option.
/// @throws InputError for the first such option of `app` or of its parsed subcommands.
void refuse_empty_values(const CLI::App& app);
/// CLI11's "--part: 1 required TEXT missing" (an option last on the line, or "--part=") as
/// "--part: no value given; give one (see wobble solve --help)"; "" for another message.
std::string missing_value_message(const std::string& what, const CLI::App& app);

/// "NAME=VALUE" assignments as (identifier, value text) pairs, for a handout: the last given for
/// a parameter first (a --set after a variant's value).
std::vector<std::pair<std::string, std::string>> shown_values(
    const Problem& problem, const std::vector<std::string>& assignments);

/// Files the command line writes are never replaced without --force.
/// @throws InputError naming `option` and `file` if `file` exists and `force` is false.
void refuse_to_replace(const std::string& option, const std::filesystem::path& file, bool force);

/// Exit codes: 0 ok, 1 an answer or key differs, 2 bad input (or too much asked), 3 a bug, 130
/// stopped by Ctrl-C or SIGTERM (128 + SIGINT, as a shell reports it).
inline constexpr int kExitOk = 0, kExitDifference = 1, kExitBadInput = 2, kExitInternal = 3,
                     kExitInterrupted = 130;

struct ListOptions {
  bool solvers = false;  ///< the solvers and their quantities instead of the catalog
};
void setup_list(CLI::App& app, ListOptions& opt);
int run_list(const ListOptions& opt);

struct SolveOptions {
  std::string problem;
  std::vector<std::string> sets;
  std::string format = "text";
  std::string part;
  std::string figure;           ///< SVG sketch to write (torque-free symmetric problems)
  bool force = false;           ///< overwrite an existing figure file
  bool cross_check = false;     ///< recompute the dynamic answers by simulation
  std::optional<long> variant;  ///< per-student values (problem/variants.hpp)
  bool handout = false;         ///< statement and values, no answers
};
void setup_solve(CLI::App& app, SolveOptions& opt);
int run_solve(const SolveOptions& opt);

struct SimulateOptions {
  std::string scene;
  std::vector<std::string> sets;
  std::string method;                ///< empty: the scene's own (auto by default)
  std::optional<double> tolerance;   ///< overrides the scene's
  std::optional<long long> samples;  ///< overrides the scene's
  std::string t_end;                 ///< overrides the scene's run.t_end (an expression, s)
  std::optional<long> variant;
  std::optional<double> max_evaluations;  ///< the run's budget (default: SceneSetup's)
  std::string out, plot;
  bool force = false;
};
void setup_simulate(CLI::App& app, SimulateOptions& opt);
int run_simulate(const SimulateOptions& opt);

struct CheckOptions {
  std::string problem, part, answer, name;
  std::string answer_after_part;  ///< the answer as a third word, for --answer
  bool answer_by_option = false;  ///< --answer given (maybe empty): refusals name it
  std::string answers;        ///< a submission file: every answer at once (check/submission.hpp)
  std::string format = "text";  ///< with --answers: text, json or gradescope
  std::vector<std::string> sets;
  std::optional<double> tolerance;  ///< default: the problem file's, else 1%
  std::optional<int> sigfigs;
  std::optional<long> variant;
};
void setup_check(CLI::App& app, CheckOptions& opt);
/// The judge's options from --tolerance and --sigfigs.
/// @throws InputError for a tolerance outside (0, 1) or sigfigs outside 1..15.
check::Options judge_options(std::optional<double> tolerance, std::optional<int> sigfigs);
/// A text file a user names with `option`, "-" for standard input, or a pipe by its path;
/// refused if missing, a folder, or over 1 MB.
std::string read_text_file(const std::string& path, const std::string& option);
int run_check(const CheckOptions& opt);  ///< 0 right, 1 wrong
/// "wobble check P I0 '0.00072 kg m^2'", the command line to type where the shell split the
/// answer into words that the command line then refused (`args` as typed, `opt` as far as it
/// was parsed); "" where no answer's words can be told.
std::string answer_quoted(const std::vector<std::string>& args, const CheckOptions& opt);

struct WorksheetOptions {
  std::string problem;
  std::vector<std::string> sets;
  std::optional<long> variant;
};
void setup_worksheet(CLI::App& app, WorksheetOptions& opt);
int run_worksheet(const WorksheetOptions& opt);

struct BenchOptions {
  bool quick = false;
  std::string format = "text";
  std::string plot;
  bool force = false;
};
void setup_bench(CLI::App& app, BenchOptions& opt);
int run_bench(const BenchOptions& opt);

struct KeysOptions {
  bool check = false, update = false;
  std::string variants;  ///< "1-40": write one key per variant into `out`
  std::string out;
  bool force = false;
  std::vector<std::string> problems;  ///< --problem: only these (for --variants)
};
void setup_keys(CLI::App& app, KeysOptions& opt);
int run_keys(const KeysOptions& opt);

struct ServeOptions {
  std::string host = "127.0.0.1";
  int port = 8080;
  std::string problems;  ///< a folder of .toml problems; empty: the catalog
  bool reveal = false;
};
void setup_serve(CLI::App& app, ServeOptions& opt);
int run_serve(const ServeOptions& opt);  ///< serves until Ctrl-C

struct PageOptions {
  std::string problem;  ///< an id or a .toml file
  std::optional<long> variant;
  bool key = false;  ///< the answers too (an instructor's page)
  bool no_hints = false;  ///< leave out the parts' hints (shown folded by default)
  std::string out;
  bool force = false;
};
void setup_page(CLI::App& app, PageOptions& opt);
int run_page(const PageOptions& opt);

struct ExportOptions {
  std::vector<std::string> problems;  ///< ids or .toml files (several for PrairieLearn)
  std::string variants;               ///< "A-B"; empty: the system's default
  std::string out, deb;
  bool force = false;
  std::optional<double> tolerance;
  std::optional<int> sigfigs;
};
/// `wobble export prairielearn|moodle|gradescope`: three subcommands sharing the options.
struct ExportCommands {
  CLI::App *prairielearn = nullptr, *moodle = nullptr, *gradescope = nullptr;
};
ExportCommands setup_export(CLI::App& app, ExportOptions& opt);
int run_export(const ExportCommands& commands, const ExportOptions& opt);

}  // namespace wobble::cli
