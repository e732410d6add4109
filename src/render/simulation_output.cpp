#include "render/simulation_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "render/gnuplot.hpp"

namespace wobble {

namespace {
std::string vec(const Vec3& v, int digits) {
  return fmt::format("({:.{}g}, {:.{}g}, {:.{}g})", v.x(), digits, v.y(), digits, v.z(), digits);
}

bool is_exact(const SimulationResult& r) {
  return r.choice.method == SimMethod::closed_form || r.choice.method == SimMethod::exact;
}

nlohmann::ordered_json json_vec(const Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

// The equations as integrated, in the doubles the run used (written as the shortest text that
// reads back as the same double): a reference computed independently from these differs from
// the rows by the method's error alone. From the scene's decimal inputs it would differ by their
// rounding too, which the motion amplifies with time (README: checking a run yourself).
nlohmann::ordered_json model_json(const SceneSetup& s) {
  const RigidBodyModel& m = s.model;
  nlohmann::ordered_json j;
  j["I_P"] = json_vec(m.I_P);
  j["L0_P"] = json_vec(s.m0_P);
  j["q0_PtoS"] = {s.q0_PtoS.w(), s.q0_PtoS.x(), s.q0_PtoS.y(), s.q0_PtoS.z()};
  j["axes_in_B"] = {json_vec(s.axes_B.col(0)), json_vec(s.axes_B.col(1)),
                    json_vec(s.axes_B.col(2))};
  j["turning_point_B"] = json_vec(s.turning_point_B);
  if (m.gravity) {
    j["mass"] = m.mass_kg;
    j["com_from_pivot_P"] = json_vec(m.d_P_m);
    j["g_S"] = json_vec(m.g_S);
  }
  if (m.torque) {
    j["torque"] = json_vec(m.torque_Nm);
    j["torque_frame"] = m.torque_in_space ? "S" : "P";
    if (s.brake_stops_s) j["brake_stops"] = *s.brake_stops_s;
  }
  if (s.free_flight) {
    j["position0_S"] = json_vec(s.x0_S);
    j["velocity0_S"] = json_vec(s.v0_S);
    j["g_S"] = json_vec(s.g_S);
  }
  return j;
}

// A measured time to three figures, in us, ms or s. Rounded before the unit is chosen: 999.6 us
// is "1 ms", where "{:.3g}" of 999.6 would print "1e+03 us".
std::string seconds(double t) {
  if (t > 0.0 && std::isfinite(t)) {
    const double scale = std::pow(10.0, 2.0 - std::floor(std::log10(t)));
    t = std::round(t * scale) / scale;
  }
  if (t < 1e-3) return fmt::format("{:.3g} us", t * 1e6);
  if (t < 1.0) return fmt::format("{:.3g} ms", t * 1e3);
  if (t < 1e3) return fmt::format("{:.3g} s", t);
  return fmt::format("{:.0f} s", t);
}
}  // namespace

int printed_digits(const SceneSetup& s, const SimulationResult& r) {
  if (is_exact(r)) return 10;
  if (r.error_estimate >= 0.0) {
    // Digits whose place value exceeds the estimated error of the column's largest value.
    const double e = std::max(r.error_estimate, std::numeric_limits<double>::epsilon());
    return std::min(static_cast<int>(std::floor(-std::log10(e))), 10);  // < 1: none is right
  }
  return std::clamp(static_cast<int>(std::floor(-std::log10(s.tolerance))) - 1, 2, 10);
}

std::string simulation_header(const SceneSetup& s, const SimulationResult& r) {
  std::string h = fmt::format("scene {}: {}\n", s.id, s.title);
  if (s.has_mass) {
    h += fmt::format("body: mass {:.10g} kg, turning about its {} at {} m (body frame)\n",
                     s.mass_kg, s.turning_point, vec(s.turning_point_B, 10));
  } else {
    h += "body: tensor given directly, turning about the origin O\n";
  }
  h += fmt::format("principal moments there: {:.10g}, {:.10g}, {:.10g} kg m^2 ({})\n",
                   s.moments[0], s.moments[1], s.moments[2],
                   s.symmetry_axis_last ? "e3 the symmetry axis, as in the heavy-top problem"
                                        : "ascending");
  for (int i = 0; i < 3; ++i) {
    h += fmt::format("  e{} = {} in the body frame\n", i + 1, vec(s.axes_B.col(i), 10));
  }
  h += "effects: ";
  for (std::size_t i = 0; i < s.effects.size(); ++i) h += (i ? "; " : "") + s.effects[i];
  h += "\n";
  h += fmt::format("method: {} ({})\n", name_of(r.choice.method), r.choice.reason);
  for (const auto& n : r.notes) h += "  " + n + "\n";
  h += fmt::format("time: 0 to {:.10g} s, {} samples", s.t_end, s.samples);
  if (!is_exact(r) && r.choice.step_s == 0.0) h += fmt::format("; tolerance {:.0e}", s.tolerance);
  if (r.choice.step_s > 0.0) h += fmt::format("; step {:.6g} s", r.choice.step_s);
  h += "\n";
  return h;
}

void emit_simulation_table(const SceneSetup& s, const SimulationResult& r, const Emit& emit) {
  const int d = std::max(printed_digits(s, r), 1);  // none right is refused before (cli)
  const std::size_t width = static_cast<std::size_t>(d) + 8;
  std::vector<std::size_t> w;
  for (const auto& c : r.columns) w.push_back(std::max(width, c.size() + 1));
  // The error is absolute, a fraction of the column's largest value: print every value of a
  // column to the decimal place of that value's d-th digit, so a small value gets fewer
  // significant digits, and one below half that place (a spin braked to rest, 1.2e-14) is 0.
  std::vector<int> last_place(r.columns.size(), 0);
  for (std::size_t j = 0; j < r.columns.size() && j < r.rows.cols(); ++j) {
    const double largest = r.rows.largest(j);
    last_place[j] = largest > 0.0 ? static_cast<int>(std::floor(std::log10(largest))) - d + 1 : 0;
  }
  std::string line;
  for (std::size_t j = 0; j < r.columns.size(); ++j)
    line += fmt::format("{:>{}}", r.columns[j], w[j]);
  emit(line + "\n");
  line.clear();
  for (std::size_t j = 0; j < r.units.size(); ++j)
    line += fmt::format("{:>{}}", "[" + r.units[j] + "]", w[j]);
  emit(line + "\n");
  r.rows.for_each([&](std::size_t, const std::vector<double>& row) {
    line.clear();
    for (std::size_t j = 0; j < row.size(); ++j) {
      // Errors are printed to 3 digits: they are sizes, not values.
      const bool err = r.columns[j].rfind("err_", 0) == 0;
      if (err) {
        line += fmt::format("{:>{}.3g}", row[j], w[j]);
        continue;
      }
      // The sample times are the run's, not its results: as the header gives t_end, whatever
      // the digits of the results (at 1 digit, 0.15 and 0.25 s would both read 0.2).
      if (j == 0 && r.columns[j] == "t") {
        line += fmt::format("{:>{}.10g}", row[j], w[j]);
        continue;
      }
      const double v = row[j], place = std::pow(10.0, last_place[j]);
      if (std::abs(v) < 0.5 * place) {
        line += fmt::format("{:>{}}", "0", w[j]);
        continue;
      }
      const int digits = static_cast<int>(std::floor(std::log10(std::abs(v)))) - last_place[j] + 1;
      // From half the place up to it, the value rounds to the place itself (0.75 at a place of 1
      // is 1, not 0.8: a digit finer than the place would be one the run does not support).
      if (digits < 1) {
        line += fmt::format("{:>{}.1g}", std::copysign(place, v), w[j]);
        continue;
      }
      line += fmt::format("{:>{}.{}g}", v, w[j], digits);
    }
    emit(line + "\n");
  });
}

namespace {
std::string digits_words(int digits) {
  if (digits < 1) return "not one digit of the samples is right";
  return fmt::format("the table prints {} digit{}", digits, digits == 1 ? "" : "s");
}
}  // namespace

std::string simulation_footer(const SceneSetup& s, const SimulationResult& r) {
  std::string f;
  if (r.invariants.empty()) {
    f += "conserved quantities: none with these effects (a constant body-frame torque, or a "
         "torque with gravity)\n";
  } else {
    f += "conserved quantities, largest deviation from t = 0 over the samples:\n";
    for (const auto& inv : r.invariants) {
      f += fmt::format("  {:<20} {:.2e} {:<9} (relative {:.2e})\n", inv.name, inv.max_abs, inv.unit,
                       inv.relative());
    }
  }
  if (!is_exact(r)) {
    if (r.error_estimate >= 0.0) {
      f += fmt::format(
          "estimated error of the samples: {:.1e} of each column's largest value "
          "(against {}, {} more evaluations); {}\n",
          r.error_estimate, r.error_reference, r.estimate_cost, digits_words(printed_digits(s, r)));
    } else {
      f += fmt::format(
          "estimated error of the samples: not available (no tighter run than rkf78 at {:.0e})\n",
          kMinSceneTolerance);
    }
  }
  f += fmt::format("cost: {} {}", r.cost, r.cost_label);
  if (r.steps > 0) f += fmt::format(", {} steps", r.steps);
  if (r.rejected > 0) f += fmt::format(" ({} rejected)", r.rejected);
  f += fmt::format("; run time {}\n", seconds(r.run_time_s));
  return f;
}

void emit_simulation_csv(const SimulationResult& r, const Emit& emit) {
  std::string line;
  for (std::size_t j = 0; j < r.columns.size(); ++j) {
    line += (j ? "," : "") + r.columns[j] + " [" + r.units[j] + "]";
  }
  emit(line + "\n");
  r.rows.for_each([&](std::size_t, const std::vector<double>& row) {
    line.clear();
    for (std::size_t j = 0; j < row.size(); ++j) line += fmt::format("{}{:.17g}", j ? "," : "", row[j]);
    emit(line + "\n");
  });
}

// The JSON document with its rows written one per line as they are read back (the rest by
// nlohmann-json): the same document as one dump, without holding the rows.
void emit_simulation_json(const SceneSetup& s, const SimulationResult& r, const Emit& emit) {
  nlohmann::ordered_json head;
  head["scene"] = s.id;
  head["title"] = s.title;
  head["method"] = name_of(r.choice.method);
  head["reason"] = r.choice.reason;
  head["effects"] = s.effects;
  head["principal_moments"] = {s.moments[0], s.moments[1], s.moments[2]};
  head["model"] = model_json(s);
  head["t_end"] = s.t_end;
  head["tolerance"] = s.tolerance;
  head["columns"] = r.columns;
  head["units"] = r.units;
  nlohmann::ordered_json inv = nlohmann::ordered_json::array();
  for (const auto& i : r.invariants) {
    inv.push_back({{"name", i.name},
                   {"unit", i.unit},
                   {"max_abs_error", i.max_abs},
                   {"relative_error", i.relative()}});
  }
  nlohmann::ordered_json tail;
  tail["invariants"] = inv;
  tail["cost"] = {{"count", r.cost},
                  {"of", r.cost_label},
                  {"steps", r.steps},
                  {"rejected", r.rejected},
                  {"run_time_s", r.run_time_s}};
  // "{\n ...\n}": the members of each object without its braces, joined around "rows".
  const auto members = [](const nlohmann::ordered_json& o) {
    const std::string text = o.dump(1);
    return text.substr(2, text.size() - 4);
  };
  emit("{\n" + members(head) + ",\n \"rows\": [");
  std::string line;
  r.rows.for_each([&](std::size_t k, const std::vector<double>& row) {
    line = k ? ",\n  [" : "\n  [";
    for (std::size_t j = 0; j < row.size(); ++j) {
      // Shortest round trip, as nlohmann writes a double; non-finite values are null in JSON.
      line += j ? ", " : "";
      if (!std::isfinite(row[j])) {
        line += "null";
        continue;
      }
      const std::size_t at = line.size();
      fmt::format_to(std::back_inserter(line), "{}", row[j]);
      if (line.find_first_of(".e", at) == std::string::npos) line += ".0";  // stays a float
    }
    emit(line + "]");
  });
  emit(std::string(r.rows.empty() ? "]" : "\n ]") + ",\n" + members(tail) + "\n}\n");
}

std::string cross_check_text(const CrossCheck& c, double key_time_s) {
  if (!c.not_compared.empty()) {
    return "not compared: " + c.not_compared + "\n" +
           fmt::format("cost of the key: {} (the whole key, exact and numeric)\n",
                       seconds(key_time_s));
  }
  std::string out = fmt::format("{:<18} {:>20} {:>20} {:>11} {:>11}\n", "answer",
                                "key (closed form)", "simulation", "difference", "relative");
  for (const auto& r : c.rows) {
    const double d = r.simulated - r.key;
    out += fmt::format("{:<18} {:>20.12g} {:>20.12g} {:>11.2e} {:>11.2e}  {}\n", r.name, r.key,
                       r.simulated, d, std::abs(d) / std::max(std::abs(r.key), 1e-300), r.unit);
  }
  out +=
      fmt::format("cost of the key: {} (the whole key, exact and numeric)\n", seconds(key_time_s));
  out += fmt::format("cost of the simulation: {} right-hand-side evaluations, {} ({})\n",
                     c.rhs_evals, seconds(c.simulation_time_s), c.method);
  return out;
}

namespace {
bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// An Euler angle's column made continuous, sample by sample: a jump over pi between samples
// is the angle wrapping at +-pi, so a whole turn is added back (the table keeps (-pi, pi]; the
// plot shows phi and psi growing as they do).
struct Unwrapper {
  double offset = 0.0, previous = 0.0;
  bool started = false;
  double operator()(double v) {
    if (started) offset -= 2 * M_PI * std::round((v + offset - previous) / (2 * M_PI));
    started = true;
    previous = v + offset;
    return previous;
  }
};

using Panel = PlotLayout::Panel;

// Panels: one per output (the part of a column's name before _x/_y/_z/_phi/_psi), the tilt
// theta on its own (nutation is invisible beside growing phi and psi), invariant errors on a
// log scale per unit, an error column that is exactly zero left out.
std::vector<Panel> plot_panels(const SimulationResult& r) {
  std::vector<Panel> panels;
  for (std::size_t j = 1; j < r.columns.size(); ++j) {
    std::string base = r.columns[j];
    bool log_scale = false;
    if (ends_with(base, "_theta")) {
      base = "tilt θ (" + base.substr(0, base.size() - 6) + ")";
    } else if (base.rfind("err_", 0) == 0) {
      if (r.rows.largest(j) == 0.0) continue;  // conserved exactly: nothing to draw
      base = "|invariant error| [" + r.units[j] + "]";
      log_scale = true;
    } else {
      for (const char* suffix : {"_x", "_y", "_z", "_phi", "_psi"}) {
        if (ends_with(base, suffix)) {
          base.resize(base.size() - std::string(suffix).size());
          if (std::string(suffix) == "_phi" || std::string(suffix) == "_psi") {
            base += " (unwrapped)";
          }
          break;
        }
      }
    }
    auto it = std::find_if(panels.begin(), panels.end(),
                           [&](const Panel& p) { return p.title == base; });
    if (it == panels.end()) {
      panels.push_back({base, {}, log_scale});
      it = panels.end() - 1;
    }
    it->cols.push_back(j);
  }
  return panels;
}
}  // namespace

PlotLayout plot_layout(const SimulationResult& r) {
  PlotLayout layout{plot_panels(r), {}};
  std::vector<std::size_t> angles;
  for (std::size_t j = 1; j < r.columns.size(); ++j) {
    if (ends_with(r.columns[j], "_phi") || ends_with(r.columns[j], "_psi")) angles.push_back(j);
  }
  std::vector<Unwrapper> unwrap(angles.size());
  // Up to kPlotBuckets buckets of consecutive samples; of each, the first and last rows and
  // those where a column is smallest or largest, so every curve keeps its envelope.
  const std::size_t n = r.rows.size();
  const std::size_t per_bucket = std::max<std::size_t>(1, (n + kPlotBuckets - 1) / kPlotBuckets);
  std::vector<std::vector<double>> bucket;
  const auto flush = [&] {
    if (bucket.empty()) return;
    std::vector<std::size_t> keep{0, bucket.size() - 1};
    for (std::size_t j = 1; j < r.rows.cols() && per_bucket > 1; ++j) {
      std::size_t lo = 0, hi = 0;
      for (std::size_t i = 1; i < bucket.size(); ++i) {
        if (bucket[i][j] < bucket[lo][j]) lo = i;
        if (bucket[i][j] > bucket[hi][j]) hi = i;
      }
      keep.push_back(lo);
      keep.push_back(hi);
    }
    std::sort(keep.begin(), keep.end());
    keep.erase(std::unique(keep.begin(), keep.end()), keep.end());
    for (const std::size_t i : keep) layout.rows.push_back(bucket[i]);
    bucket.clear();
  };
  r.rows.for_each([&](std::size_t, const std::vector<double>& row) {
    std::vector<double> shown = row;
    for (std::size_t a = 0; a < angles.size(); ++a) shown[angles[a]] = unwrap[a](row[angles[a]]);
    bucket.push_back(std::move(shown));
    if (bucket.size() == per_bucket) flush();
  });
  flush();
  return layout;
}

void write_simulation_plot(const SceneSetup& s, const SimulationResult& r,
                           const std::filesystem::path& out) {
  const PlotLayout layout = plot_layout(r);
  const auto& panels = layout.panels;
  const auto& rows = layout.rows;
  draw_with_gnuplot(
      [&](const std::filesystem::path& file) {
        std::string g = "set encoding utf8\n";
        g += gnuplot_terminal(file, 900, static_cast<int>(std::max<std::size_t>(1, panels.size()) * 240));
        g += fmt::format("set output \"{}\"\n", gnuplot_quote(file.string()));
        g += fmt::format("set multiplot layout {},1 title \"{}\" noenhanced\n", panels.size(),
                         gnuplot_quote(s.id + ": " + s.title));
        // The same margins in every panel, so their time axes line up.
        g += "set grid\nset key outside right\nset xlabel \"t [s]\"\n"
             "set lmargin at screen 0.12\nset rmargin at screen 0.72\n";
        g += "$data << EOD\n";
        for (const auto& row : rows) {
          for (std::size_t j = 0; j < row.size(); ++j)
            g += fmt::format("{}{:.17g}", j ? " " : "", row[j]);
          g += "\n";
        }
        g += "EOD\n";
        for (const auto& p : panels) {
          g += fmt::format("set ylabel \"[{}]\" noenhanced\n", gnuplot_quote(r.units[p.cols[0]]));
          g += fmt::format("set title \"{}\" noenhanced\n", gnuplot_quote(p.title));
          g += p.log_scale ? "set logscale y\nset format y \"%.0e\"\n" : "unset logscale y\nset format y \"% h\"\n";
          g += "plot ";
          for (std::size_t k = 0; k < p.cols.size(); ++k) {
            const std::size_t c = p.cols[k] + 1;
            // On a log scale, |error|; a sample that is exactly 0 is left out (log 0).
            const std::string y =
                p.log_scale ? fmt::format("(abs(${0}) > 0 ? abs(${0}) : NaN)", c) : fmt::format("{}", c);
            g += fmt::format("{}$data using 1:{} with lines lw 2 title \"{}\" noenhanced",
                             k ? ", " : "", y, gnuplot_quote(r.columns[p.cols[k]]));
          }
          g += "\n";
        }
        g += "unset multiplot\n";
        return g;
      },
      out);
}

}  // namespace wobble
