// Scenes end to end (load, set up, choose, simulate): every example runs and keeps its
// invariants; methods agree with each other and with independent computations.
#include <fmt/format.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "core/exact_free_body.hpp"
#include "solvers/catalog.hpp"
#include "problem/scene.hpp"
#include "problem/values.hpp"
#include "simulate/cross_check.hpp"
#include "simulate/invariants.hpp"
#include "simulate/simulation.hpp"
#include "simulate/scene_helpers.hpp"
#include "solvers/solve.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();

// Largest relative error each method's invariants may show: exact methods a few eps per
// evaluation (64 eps); adaptive methods the per-step tolerance accumulated over their steps
// (linear accumulation bound: tol * steps, at least tol).
double invariant_bound(const SceneSetup& s, const SimulationResult& r) {
  if (r.choice.method == SimMethod::closed_form || r.choice.method == SimMethod::exact)
    return 64 * kEps;
  return s.tolerance * static_cast<double>(std::max<std::int64_t>(r.steps, 1));
}
}  // namespace

TEST_CASE("every example scene runs with auto and with Fehlberg 7(8), invariants kept") {
  for (const std::string id :
       {"tennis-racket", "flying-plate", "thrown-plate", "heavy-top", "spin-up", "wheel-brake"}) {
    const SceneSetup s = setup_scene(find_scene(id), std::vector<std::string>{});
    for (const std::string method : {"auto", "rkf78"}) {
      const SimulationResult r = run(s, method);
      INFO(id << " with " << method << " (" << name_of(r.choice.method) << ")");
      REQUIRE(r.rows.size() == static_cast<std::size_t>(s.samples));
      REQUIRE(r.rows.back()[0] == s.t_end);
      REQUIRE(r.cost > 0);
      for (const auto& inv : r.invariants) {
        INFO(inv.name << ": relative " << inv.relative());
        REQUIRE(inv.relative() <= invariant_bound(s, r));
      }
    }
  }
}

TEST_CASE("auto picks the closed form, the exact solution, or an adaptive pair, and says why") {
  REQUIRE(choose_method(setup_scene(find_scene("flying-plate"), {}), "auto").method ==
          SimMethod::closed_form);
  REQUIRE(choose_method(setup_scene(find_scene("tennis-racket"), {}), "auto").method ==
          SimMethod::exact);
  const SceneSetup top = setup_scene(find_scene("heavy-top"), {});
  const MethodChoice exact = choose_method(top, "auto");
  REQUIRE(exact.method == SimMethod::exact);
  REQUIRE_THAT(exact.reason, Catch::Contains("heavy symmetric top"));
  // Asked for more than the closed form's rounding allows (a tolerance below its 16 eps and
  // more): Verner 9(8), and why.
  SceneSetup strict = top;
  strict.tolerance = 1e-17;
  const MethodChoice rounding = choose_method(strict, "auto");
  REQUIRE(rounding.method == SimMethod::vern9);
  REQUIRE_THAT(rounding.reason, Catch::Contains("of rounding over the run"));
  // The same top with its centre of mass off the axle is no symmetric top: Verner 9(8).
  SceneSetup off_axis = top;
  off_axis.model.d_P_m.x() = 1e-3;
  const MethodChoice c = choose_method(off_axis, "auto");
  REQUIRE(c.method == SimMethod::vern9);
  REQUIRE_THAT(c.reason, Catch::Contains("Verner"));
  REQUIRE_THROWS_WITH(choose_method(off_axis, "exact"), Catch::Contains("no symmetric top"));
  // Tilted from upright by less than 1.5e-154 rad but not 0: the closed form would square the
  // tilt to 0 (it made NaN); Verner 9(8), and the exact solution refused with the reason.
  const SceneSetup hair = setup_scene(find_scene("heavy-top"), {"theta0=1e-200", "psidot0=10"});
  REQUIRE(choose_method(hair, "auto").method == SimMethod::vern9);
  REQUIRE_THROWS_WITH(choose_method(hair, "exact"), Catch::Contains("within 1.5e-154 rad"));
  SceneSetup loose = off_axis;
  loose.tolerance = 1e-4;  // loose: Verner is level with the other pairs there, not dearer
  REQUIRE(choose_method(loose, "auto").method == SimMethod::vern9);
}

TEST_CASE(
    "the heavy-top scene's exact solution and Fehlberg 7(8) at 1e-13 agree, the body above or "
    "below its pivot") {
  // The default (cusps), loops, a hanging start, and starts 1e-5 rad from the vertical and
  // 2e-6 rad from hanging straight down (where p_phi and p_psi nearly cancel). (A top too slow
  // to sleep released near upright is hard 16's: its fall amplifies Fehlberg's own errors past
  // the bound below, which assumes they only add up.)
  const std::vector<std::vector<std::string>> sets{{},
                                                   {"phidot0=-3"},
                                                   {"theta0=150deg", "psidot0=20"},
                                                   {"theta0=0.001deg"},
                                                   {"theta0=179.9999deg", "psidot0=5"}};
  std::vector<std::pair<std::string, SceneSetup>> tops;
  for (const auto& set : sets)
    tops.emplace_back(set.empty() ? "defaults" : set.front(),
                      setup_scene(find_scene("heavy-top"), set));
  // The same disc written below the pivot along its axle, the body's z (as a cone on its apex
  // is written: the cone shape puts its apex above its centre), tilted 150 deg: the disc stands
  // 30 deg from upright above the pivot. The axle e3 is taken from the pivot toward the centre
  // of mass, so this is a heavy top the exact solution serves, spun at -psidot0 about e3.
  Scene below = find_scene("heavy-top");
  below.model.body.shapes.at(0).center = {"0", "0", "-l"};
  tops.emplace_back("below the pivot",
                    setup_scene(below, std::vector<std::string>{"theta0=150deg"}));
  for (auto& [name, s] : tops) {
    // Vectors, not Euler angles: at 2e-6 rad from the pole phi and psi themselves are
    // ill-conditioned (1/sin(theta)), whatever computes them.
    s.outputs = {"omega_body", "e1_space", "e3_space"};
    INFO(name);
    REQUIRE(choose_method(s, "auto").method == SimMethod::exact);
    const SimulationResult exact = run(s, "exact");
    SceneSetup tight = s;
    tight.tolerance = 1e-13;
    const SimulationResult rk = run(tight, "rkf78");
    REQUIRE(exact.rows.size() == rk.rows.size());
    REQUIRE_THAT(exact.notes.front(), Catch::Contains("theta nods between"));
    // Fehlberg 7(8) at 1e-13 per step: each accepted step's error measure bounds each momentum
    // component's error by tol times the run's momentum scale and each quaternion component's by
    // tol, so omega = I^-1 m moves by up to sqrt(3) tol scale / I_min and a unit vector turned by
    // q by up to 4 tol (|d(q v q*)| <= 2 |dq|, |dq| <= 2 tol). The errors add along the run (no
    // contraction); the exact solution is far closer.
    REQUIRE(rk.steps > 0);
    const double steps = static_cast<double>(rk.steps);
    const double kOmegaBound =
        steps * std::sqrt(3.0) * tight.tolerance * momentum_scale(s) / s.moments.minCoeff();
    const double kVectorBound = steps * 4 * tight.tolerance;
    for (std::size_t k = 0; k < exact.rows.size(); ++k) {
      for (std::size_t j = 1; j < exact.columns.size(); ++j) {
        if (exact.columns[j].rfind("err_", 0) == 0) continue;
        const double d = exact.rows[k][j] - rk.rows[k][j];
        const bool omega = exact.columns[j].rfind("omega", 0) == 0;
        INFO(exact.columns[j] << " at row " << k);
        REQUIRE_THAT(d, WithinAbs(0.0, omega ? kOmegaBound : kVectorBound));
      }
    }
  }
}

TEST_CASE("closed form, exact solver, integrators and splittings agree on a symmetric body") {
  const SceneSetup s = setup_scene(find_scene("flying-plate"), {});
  const SimulationResult ref = run(s, "closed_form");
  // Bounds: exact ~1e-15; rkf78, dop853, vern9 and dopri5 at 1e-10 over ~100-1000 steps
  // (<= 1e-8 of the unit vectors; dopri5 and dop853 samples from their dense output, whose
  // error is of the steps' size); splittings at the step from the tolerance rule, whose error
  // is about the tolerance times the turns made (~2 here) -> 1e-8 as well; rk4 likewise.
  for (const std::string m :
       {"exact", "rkf78", "dopri5", "dop853", "vern9", "rk4", "split2", "split4"}) {
    const SimulationResult r = run(s, m);
    INFO(m);
    for (const std::string c : {"e3_space_x", "e3_space_y", "omega_body_x", "omega_body_z"}) {
      const std::size_t j = column(ref, c);
      const double bound = m == "exact" ? 64 * kEps * 10 : 1e-7 * 10;  // omega is ~10 rad/s
      for (std::size_t k = 0; k < ref.rows.size(); ++k) {
        REQUIRE_THAT(r.rows[k][j], WithinAbs(ref.rows[k][j], bound));
      }
    }
  }
}

TEST_CASE("free flight rotates exactly as torque-free, and the centre of mass flies a parabola") {
  const Scene thrown = find_scene("thrown-plate");
  Scene still = thrown;
  still.free_flight.reset();
  const SceneSetup a = setup_scene(thrown, {}), b = setup_scene(still, {});
  const SimulationResult ra = run(a, "auto"), rb = run(b, "auto");
  const std::size_t e3x = column(ra, "e3_space_x");
  for (std::size_t k = 0; k < ra.rows.size(); ++k) {
    // The same rotational model, the same method: identical to the bit.
    REQUIRE(ra.rows[k][e3x] == rb.rows[k][column(rb, "e3_space_x")]);
    const double t = ra.rows[k][0];
    // Launch from 1.5 m at 6 m/s, 30 degrees up, g = 9.81 (the scene's defaults).
    const double vx = 6 * std::cos(M_PI / 6), vz = 6 * std::sin(M_PI / 6);
    REQUIRE_THAT(ra.rows[k][column(ra, "com_position_x")], WithinAbs(vx * t, 8 * kEps * 5));
    REQUIRE_THAT(ra.rows[k][column(ra, "com_position_z")],
                 WithinAbs(1.5 + vz * t - 0.5 * 9.81 * t * t, 8 * kEps * 5));
  }
  // Total energy (rotation + flight + height) is constant along the flight.
  const std::size_t E = column(ra, "total_energy");
  for (const auto& row : ra.rows) REQUIRE_THAT(row[E], WithinRel(ra.rows[0][E], 16 * kEps));
}

TEST_CASE("without gravity there is no gravity term: energy and L in space stay constant") {
  const SceneSetup s = setup_scene(find_scene("tennis-racket"), {});
  const SimulationResult r = run(s, "rkf78");
  REQUIRE(r.invariants.size() == 3);  // rotational energy, |L|, L in space
  for (const auto& inv : r.invariants) REQUIRE(inv.relative() <= invariant_bound(s, r));
  // With gravity about a pivot below the centre, L in space is not conserved (only L_z).
  Scene pivoted = find_scene("tennis-racket");
  pivoted.gravity = GravitySpec{"9.81", {"0", "0", "-0.1"}};
  const SceneSetup g = setup_scene(pivoted, {});
  REQUIRE(g.model.gravity);
  REQUIRE(run(g, "auto").invariants[0].name == "total_energy");
}

namespace {
double answer_value(const Key& key, const std::string& name) {
  for (const auto& part : key.parts) {
    for (const auto& a : part.answers) {
      if (a.name == name) return a.value.data.at(0);
    }
  }
  throw std::logic_error("no answer " + name);
}
}  // namespace

TEST_CASE(
    "tennis racket: the simulated flips come at the key's flip interval, the exact half period") {
  // The problem tennis-racket and the scene tennis-racket are the same body and spin: the scene
  // is run at the problem's values (its names: w for omega, wobble for epsilon).
  const Problem problem = find_problem("tennis-racket");
  const sym::Values v = parameter_values(problem, {});
  const Key key = solve(problem, v);
  Scene sc = find_scene("tennis-racket");
  sc.samples = 4001;
  sc.tolerance = 1e-12;
  const SceneSetup s =
      setup_scene(sc, std::vector<std::string>{
                          fmt::format("m={:.17g}", v.at("m")), fmt::format("a={:.17g}", v.at("a")),
                          fmt::format("b={:.17g}", v.at("b")), fmt::format("c={:.17g}", v.at("c")),
                          fmt::format("w={:.17g}", v.at("omega")),
                          fmt::format("wobble={:.17g}", v.at("epsilon"))});
  const SimulationResult r = run(s, "rkf78");
  const double half = ExactFreeMotion(s.model.I_P, s.m0_P, s.q0_PtoS).period_s() / 2;
  // The key's exact form (GiNaC, 40 digits) and core's exact solution: two routes, same number.
  REQUIRE_THAT(answer_value(key, "flip_interval"), WithinRel(half, 64 * kEps));
  const std::size_t wy = column(r, "omega_body_y");
  std::vector<double> crossings;
  for (std::size_t k = 1; k < r.rows.size(); ++k) {
    const double a = r.rows[k - 1][wy], b = r.rows[k][wy];
    if ((a > 0) != (b > 0)) {
      const double t0 = r.rows[k - 1][0], t1 = r.rows[k][0];
      crossings.push_back(t0 + (t1 - t0) * a / (a - b));
    }
  }
  REQUIRE(crossings.size() >= 4);
  // Near the separatrix (k'^2 = 4e-7) the flip time is sensitive to the state: the
  // integration's 1e-12 per step moves it by ~1e-9 relative; linear interpolation at a zero of
  // sn is O(dt^3) accurate (dt = 2.5 ms): 1e-6 relative bounds both.
  for (std::size_t i = 1; i < crossings.size(); ++i) {
    REQUIRE_THAT(crossings[i] - crossings[i - 1], WithinRel(half, 1e-6));
  }
}

TEST_CASE("heavy top agrees with an independent integration of Lagrange's equations") {
  // Independent model: the Euler-angle Lagrangian of the heavy symmetric top,
  // L = I1/2 (phidot^2 sin^2 th + thdot^2) + I3/2 (psidot + phidot cos th)^2 - M g l cos th,
  // with p_psi = I3 w3 and p_phi conserved; integrated for (th, thdot, phi) with Boost.Odeint.
  const SceneSetup s = setup_scene(find_scene("heavy-top"), {});
  const SimulationResult r = run(s, "auto");
  const double M = 0.5, R = 0.05, l = 0.08, g = 9.81, spin = 150, th0 = M_PI / 6;
  const double I3 = M * R * R / 2, I1 = M * R * R / 4 + M * l * l;
  const double w3 = spin, pphi = I3 * w3 * std::cos(th0);  // phidot(0) = thdot(0) = 0
  using State = std::array<double, 3>;
  auto rhs = [&](const State& x, State& d, double) {
    const double th = x[0], st = std::sin(th), ct = std::cos(th);
    const double phidot = (pphi - I3 * w3 * ct) / (I1 * st * st);
    d[0] = x[1];
    d[1] = (I1 * phidot * phidot * st * ct - I3 * w3 * phidot * st + M * g * l * st) / I1;
    d[2] = phidot;
  };
  namespace ode = boost::numeric::odeint;
  ode::controlled_runge_kutta<ode::runge_kutta_fehlberg78<State>> stepper(
      ode::default_error_checker<double, ode::array_algebra, ode::default_operations>(1e-13,
                                                                                      1e-13));
  State x{th0, 0.0, 0.0};
  double t = 0;
  const std::size_t th = column(r, "euler_zyz_theta"), ph = column(r, "euler_zyz_phi");
  for (const auto& row : r.rows) {
    if (row[0] > t) {
      ode::integrate_adaptive(stepper, rhs, x, t, row[0], 1e-4);
      t = row[0];
    }
    // Both runs are controlled to <= 1e-10 per step over ~1000 steps; the angles agree to
    // 1e-7 rad (measured ~1e-9).
    REQUIRE_THAT(row[th], WithinAbs(x[0], 1e-7));
    REQUIRE_THAT(std::remainder(row[ph] - x[2], 2 * M_PI), WithinAbs(0.0, 1e-7));
  }
}

namespace {
// The heavy-top scene at the heavy-top problem's values (the same disc, pivot and start).
Scene heavy_top_scene_at(const sym::Values& v, int samples) {
  Scene sc = find_scene("heavy-top");
  sc.model.parameters.clear();  // the values below are numbers: no parameters needed
  const auto num = [](double x) { return fmt::format("{:.17g}", x); };
  sc.model.body.shapes.at(0).mass = num(v.at("M"));
  sc.model.body.shapes.at(0).sizes = {num(v.at("R"))};
  sc.model.body.shapes.at(0).center = {"0", "0", num(v.at("l"))};
  sc.gravity->g = num(v.at("g"));
  sc.orientation.euler = {"0", num(v.at("theta0")), "0"};
  sc.samples = samples;
  sc.tolerance = 1e-12;
  return sc;
}

// Every interior extremum of column j: the vertex of the parabola through the three samples
// around it.
std::vector<double> extrema(const SimulationResult& r, std::size_t j) {
  std::vector<double> out;
  for (std::size_t k = 1; k + 1 < r.rows.size(); ++k) {
    const double a = r.rows[k - 1][j], b = r.rows[k][j], c = r.rows[k + 1][j];
    if ((b - a) * (c - b) < 0) {
      const double curvature = a - 2 * b + c;
      out.push_back(b - (c - a) * (c - a) / (8 * curvature));
    }
  }
  return out;
}
}  // namespace

TEST_CASE("heavy top: the scene nods between the key's nutation limits") {
  const Problem problem = find_problem("heavy-top");
  const sym::Values v = parameter_values(problem, {});
  const Key key = solve(problem, v);
  Scene sc = heavy_top_scene_at(v, 20001);
  sc.omega = {"0", "0", fmt::format("{:.17g}", v.at("psidot0"))};  // released at rest
  const SimulationResult r = run(setup_scene(sc, std::vector<std::string>{}), "rkf78");
  const auto turns = extrema(r, column(r, "euler_zyz_theta"));
  REQUIRE(turns.size() >= 10);  // the nutation period is about 0.2 s
  const double lo = answer_value(key, "theta_min"), hi = answer_value(key, "theta_max");
  // Bounds: the run's tolerance 1e-12 per step over ~1e4 steps (1e-8), and the parabola's error
  // at a vertex, about |d3 theta/dt3| h^3 with d3 theta/dt3 ~ (hi - lo) (2 pi / 0.2 s)^3 and
  // h = 1e-4 s (4e-8).
  for (const double th : turns) {
    const double limit = std::abs(th - lo) < std::abs(th - hi) ? lo : hi;
    REQUIRE_THAT(th, WithinAbs(limit, 1e-7));
  }
}

TEST_CASE("heavy top: started at the key's steady precession, it precesses steadily") {
  const Problem problem = find_problem("heavy-top");
  const sym::Values v = parameter_values(problem, {});
  const Key key = solve(problem, v);
  for (const std::string rate : {"phidot_slow", "phidot_fast"}) {
    INFO(rate);
    const double phidot = answer_value(key, rate), th0 = v.at("theta0");
    Scene sc = heavy_top_scene_at(v, 201);
    sc.t_end = "0.5";
    // omega in the body frame at psi = 0 (Taylor): (-phidot sin(theta), thetadot, w3).
    sc.omega = {fmt::format("{:.17g}", -phidot * std::sin(th0)), "0",
                fmt::format("{:.17g}", answer_value(key, "omega3"))};
    const SimulationResult r = run(setup_scene(sc, std::vector<std::string>{}), "rkf78");
    const std::size_t th = column(r, "euler_zyz_theta"), ph = column(r, "euler_zyz_phi");
    // Steady: theta stays put and phi advances uniformly, to the run's accumulated tolerance
    // (1e-12 per step over a few thousand steps).
    for (const auto& row : r.rows) {
      REQUIRE_THAT(row[th], WithinAbs(th0, 1e-8));
      REQUIRE_THAT(std::remainder(row[ph] - phidot * row[0], 2 * M_PI), WithinAbs(0.0, 1e-8));
    }
  }
}

TEST_CASE("cross-check: simulated dynamic answers agree with the closed forms") {
  for (const std::string id : {"rect-solid", "flying-plate", "flying-square-plate"}) {
    for (const std::string alpha : {"5deg", "40deg", "80deg"}) {
      const Problem p = find_problem(id);
      const sym::Values v = parameter_values(p, {"alpha=" + alpha});
      const CrossCheck c = cross_check_torque_free(p, v, solve(p, v));
      REQUIRE(c.rows.size() == 4);
      for (const auto& row : c.rows) {
        INFO(id << " alpha " << alpha << ": " << row.name << " key " << row.key << " simulated "
                << row.simulated);
        // Fehlberg 7(8) at 1e-12 per step over ~4000 steps: values within ~4e-9 relative;
        // a rate from the turn over the run, and a peak time from a parabola (error
        // O(dt^3)), stay within it too (measured <= 4e-12). Bound 1e-8.
        REQUIRE_THAT(row.simulated, WithinRel(row.key, 1e-8));
      }
    }
  }
}

TEST_CASE("the error estimate of an integrator's samples matches its actual error") {
  // Heavy top with Dormand-Prince at 1e-6: the estimate compares with rkf78 at 1e-8; the truth
  // here is rkf78 at 1e-13. The two must agree within the reference's own error (~1e-7 of
  // the estimate's size or less), so within a factor 1.5.
  Scene sc = find_scene("heavy-top");
  sc.tolerance = 1e-6;
  const SceneSetup s = setup_scene(sc, std::vector<std::string>{});
  const SimulationResult loose = run(s, "dopri5");
  SceneSetup tight = s;
  tight.tolerance = 1e-13;
  const SimulationResult truth = run(tight, "rkf78");
  double actual = 0.0;
  for (std::size_t j = 1; j < loose.columns.size(); ++j) {
    if (loose.columns[j].rfind("err_", 0) == 0) continue;
    double scale = 0.0, diff = 0.0;
    for (std::size_t k = 0; k < loose.rows.size(); ++k) {
      scale = std::max(scale, std::abs(truth.rows[k][j]));
      diff =
          std::max(diff, std::abs(std::remainder(loose.rows[k][j] - truth.rows[k][j], 2 * M_PI)));
    }
    actual = std::max(actual, diff / scale);
  }
  INFO("estimate " << loose.error_estimate << ", actual " << actual);
  REQUIRE(loose.error_estimate > 0.0);
  REQUIRE_THAT(loose.error_estimate, WithinRel(actual, 0.5));
  // Near the separatrix the estimate is what tells the truth: rkf78 at 1e-14 on the tennis
  // racket with wobble 0.001 is accurate to ~1e-7 only (checked against a 30-digit Taylor
  // integration with mpmath while developing), not to 1e-14.
  Scene racket = find_scene("tennis-racket");
  racket.tolerance = 1e-14;
  const SceneSetup rs = setup_scene(racket, std::vector<std::string>{"wobble=0.001"});
  const SimulationResult rr = run(rs, "rkf78");
  REQUIRE(rr.error_estimate > 1e-9);
  REQUIRE(rr.error_reference == "the exact solution");
}

TEST_CASE("a brake stops the spin about its axis and never turns the wheel backwards") {
  Scene sc = find_scene("wheel-brake");
  sc.t_end = "10";  // well past the stop (4 s at the defaults)
  sc.samples = 201;
  const SceneSetup s = setup_scene(sc, std::vector<std::string>{});
  REQUIRE(s.brake_stops_s.has_value());
  // I3 w3 / tau: the cylinder (2 kg, R 0.2 m) has I3 = 0.04 kg m^2, w3 = 20 rad/s, tau 0.2 N m.
  REQUIRE_THAT(*s.brake_stops_s, WithinRel(0.04 * 20 / 0.2, 4 * kEps));
  // auto (Verner 9(8), landing on every sample), Fehlberg 7(8) likewise, and DOP853 (samples
  // before and after the stop from its dense output, the stop itself landed on).
  for (const std::string method : {"auto", "rkf78", "dop853"}) {
    const SimulationResult r = run(s, method);
    const std::size_t wz = column(r, "omega_body_z");
    REQUIRE(r.rows.size() == 201);
    for (const auto& row : r.rows) {
      INFO(method << ", t = " << row[0]);
      // Before the stop w3 falls linearly (tau / I3 = 5 rad/s^2), to the run's tolerance
      // (1e-9 relative, 20 rad/s: a few 1e-8); after it, exactly zero.
      const double want = std::max(0.0, 20.0 - 5.0 * row[0]);
      REQUIRE_THAT(row[wz], WithinAbs(want, 1e-7));
      if (row[0] >= *s.brake_stops_s) REQUIRE(row[wz] == 0.0);
    }
  }
  // Refused: a brake that would speed the spin up, or one not about a symmetry axis.
  Scene faster = find_scene("wheel-brake");
  faster.torque->value = {"0", "0", "brake"};
  REQUIRE_THROWS_WITH(setup_scene(faster, std::vector<std::string>{}),
                      Catch::Contains("opposes the spin"));
  Scene sideways = find_scene("wheel-brake");
  sideways.torque->value = {"-brake", "0", "-brake"};
  REQUIRE_THROWS_WITH(setup_scene(sideways, std::vector<std::string>{}),
                      Catch::Contains("symmetry axis"));
}

TEST_CASE("the heavy-top scene numbers its axes as the problem does: e3 is the axle") {
  const SceneSetup s = setup_scene(find_scene("heavy-top"), {});
  REQUIRE(s.symmetry_axis_last);
  // The disc's axle is the body's z axis; its moment about the pivot is the unique one.
  REQUIRE_THAT((s.axes_B.col(2) - Vec3::UnitZ()).norm(), WithinAbs(0.0, 4 * kEps));
  REQUIRE(s.moments[0] == s.moments[1]);
  REQUIRE(s.moments[2] < s.moments[0]);
  REQUIRE_THAT(s.axes_B.determinant(), WithinAbs(1.0, 4 * kEps));  // still right-handed
}

TEST_CASE("a top's axle e3 points from the pivot toward the centre of mass, either side") {
  // The disc above and below the pivot, far from it (the axle's moment the smallest: the pair
  // of equal moments is e1, e2 after a turn) and near it (l < R/2: the axle's moment the
  // largest, e3 already): e3 is +z or -z of the body, whichever reaches the centre of mass,
  // d = l e3 with l > 0, and the exact solution serves every one.
  for (const std::string l : {"0.08", "0.01"}) {
    for (const std::string side : {"l", "-l"}) {
      Scene sc = find_scene("heavy-top");
      sc.model.body.shapes.at(0).center = {"0", "0", side};
      const SceneSetup s = setup_scene(sc, std::vector<std::string>{"l=" + l});
      INFO("l = " << l << ", centre at z = " << side);
      const double z = side == "l" ? 1.0 : -1.0;
      REQUIRE_THAT((s.axes_B.col(2) - z * Vec3::UnitZ()).norm(), WithinAbs(0.0, 4 * kEps));
      REQUIRE_THAT(s.model.d_P_m.z(), WithinRel(std::stod(l), 4 * kEps));
      REQUIRE_THAT(s.axes_B.determinant(), WithinAbs(1.0, 4 * kEps));
      REQUIRE(s.moments[0] == s.moments[1]);
      REQUIRE(choose_method(s, "auto").method == SimMethod::exact);
    }
  }
}

TEST_CASE("rows past the in-memory limit go to a temporary file and come back unchanged") {
  // 26 columns: 40 330 rows fit in 2^20 numbers; 100 000 rows spill, and reads interleave with
  // appends (the error estimate reads row k while rows are still arriving elsewhere).
  RowStore store;
  const std::size_t cols = 26, rows = 100000;
  const auto value = [](std::size_t k, std::size_t j) {
    return std::ldexp(static_cast<double>(k * 31 + j), -7) - 1000.0;
  };
  std::vector<double> row(cols);
  for (std::size_t k = 0; k < rows; ++k) {
    for (std::size_t j = 0; j < cols; ++j) row[j] = value(k, j);
    store.append(row);
    if (k % 9973 == 0) REQUIRE(store[k / 2][3] == value(k / 2, 3));
  }
  REQUIRE(store.size() == rows);
  CHECK(store.back()[cols - 1] == value(rows - 1, cols - 1));
  std::size_t seen = 0;
  bool equal = true;
  store.for_each([&](std::size_t k, const std::vector<double>& r) {
    for (std::size_t j = 0; j < cols; ++j) equal = equal && r[j] == value(k, j);
    ++seen;
  });
  CHECK(seen == rows);
  CHECK(equal);
  CHECK(store.largest(0) == value(rows - 1, 0));  // the values grow with k
  CHECK_THROWS_AS(store.append(std::vector<double>(3)), std::invalid_argument);
}
