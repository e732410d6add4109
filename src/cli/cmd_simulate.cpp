#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "cli/commands.hpp"
#include "core/characters.hpp"
#include "core/work_budget.hpp"
#include "io/atomic_write.hpp"
#include "problem/field_lines.hpp"
#include "problem/scene.hpp"
#include "problem/values.hpp"
#include "problem/variants.hpp"
#include "render/simulation_output.hpp"
#include "simulate/scene_setup.hpp"

namespace wobble::cli {

void setup_simulate(CLI::App& app, SimulateOptions& opt) {
  app.add_option("scene", opt.scene, "Scene id (a file in scenes/) or a .toml file")->required();
  app.add_option(
         "--set", opt.sets,
         "Parameter value NAME=VALUE, in SI or with a unit (R=5 cm, theta0=30deg), as for solve")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_option("--variant", opt.variant,
                 "Per-student values: variant N of the scene's parameters")
      ->transform(whole_number());
  // The names from the method table, so that a new method is offered where it is listed.
  std::string methods = "auto";
  const auto& names = simulation_method_names();
  for (std::size_t i = 0; i < names.size(); ++i)
    methods += (i + 1 == names.size() ? " or " : ", ") + names[i].first;
  // In any case, as the tables print some of them (DOP853, RK4).
  app.add_option("--method", opt.method, methods + " (default: the scene's, usually auto)")
      ->transform([](const std::string& text) { return ascii_lower(text); });
  app.add_option("--tolerance", opt.tolerance,
                 "Relative tolerance for the adaptive methods, " + scene_tolerance_range());
  app.add_option("--samples", opt.samples,
                 "Number of output times, " + scene_samples_range() +
                     ", as 500 or 1e5 (default: the scene's)")
      ->transform(whole_number());
  app.add_option("--t-end", opt.t_end,
                 "End of the run, s (default: the scene's run.t_end); an expression such as 10 "
                 "or 2*pi, or with a unit of time: 500 ms, 2 min");
  app.add_option("--out", opt.out, "Write the samples to FILE.csv or FILE.json instead");
  app.add_option("--plot", opt.plot, "Draw the outputs against time as .svg, .png or .pdf (gnuplot)");
  app.add_option("--max-evaluations", opt.max_evaluations,
                 "Refuse a run estimated to need more evaluations than this (default 5e7, a "
                 "few seconds), and stop one that does");
  app.add_flag("--force", opt.force, "Overwrite existing --out and --plot files");
}

namespace {
// The text table prints only the digits the run's estimated error supports; where not one would
// be right (dopri5 at tolerance 1e-2 over 1000 s of the tennis racket: error 1.2 of each
// column's largest value), it is refused, naming what set the run's accuracy. --out writes the
// samples as computed, at full precision, for a look at how a run goes wrong.
void refuse_table_without_a_right_digit(const SimulateOptions& opt, const SceneSetup& setup,
                                        const MethodChoice& choice,
                                        const SimulationResult& result) {
  if (!opt.out.empty() || printed_digits(setup, result) >= 1) return;
  const bool stepped = choice.step_s > 0.0 && setup.step;  // else the tolerance set the step
  const std::string field =
      stepped ? fmt::format("run.step: {:.6g} s", *setup.step)
              : fmt::format("{}: {:.0e}", opt.tolerance ? "--tolerance" : "run.tolerance",
                            setup.tolerance);
  throw InputError(fmt::format(
      "{} leaves not one digit of the table right: the samples' estimated error is {:.2g} of "
      "each column's largest value (against {}); {} it, or write the samples as computed with "
      "--out",
      field, result.error_estimate, result.error_reference, stepped ? "shorten" : "tighten"));
}
}  // namespace

int run_simulate(const SimulateOptions& opt) {
  if (!opt.out.empty()) {
    const std::string ext = std::filesystem::path(opt.out).extension().string();
    if (ext != ".csv" && ext != ".json") {
      throw InputError("--out: " + opt.out + ": the file must end in .csv or .json");
    }
  }
  if (!opt.plot.empty()) {
    const std::string ext = std::filesystem::path(opt.plot).extension().string();
    if (ext != ".svg" && ext != ".png" && ext != ".pdf") {
      throw InputError("--plot: " + opt.plot + ": the file must end in .svg, .png or .pdf");
    }
  }
  refuse_to_replace("--out", opt.out, opt.force);
  refuse_to_replace("--plot", opt.plot, opt.force);
  if (opt.tolerance && !(*opt.tolerance >= kMinSceneTolerance && *opt.tolerance <= kMaxSceneTolerance)) {
    throw InputError(fmt::format("--tolerance: {} is out of range (expected {})", *opt.tolerance,
                                 scene_tolerance_range()));
  }
  if (opt.max_evaluations && !(*opt.max_evaluations >= 1 && *opt.max_evaluations <= 1e15)) {
    throw InputError(fmt::format("--max-evaluations: {} is out of range (expected 1 to 1e15)",
                                 *opt.max_evaluations));
  }
  if (opt.samples && (*opt.samples < kMinSamples || *opt.samples > kMaxSamples)) {
    throw InputError(
        fmt::format("--samples: {} is out of range (expected {})", *opt.samples, scene_samples_range()));
  }
  // An unwritable target is found before the work, not after it.
  if (!opt.out.empty()) require_writable(opt.out);
  if (!opt.plot.empty()) require_writable(opt.plot);
  Scene scene = find_scene(opt.scene);
  require_each_set_once(scene.model, opt.sets);
  if (opt.samples) scene.samples = static_cast<int>(*opt.samples);
  if (!opt.t_end.empty()) {
    scene.t_end = opt.t_end;  // read and checked (> 0) as run.t_end, at no line of the file
    scene.model.field_lines.erase("run.t_end");
  }
  std::vector<std::string> assignments;
  if (opt.variant) {
    // A scene's variant is valid when its setup accepts it (a scene has no solver to ask).
    assignments = first_valid_variant(scene.model, *opt.variant, [&](const auto& a) {
      (void)setup_scene(scene, a);
    });
  }
  assignments.insert(assignments.end(), opt.sets.begin(), opt.sets.end());
  SceneSetup setup = [&] {
    try {
      return setup_scene(scene, assignments);
    } catch (const InputError& e) {
      // The end time came from --t-end: name the option, not the file's field.
      const std::string field = "run.t_end";
      const std::string what = e.what();
      if (!opt.t_end.empty() && what.rfind(field, 0) == 0) {
        throw InputError("--t-end" + what.substr(field.size()));
      }
      throw;
    }
  }();
  if (opt.tolerance) setup.tolerance = *opt.tolerance;
  if (opt.max_evaluations) setup.max_evaluations = *opt.max_evaluations;
  const MethodChoice choice =
      opt.method.empty()
          ? choose_method(setup, setup.method, field_in_file(scene.model, "run.method"))
          : choose_method(setup, opt.method, "--method");
  const WorkEstimate work = estimate_work(setup, choice);
  require_within_budget(work, setup.max_evaluations, "--max-evaluations");

  // Progress on a terminal only, and only once a run has taken a moment.
  const bool tty = ::isatty(STDERR_FILENO) != 0;
  bool shown = false;
  const auto start = std::chrono::steady_clock::now();
  const auto progress = [&](double done) {
    if (!tty) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed < 0.5) return;
    fmt::print(stderr, "\rsimulating {}: {:3.0f}%", setup.id, 100 * done);
    std::fflush(stderr);
    shown = true;
  };
  const SimulationResult result = [&] {
    try {
      return simulate(setup, choice, progress);
    } catch (const WorkLimitReached& e) {
      throw InputError(fmt::format("--max-evaluations: {} (estimated {:.2g} before it started, "
                                   "from {}); shorten the run or raise --max-evaluations",
                                   e.what(), work.evaluations, work.basis));
    }
  }();
  if (shown) fmt::print(stderr, "\r{:40}\r", "");
  refuse_table_without_a_right_digit(opt, setup, choice, result);

  // Files first, then stdout: a run that fails to write prints nothing. Samples are written as
  // they are read back, never held whole (a million of them would be gigabytes of text).
  std::string notes;
  if (!opt.out.empty()) {
    const bool csv = std::filesystem::path(opt.out).extension() == ".csv";
    write_atomically_with(opt.out, [&](const Emit& append) {
      if (csv) {
        emit_simulation_csv(result, append);
      } else {
        emit_simulation_json(setup, result, append);
      }
    });
    notes += fmt::format("wrote {} samples to {}\n", result.rows.size(), opt.out);
  }
  if (!opt.plot.empty()) {
    write_simulation_plot(setup, result, opt.plot);
    notes += fmt::format("drew {}\n", opt.plot);
  }
  const auto print = [](std::string_view piece) { std::fwrite(piece.data(), 1, piece.size(), stdout); };
  print(simulation_header(setup, result));
  if (opt.out.empty()) {
    print("\n");
    emit_simulation_table(setup, result, print);
    print("\n");
  }
  print(notes);
  print(simulation_footer(setup, result));
  std::fflush(stdout);
  return kExitOk;
}

}  // namespace wobble::cli
