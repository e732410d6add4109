#include <fmt/format.h>

#include <filesystem>

#include "bench/report.hpp"
#include "cli/commands.hpp"
#include "core/input_error.hpp"
#include "core/work_budget.hpp"
#include "io/atomic_write.hpp"
#include "render/bench_output.hpp"

namespace wobble::cli {

void setup_bench(CLI::App& app, BenchOptions& opt) {
  app.add_flag("--quick", opt.quick, "Fewer points and repeats (under a minute; for CI)");
  app.add_option("--format", opt.format, "Output format")
      ->check(CLI::IsMember({"text", "markdown", "json", "csv"}));
  app.add_option("--plot", opt.plot, "Draw the work-precision diagram as SVG (gnuplot)");
  app.add_flag("--force", opt.force, "Overwrite an existing --plot file");
}

int run_bench(const BenchOptions& opt) {
  refuse_to_replace("--plot", opt.plot, opt.force);
  // An unwritable plot is found before a minute of measuring, not after.
  if (!opt.plot.empty()) require_writable(opt.plot);
  const bench::TimingPlan plan = opt.quick ? bench::TimingPlan{3, 1e-4} : bench::TimingPlan{};
  BenchReport report;
  report.machine = bench::machine_description();
  report.quick = opt.quick;
  for (const auto& p : bench::bench_problems()) {
    throw_if_interrupted();
    report.problems.push_back(p);
    const auto runs = bench::work_precision(p, opt.quick, plan);
    report.runs.insert(report.runs.end(), runs.begin(), runs.end());
  }
  for (auto rows : {bench::elliptic_bench(plan), bench::principal_axes_bench(plan),
                    bench::process_bench(std::filesystem::read_symlink("/proc/self/exe").string(),
                                         opt.quick ? 3 : 15)}) {
    report.components.insert(report.components.end(), rows.begin(), rows.end());
  }
  report.drift = bench::drift_table(opt.quick);
  report.dense = bench::dense_output_table(opt.quick, plan);
  report.exact_drift = bench::exact_error_against_time();
  report.long_run = bench::long_splitting_run(opt.quick);
  bench::evaluate_targets(report);
  // The file first, then stdout: a run that fails to write prints nothing.
  if (!opt.plot.empty()) write_bench_plot(report, opt.plot);
  fmt::print("{}", render_bench(report, opt.format));
  return kExitOk;
}

}  // namespace wobble::cli
