// What a simulation's plot draws (render/simulation_output.hpp): angles unwrapped, the tilt
// alone, no exactly-zero error curve, and a bounded number of rows for any run.
#include <catch2/catch.hpp>
#include <cmath>

#include "problem/scene.hpp"
#include "render/simulation_output.hpp"
#include "simulate/scene_helpers.hpp"
#include "simulate/simulation.hpp"

using namespace wobble;

TEST_CASE("a plot shows Euler angles unwrapped, the tilt alone, no exactly-zero error") {
  SceneSetup s = setup_scene(find_scene("heavy-top"), {});
  s.samples = 2001;  // 1 ms apart: psi turns 0.15 rad between samples, so unwrapping is unique
  const SimulationResult r = run(s, "auto");
  const PlotLayout layout = plot_layout(r);
  const std::size_t phi = column(r, "euler_zyz_phi"), psi = column(r, "euler_zyz_psi");
  // Unwrapped: no step of a whole turn between samples, and psi grows by about the spin times
  // the run (150 rad/s over 2 s, plus the slow precession's share).
  for (std::size_t k = 1; k < layout.rows.size(); ++k) {
    REQUIRE(std::abs(layout.rows[k][phi] - layout.rows[k - 1][phi]) < M_PI);
    REQUIRE(std::abs(layout.rows[k][psi] - layout.rows[k - 1][psi]) < M_PI);
  }
  REQUIRE(layout.rows.back()[psi] > 250.0);
  bool tilt_alone = false, zero_error_drawn = false;
  for (const auto& p : layout.panels) {
    tilt_alone = tilt_alone || (p.cols.size() == 1 && p.cols[0] == column(r, "euler_zyz_theta"));
    for (const std::size_t c : p.cols) {
      zero_error_drawn = zero_error_drawn || r.columns[c] == "err_p_psi";
    }
  }
  REQUIRE(tilt_alone);
  REQUIRE_FALSE(zero_error_drawn);
}

TEST_CASE("a plot of 200 000 samples keeps each curve's envelope in a bounded number of rows") {
  const Scene scene = find_scene("tennis-racket");
  SceneSetup s = setup_scene(scene, {});
  s.samples = 200000;
  const SimulationResult r = simulate(s, choose_method(s, "auto"));
  const PlotLayout layout = plot_layout(r);
  // Each bucket keeps its first and last row and each column's extremes.
  CHECK(layout.rows.size() <= kPlotBuckets * (2 + 2 * r.columns.size()));
  CHECK(layout.rows.front()[0] == 0.0);
  CHECK(layout.rows.back()[0] == s.t_end);
  for (std::size_t j = 1; j < r.columns.size(); ++j) {
    if (r.columns[j].find("_phi") != std::string::npos ||
        r.columns[j].find("_psi") != std::string::npos) {
      continue;  // unwrapped in the plot
    }
    double largest = 0.0;
    for (const auto& row : layout.rows) largest = std::max(largest, std::abs(row[j]));
    INFO(r.columns[j]);
    CHECK(largest == r.rows.largest(j));  // the extreme sample is among those drawn
  }
}
