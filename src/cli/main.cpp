// wobble: worked, checked answers for rigid-body rotation problems.
// Parses the command line, runs one subcommand, and turns every failure into one line on stderr
// and an exit code (commands.hpp).
#include <fmt/format.h>

#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>
#include <string>
#include <string_view>

#include "cli/commands.hpp"
#include "core/work_budget.hpp"
#include "io/data_dir.hpp"
#include "problem/problem.hpp"

namespace {
constexpr const char* kCommandList =
    "list, solve, check, worksheet, simulate, bench, keys, export, serve, page";

// CLI11's "Could not convert: --variant = abc" in the words of wobble's other messages:
// "--variant: 'abc' is not a number". Another text is passed on as it is.
std::string conversion_message(const std::string& what) {
  const std::string lead = "Could not convert: ";
  const auto eq = what.find(" = ");
  if (what.rfind(lead, 0) != 0 || eq == std::string::npos) return what;
  return what.substr(lead.size(), eq - lead.size()) + ": '" + what.substr(eq + 3) +
         "' is not a number";
}
}  // namespace

namespace {
// Where the shell split an answer at its spaces ("wobble check ID I0 0.00072 kg m^2"), what to
// say, with the line to type instead.
std::string split_answer_message(const std::string& quoted) {
  return "the answer reached wobble as several words (the shell splits at spaces); put it in "
         "quotes: " +
         quoted;
}
}  // namespace

int main(int argc, char** argv) {
  // Past a file-size limit (or on a full disk) a write should fail and be reported, with the
  // temporary removed and the old file kept (io/atomic_write), not kill the process.
  std::signal(SIGXFSZ, SIG_IGN);
  using namespace wobble::cli;
  CLI::App app{"wobble: worked, checked answers for rigid-body rotation problems", "wobble"};
  app.set_version_flag("--version", std::string("wobble ") + WOBBLE_VERSION);
  app.require_subcommand(1);
  std::string data_dir;
  app.add_option("--data-dir", data_dir,
                 "Folder holding problems/, scenes/ and solutions/ (default: installed next to "
                 "the program, else the source tree)");

  ListOptions list_opt;
  SolveOptions solve_opt;
  KeysOptions keys_opt;
  SimulateOptions simulate_opt;
  BenchOptions bench_opt;
  CheckOptions check_opt;
  WorksheetOptions worksheet_opt;
  ExportOptions export_opt;
  ServeOptions serve_opt;
  PageOptions page_opt;
  CLI::App* list = app.add_subcommand("list", "List the problems with their titles");
  CLI::App* solve = app.add_subcommand("solve", "Print the worked key of a problem");
  CLI::App* keys = app.add_subcommand("keys", "Check or update the golden keys in solutions/");
  CLI::App* simulate =
      app.add_subcommand("simulate", "Simulate a scene: a body, its spin and the effects on it");
  setup_list(*list, list_opt);
  setup_solve(*solve, solve_opt);
  setup_keys(*keys, keys_opt);
  setup_simulate(*simulate, simulate_opt);
  CLI::App* bench = app.add_subcommand(
      "bench", "Measure what accuracy costs: work-precision of every method against peers");
  setup_bench(*bench, bench_opt);
  CLI::App* check = app.add_subcommand("check", "Check your answer to one part of a problem");
  setup_check(*check, check_opt);
  CLI::App* worksheet =
      app.add_subcommand("worksheet", "Work through a problem part by part, with feedback");
  setup_worksheet(*worksheet, worksheet_opt);
  CLI::App* exporter = app.add_subcommand(
      "export", "Export a problem with its variants to PrairieLearn, Moodle or Gradescope");
  const ExportCommands export_commands = setup_export(*exporter, export_opt);
  CLI::App* server = app.add_subcommand(
      "serve", "Serve the worksheet to a class in the browser (math typeset, answers judged)");
  setup_serve(*server, serve_opt);
  CLI::App* page = app.add_subcommand(
      "page", "Write a problem's page as one HTML file (3-D motion, typeset math; no server)");
  setup_page(*page, page_opt);

  // CLI11 would only say "a subcommand is required"; name the word the user typed instead.
  const auto known =
      app.get_subcommands([&](CLI::App* sub) { return argc > 1 && sub->get_name() == argv[1]; });
  if (argc > 1 && argv[1][0] != '-' && known.empty()) {
    fmt::print(stderr, "wobble: unknown command '{}' (commands: {}; see --help)\n", argv[1],
               kCommandList);
    return kExitBadInput;
  }
  if (argc > 1 && std::string_view(argv[1]) == "export" &&
      (argc == 2 || (argv[2][0] != '-' && exporter->get_subcommands([&](CLI::App* sub) {
                                              return sub->get_name() == argv[2];
                                            }).empty()))) {
    fmt::print(stderr, "wobble: export: {} (systems: prairielearn, moodle, gradescope)\n",
               argc == 2 ? std::string("name the system") : fmt::format("unknown system '{}'", argv[2]));
    return kExitBadInput;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ExtrasError& e) {
    // "wobble check ID I0 -m*R^2/4": CLI11 takes a word that starts with '-' and a letter for
    // options, so a negative expression needs the "--" that ends them ("--frob" is an option).
    const std::string what = e.what();
    const bool negative_answer = check->parsed() && what.find(": -") != std::string::npos &&
                                 what.find(": --") == std::string::npos;
    // "wobble check ID I0 0.00072 kg m^2": the shell split the answer at its spaces.
    const std::string quoted =
        check->parsed() && !negative_answer ? answer_quoted({argv, argv + argc}, check_opt) : "";
    // "wobble simulate wheel-brake --t-end 2 min": an option's value split likewise.
    const std::string split_value =
        quoted.empty() ? value_split_message({argv, argv + argc}, app.remaining(true)) : "";
    if (!quoted.empty()) {
      fmt::print(stderr, "wobble: check: {}\n", split_answer_message(quoted));
    } else if (!split_value.empty()) {
      fmt::print(stderr, "wobble: {}\n", split_value);
    } else {
      fmt::print(stderr, "wobble: {}{}\n", what,
                 negative_answer ? "; an answer that starts with '-' goes after -- (wobble check "
                                   "ID NAME -- -m*R^2/4) or as --answer=-m*R^2/4"
                                 : "");
    }
    return kExitBadInput;
  } catch (const CLI::ConversionError& e) {
    fmt::print(stderr, "wobble: {}\n", conversion_message(e.what()));
    return kExitBadInput;
  } catch (const CLI::RequiredError& e) {
    // "wobble" alone: CLI11 would say "A subcommand is required".
    // CLI11 checks what is required before what is unknown: "export moodle ID -o quiz.xml"
    // would say "--out is required" and not name the -o typed for it.
    const std::vector<std::string> unknown = app.remaining(/*recurse=*/true);
    if (argc == 1) {
      fmt::print(stderr, "wobble: name a command ({}; see --help)\n", kCommandList);
    } else if (!unknown.empty()) {
      fmt::print(stderr, "wobble: {}\n", CLI::ExtrasError(unknown).what());
    } else {
      fmt::print(stderr, "wobble: {}\n", e.what());
    }
    return kExitBadInput;
  } catch (const CLI::ParseError& e) {
    // "--answer 0.00072 kg m^2": the answer's second word in the answer's place.
    const bool excludes =
        check->parsed() && std::string_view(e.what()).find("excludes") != std::string_view::npos;
    const std::string quoted = excludes ? answer_quoted({argv, argv + argc}, check_opt) : "";
    const std::string missing = missing_value_message(e.what(), app);
    if (!quoted.empty()) {
      fmt::print(stderr, "wobble: check: {}\n", split_answer_message(quoted));
    } else if (!missing.empty()) {
      fmt::print(stderr, "wobble: {}\n", missing);
    } else {
      fmt::print(stderr, "wobble: {}\n", e.what());
    }
    return kExitBadInput;
  }

  // The long commands stop cleanly on Ctrl-C: their loops poll the flag and unwind, removing
  // temporaries (core/work_budget.hpp). The others keep the default (nothing to clean up).
  if (simulate->parsed() || keys->parsed() || bench->parsed() || exporter->parsed() ||
      server->parsed()) wobble::stop_on_signals();
  try {
    refuse_empty_values(app);
    if (!data_dir.empty()) wobble::set_data_dir(data_dir);
    if (list->parsed()) return run_list(list_opt);
    if (solve->parsed()) return run_solve(solve_opt);
    if (keys->parsed()) return run_keys(keys_opt);
    if (simulate->parsed()) return run_simulate(simulate_opt);
    if (bench->parsed()) return run_bench(bench_opt);
    if (check->parsed()) return run_check(check_opt);
    if (worksheet->parsed()) return run_worksheet(worksheet_opt);
    if (exporter->parsed()) return run_export(export_commands, export_opt);
    if (server->parsed()) return run_serve(serve_opt);
    if (page->parsed()) return run_page(page_opt);
  } catch (const wobble::Interrupted&) {
    fmt::print(stderr, "wobble: interrupted; no file was left half-written\n");
    return kExitInterrupted;
  } catch (const wobble::InputError& e) {
    fmt::print(stderr, "wobble: {}\n", e.what());
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr,
               "wobble: out of memory: the input asks for more than this machine can hold\n");
    return kExitBadInput;
  } catch (const std::filesystem::filesystem_error& e) {
    // "filesystem error: cannot ...: Not a directory [path]" in the user's terms: the path first.
    fmt::print(stderr, "wobble: {}: {}\n", e.path1().string(), e.code().message());
    return kExitBadInput;
  } catch (const std::logic_error& e) {
    fmt::print(stderr, "wobble: internal error (please report): {}\n", e.what());
    return kExitInternal;
  } catch (const std::exception& e) {
    // A numerical library's own failure (Boost.Math's "Error in function boost::...") is not
    // the user's input, which is validated first: it is reported as the bug it is.
    if (std::string_view(e.what()).find("boost::") != std::string_view::npos) {
      fmt::print(stderr, "wobble: internal error (please report): a numerical routine failed: {}\n",
                 e.what());
      return kExitInternal;
    }
    fmt::print(stderr, "wobble: {}\n", e.what());
    return kExitBadInput;
  }
  return kExitInternal;
}
