#include "render/bench_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

#include "render/gnuplot.hpp"

namespace wobble {

namespace {
// A Markdown table cell: '|' would end the cell.
std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

// The same line style for a method in every panel.
int style_of(const std::string& method) {
  static const char* order[] = {"exact",         "dopri5",       "rkf78",     "dop853",
                                "vern9",         "odeint_dopri5", "odeint_rkf78", "gsl_rk8pd",
                                "gsl_rkf45",     "cvode_adams",  "rk4",       "split2",
                                "split4"};
  constexpr int n = sizeof order / sizeof order[0];
  for (int i = 0; i < n; ++i) {
    if (method == order[i]) return i + 1;
  }
  return n + 1;
}

std::string us(double s) {
  return fmt::format("{:.3g}", s * 1e6);
}
std::string err(double e) {
  return std::isfinite(e) ? fmt::format("{:.1e}", e) : "diverged";
}

// The ratios the targets name: wobble's best adaptive pair against each peer, at the errors
// where the curves are compared.
std::string ratios(const BenchReport& r, const bench::BenchProblem& p, bool markdown) {
  std::string out;
  for (const double target : {1e-8, 1e-12}) {
    for (const char* peer : bench::kPeerIntegrators) {
      for (const char* mine : bench::kWobbleIntegrators) {
        const double ratio = bench::time_ratio_at(r.runs, p.id, mine, peer, target);
        if (ratio < 0) continue;
        out += fmt::format("{}{} / {} at error {:.0e}: {:.2f}\n", markdown ? "- " : "  ", mine,
                           peer, target, ratio);
      }
    }
  }
  return out;
}

std::string table(const BenchReport& r, const bench::BenchProblem& p, bool markdown) {
  std::string out;
  if (markdown) {
    out += fmt::format("**{}**: {}\n\n", p.id, p.description);
    out +=
        "| method | setting | error | energy error | \\|L\\| or p_phi error | evaluations | time "
        "(us) |\n";
    out += "|---|---|---|---|---|---|---|\n";
  } else {
    out += fmt::format("{}: {}\n", p.id, p.description);
    out += fmt::format("  {:<14} {:<11} {:>9} {:>11} {:>11} {:>11} {:>10}\n", "method", "setting",
                       "error", "energy err", "L/p_phi err", "evaluations", "time (us)");
  }
  for (const auto& run : r.runs) {
    if (run.problem != p.id) continue;
    if (markdown) {
      out += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", run.method, run.setting,
                         err(run.error), err(run.energy_error), err(run.L_error), run.evals,
                         us(run.time_s));
    } else {
      out += fmt::format("  {:<14} {:<11} {:>9} {:>11} {:>11} {:>11} {:>10}\n", run.method,
                         run.setting, err(run.error), err(run.energy_error), err(run.L_error),
                         run.evals, us(run.time_s));
    }
  }
  if (const double c = bench::measured_condition(p); c > 0 && p.id == "P3") {
    out += fmt::format(
        "{}measured condition: a change of eps |m0| in m0 moves m(T) by {:.1f} eps |m0|\n",
        markdown ? "\n" : "  ", c);
  }
  const std::string rs = ratios(r, p, markdown);
  if (!rs.empty())
    out += (markdown ? "\nwobble / peer time at equal error:\n\n"
                     : "  wobble / peer time at equal error:\n") +
           rs;
  return out + "\n";
}

std::string components(const BenchReport& r, bool markdown) {
  std::string out, group;
  for (const auto& c : r.components) {
    if (c.group != group) {
      group = c.group;
      const std::string what =
          group == "elliptic"
              ? "elliptic functions (error: largest over the points of sn, dn relative and cn "
                "absolute, in eps)"
          : group == "principal axes"
              ? "principal axes of R diag(l) R^T (error: eigenvalues, residual and "
                "orthonormality, in eps l_max)"
              : "whole process, the program spawned without a shell (median of repeated runs)";
      out +=
          markdown
              ? fmt::format(
                    "\n{}:\n\n| what | cases | error | time per call |\n|---|---|---|---|\n", what)
              : fmt::format("{}:\n", what);
    }
    const std::string e = c.max_error < 0 ? "-" : fmt::format("{:.3g}", c.max_error);
    const std::string t = c.group == "process" ? fmt::format("{:.3g} ms", c.ns_per_call * 1e-6)
                                               : fmt::format("{:.3g} ns", c.ns_per_call);
    out += markdown ? fmt::format("| {} | {} | {} | {} |\n", cell(c.method), cell(c.cases), e, t)
                    : fmt::format("  {:<48} {:<38} {:>9} {:>11}\n", c.method, c.cases, e, t);
  }
  if (!r.drift.empty()) {
    std::string head = "P2 against time, relative energy error (|L| error) at t =";
    for (const double t : r.drift.front().times) head += fmt::format(" {:g}", t);
    out += "\n" + head + ":\n" + (markdown ? "\n" : "");
    for (const auto& d : r.drift) {
      std::string line = fmt::format("{} {}:", d.method, d.setting);
      for (std::size_t i = 0; i < d.times.size(); ++i) {
        line += fmt::format(" {:.1e} ({:.1e})", d.energy_error[i], d.L_error[i]);
      }
      out += (markdown ? "- " : "  ") + line + "\n";
    }
  }
  if (!r.exact_drift.empty()) {
    out += "\nThe exact solutions against 50 digits (P2 the free body, P4 the heavy top, its "
           "nutation periods), |m(t) - m_50(t)| in eps |m0| (attitude, Frobenius distance in "
           "eps):\n" +
           std::string(markdown ? "\n" : "");
    for (const auto& d : r.exact_drift) {
      out += fmt::format("{}{} t = {:.0e} s ({:.3g} periods): {:.2f} eps ({:.2f} eps)\n",
                         markdown ? "- " : "  ", d.problem, d.t_s, d.periods, d.error_eps,
                         d.attitude_eps);
    }
  }
  if (!r.dense.empty()) {
    out += "\nP2 sampled at few and at many output times (one run each; dense output in dopri5 "
           "and dop853, rkf78 lands on every time):\n" +
           std::string(markdown ? "\n" : "");
    for (const auto& d : r.dense) {
      out += fmt::format("{}{} {}: {} times {:.3g} ms ({} evaluations), {} times {:.3g} ms ({} "
                         "evaluations): {:.2f}x\n",
                         markdown ? "- " : "  ", d.method, d.setting, d.few, d.time_few_s * 1e3,
                         d.evals_few, d.many, d.time_many_s * 1e3, d.evals_many,
                         d.time_many_s / d.time_few_s);
    }
  }
  const auto& l = r.long_run;
  out += fmt::format(
      "\nP2 long run, Strang splitting h = 0.01, {} steps: |L| relative error {:.1e} at the end; "
      "largest energy error {:.2e} over [0, 10], {:.2e} over the whole run\n",
      l.steps, l.L_error_end, l.energy_error_10, l.energy_error_1e4);
  return out + "\n";
}

std::string targets(const BenchReport& r, bool markdown) {
  std::string out = markdown ? "| target | measured | limit | |\n|---|---|---|---|\n"
                             : "targets (measured within this run):\n";
  for (const auto& t : r.targets) {
    const std::string m =
        t.measured < 0 ? "not measured" : fmt::format("{:.3g} {}", t.measured, t.unit);
    const std::string verdict = t.met() ? "met" : "missed";
    out += markdown ? fmt::format("| {} | {} | {:g} {} | {} |\n", cell(t.what), m, t.limit, t.unit,
                                  verdict)
                    : fmt::format("  {:<62} {:>16}  limit {:g} {}  {}\n", t.what, m, t.limit,
                                  t.unit, verdict);
  }
  return out;
}
}  // namespace

std::string render_bench(const BenchReport& r, const std::string& format) {
  if (format == "json") {
    nlohmann::ordered_json j;
    j["machine"] = r.machine;
    j["quick"] = r.quick;
    nlohmann::ordered_json runs = nlohmann::ordered_json::array();
    for (const auto& run : r.runs) {
      runs.push_back({{"problem", run.problem},
                      {"method", run.method},
                      {"peer", run.peer},
                      {"setting", run.setting},
                      {"error", run.error},
                      {"energy_error", run.energy_error},
                      {"L_error", run.L_error},
                      {"evaluations", run.evals},
                      {"time_s", run.time_s}});
    }
    j["runs"] = runs;
    nlohmann::ordered_json comps = nlohmann::ordered_json::array();
    for (const auto& c : r.components) {
      comps.push_back({{"group", c.group},
                       {"method", c.method},
                       {"cases", c.cases},
                       {"max_error", c.max_error},
                       {"error_kind", c.error_kind},
                       {"ns_per_call", c.ns_per_call}});
    }
    j["components"] = comps;
    nlohmann::ordered_json dense = nlohmann::ordered_json::array();
    for (const auto& d : r.dense) {
      dense.push_back({{"method", d.method},
                       {"setting", d.setting},
                       {"few_times", d.few},
                       {"many_times", d.many},
                       {"evaluations_few", d.evals_few},
                       {"evaluations_many", d.evals_many},
                       {"time_few_s", d.time_few_s},
                       {"time_many_s", d.time_many_s}});
    }
    j["dense_output"] = dense;
    nlohmann::ordered_json drift = nlohmann::ordered_json::array();
    for (const auto& d : r.exact_drift) {
      drift.push_back({{"problem", d.problem},
                       {"t_s", d.t_s},
                       {"periods", d.periods},
                       {"error_eps", d.error_eps},
                       {"attitude_eps", d.attitude_eps}});
    }
    j["exact_error_against_time"] = drift;
    nlohmann::ordered_json ts = nlohmann::ordered_json::array();
    for (const auto& t : r.targets) {
      ts.push_back({{"target", t.what},
                    {"measured", t.measured},
                    {"limit", t.limit},
                    {"unit", t.unit},
                    {"met", t.met()}});
    }
    j["targets"] = ts;
    return j.dump(1) + "\n";
  }
  if (format == "csv") {
    std::string out = "problem,method,peer,setting,error,energy_error,L_error,evaluations,time_s\n";
    for (const auto& run : r.runs) {
      out += fmt::format("{},{},{},{},{:.6e},{:.6e},{:.6e},{},{:.6e}\n", run.problem, run.method,
                         run.peer ? 1 : 0, run.setting, run.error, run.energy_error, run.L_error,
                         run.evals, run.time_s);
    }
    return out;
  }
  const bool md = format == "markdown";
  std::string out = fmt::format("{}machine: {}{}\n\n", md ? "" : "", r.machine,
                                r.quick ? " (quick run: fewer points and repeats)" : "");
  for (const auto& p : r.problems) out += table(r, p, md);
  out += components(r, md);
  out += targets(r, md);
  return out;
}

void write_bench_plot(const BenchReport& r, const std::filesystem::path& out) {
  draw_with_gnuplot(
      [&](const std::filesystem::path& svg) {
        std::string g = "set encoding utf8\n";
        g += fmt::format(
            "set terminal svg size 1000,{} dynamic font \"Helvetica,13\" background rgb "
            "\"white\"\n",
            360 * ((r.problems.size() + 1) / 2));
        g += fmt::format("set output \"{}\"\n", gnuplot_quote(svg.string()));
        g += fmt::format(
            "set multiplot layout {},2 title \"work-precision: error against run time\"\n",
            (r.problems.size() + 1) / 2);
        g += "set logscale xy\nset format x \"10^{%L}\"\nset format y \"10^{%L}\"\nset grid\n";
        // Room below the lowest point (an error of 0 is drawn at ε/2, on the axis otherwise).
        g += "set offsets 0, 0, graph 0.04, graph 0.06\n";
        // gnuplot's linetypes repeat their eight colours from 9 on (split4 took vern9's yellow):
        // the styles past eight get colours of their own, keeping their point types.
        int linetype = 9;
        for (const char* colour : {"#8c564b", "#e377c2", "#7f7f7f", "#17becf", "#bcbd22"}) {
          g += fmt::format("set linetype {0} lc rgb \"{1}\" pt {0}\n", linetype++, colour);
        }
        g += "set xlabel \"run time [s]\"\nset ylabel \"error at T\"\nset key outside right font "
             "\",10\"\n";
        for (const auto& p : r.problems) {
          std::vector<std::string> methods;
          std::set<std::string> seen;
          for (const auto& run : r.runs) {
            if (run.problem == p.id && seen.insert(run.method).second)
              methods.push_back(run.method);
          }
          g += fmt::format("set title \"{}\" noenhanced\nplot ", gnuplot_quote(p.id));
          // An error of 0 (the closed form equal to 50 digits in every double it gives) has no
          // place on a log scale: it is drawn at ε/2 (half an ulp of 1), below every other
          // point, and its title says so.
          constexpr double kZeroDrawnAt = std::numeric_limits<double>::epsilon() / 2;
          std::vector<std::vector<const bench::Run*>> runs_by_method(methods.size());
          for (const auto& run : r.runs) {
            const auto m = std::find(methods.begin(), methods.end(), run.method);
            if (run.problem == p.id && m != methods.end() && run.error >= 0)
              runs_by_method[static_cast<std::size_t>(m - methods.begin())].push_back(&run);
          }
          for (std::size_t i = 0; i < methods.size(); ++i) {
            const auto& runs = runs_by_method[i];
            const bool peer = !runs.empty() && runs.front()->peer;
            const bool zero = std::any_of(runs.begin(), runs.end(),
                                          [](const bench::Run* run) { return run->error == 0; });
            g += fmt::format(
                "{}'-' using 1:2 with linespoints lw 2 lt {} {} title \"{}{}\" noenhanced",
                i ? ", " : "", style_of(methods[i]), peer ? "dt 2" : "dt 1",
                gnuplot_quote(methods[i]), zero ? " (0, at ε/2)" : "");
          }
          g += "\n";
          for (const auto& runs : runs_by_method) {
            for (const bench::Run* run : runs) {
              g += fmt::format("{:.6e} {:.6e}\n", run->time_s,
                               run->error > 0 ? run->error : kZeroDrawnAt);
            }
            g += "e\n";
          }
        }
        g += "unset multiplot\n";
        return g;
      },
      out);
}

}  // namespace wobble
