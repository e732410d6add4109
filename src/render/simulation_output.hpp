#pragma once
/// @file
/// A simulation as text (header, table, footer), CSV, JSON, and a gnuplot plot.
///
/// Text prints the digits the run supports: d significant digits of each column's largest value
/// (d = 10 for the closed form and the exact solution; for an integrator, from its estimated
/// error, else from the tolerance), and every other value of the column to the same decimal
/// place. CSV and JSON carry every double to 17 significant digits (for programs; the footer
/// says how far to trust them).
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "simulate/cross_check.hpp"
#include "simulate/simulation.hpp"

namespace wobble {

/// Text handed over a piece at a time (a line, a row), so that a million samples are written
/// without being held: to a file (io/atomic_write) or to stdout.
using Emit = std::function<void(std::string_view)>;

std::string simulation_header(const SceneSetup& s, const SimulationResult& r);
std::string simulation_footer(const SceneSetup& s, const SimulationResult& r);
void emit_simulation_table(const SceneSetup& s, const SimulationResult& r, const Emit& emit);
void emit_simulation_csv(const SimulationResult& r, const Emit& emit);
void emit_simulation_json(const SceneSetup& s, const SimulationResult& r, const Emit& emit);

/// Significant digits the text table prints for this run: those whose place value exceeds the
/// estimated error of each column's largest value, at most 10; fewer than 1 where not even the
/// first is right (simulate refuses the table then).
int printed_digits(const SceneSetup& s, const SimulationResult& r);

/// A plot draws at most this many buckets of samples (each at most 2 + 2 columns rows): beyond
/// it, more samples add nothing a picture 900 pixels wide can show, only memory and file size.
inline constexpr std::size_t kPlotBuckets = 1000;

/// What a plot of a run shows: panels of columns (one per output; the tilt theta on its own;
/// invariant errors as |error| on a log scale, one panel per unit, an error that is exactly zero
/// left out) and the rows with Euler angles phi and psi unwrapped (continuous, no jump at +-pi);
/// past kPlotBuckets samples, of each bucket only the rows where a column is at its extremes.
struct PlotLayout {
  struct Panel {
    std::string title;
    std::vector<std::size_t> cols;
    bool log_scale = false;
  };
  std::vector<Panel> panels;
  std::vector<std::vector<double>> rows;
};
PlotLayout plot_layout(const SimulationResult& r);

/// Every output column against time, panels as plot_layout says, as .svg, .png or .pdf through
/// gnuplot (atomic).
/// @throws std::runtime_error naming the file if gnuplot fails.
void write_simulation_plot(const SceneSetup& s, const SimulationResult& r,
                           const std::filesystem::path& out);

/// The cross-check table: each answer from the key and from simulation, their difference, and
/// what each cost (`key_time_s`: computing the whole key).
std::string cross_check_text(const CrossCheck& c, double key_time_s);

}  // namespace wobble
