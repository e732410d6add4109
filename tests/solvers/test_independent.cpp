// The keys against independent hand derivations, at parameter values that are not the defaults.
#include <fmt/format.h>

#include <array>
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "problem/values.hpp"
#include "solvers/catalog.hpp"
#include "solvers/solve.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;

namespace {
// An answer holding only a matrix value, to compare a rotation rebuilt by hand with.
Answer matrix_answer(const std::string& name, std::vector<double> rowmajor) {
  Answer a;
  a.name = name;
  a.value = Value::matrix(3, 3, std::move(rowmajor));
  return a;
}

constexpr double kEps = std::numeric_limits<double>::epsilon();

const Answer& answer(const Key& key, const std::string& name) {
  for (const auto& part : key.parts) {
    for (const auto& a : part.answers) {
      if (a.name == name) return a;
    }
  }
  FAIL("no answer " << name);
  throw std::logic_error("unreachable");
}

Key solve_with(const std::string& id, const std::vector<std::string>& sets) {
  const Problem p = find_problem(id);
  return solve(p, parameter_values(p, sets));
}

// The hand formulas below are a few roundings each; the keys are exact then rounded once.
void require_values(const Answer& a, const std::vector<double>& expected) {
  REQUIRE(a.value.data.size() == expected.size());
  double scale = 0.0;
  for (double x : expected) scale = std::max(scale, std::abs(x));
  for (std::size_t i = 0; i < expected.size(); ++i) {
    INFO(a.name << "[" << i << "]");
    REQUIRE_THAT(a.value.data[i], WithinAbs(expected[i], 16 * kEps * scale));
  }
}
}  // namespace

TEST_CASE("taylor-10-35: moments 5, 7, 10 m a^2 and axes (0,1,-1)/sqrt2, (0,1,1)/sqrt2, x") {
  const double m = 2.3, a = 0.41, ma2 = m * a * a;
  const Key key = solve_with("taylor-10-35", {"m=2.3", "a=0.41"});
  require_values(answer(key, "I"), {10 * ma2, 0, 0, 0, 6 * ma2, ma2, 0, ma2, 6 * ma2});
  require_values(answer(key, "principal_moments"), {5 * ma2, 7 * ma2, 10 * ma2});
  const double h = std::sqrt(0.5);
  // Columns e1 = (0, h, -h), e2 = (0, h, h), e3 = e1 x e2 = (1, 0, 0).
  require_values(answer(key, "principal_axes"), {0, 0, 1, h, h, 0, -h, h, 0});
}

TEST_CASE("four-masses: moments 5/2, 3, 7/2 m a^2") {
  const double m = 0.7, a = 1.9, ma2 = m * a * a;
  const Key key = solve_with("four-masses", {"m=0.7", "a=1.9"});
  require_values(answer(key, "I"), {3 * ma2, -ma2 / 2, 0, -ma2 / 2, 3 * ma2, 0, 0, 0, 3 * ma2});
  require_values(answer(key, "principal_moments"), {2.5 * ma2, 3 * ma2, 3.5 * ma2});
}

TEST_CASE("box-corner: textbook corner tensor, diagonal centre tensor, invariants of the moments") {
  const double M = 3.1, a = 0.5, b = 1.25, c = 0.8;
  const Key key = solve_with("box-corner", {"M=3.1", "a=0.5", "b=1.25", "c=0.8"});
  const double xx = M * (b * b + c * c) / 3, yy = M * (a * a + c * c) / 3,
               zz = M * (a * a + b * b) / 3;
  const double xy = -M * a * b / 4, xz = -M * a * c / 4, yz = -M * b * c / 4;
  require_values(answer(key, "I_corner"), {xx, xy, xz, xy, yy, yz, xz, yz, zz});
  require_values(answer(key, "center_of_mass"), {a / 2, b / 2, c / 2});
  require_values(answer(key, "I_cm"), {M * (b * b + c * c) / 12, 0, 0, 0, M * (a * a + c * c) / 12,
                                       0, 0, 0, M * (a * a + b * b) / 12});
  // Numeric moments: check the three invariants of the tensor instead of solving again.
  const auto& l = answer(key, "principal_moments_corner").value.data;
  const double trace = xx + yy + zz;
  const double minors = xx * yy + yy * zz + zz * xx - xy * xy - xz * xz - yz * yz;
  const double det = xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * xz) + xz * (xy * yz - yy * xz);
  // Invariants from eigenvalues carry ~ 8 n eps |I|^k relative error (k = 1, 2, 3).
  const double tol = 8 * 3 * kEps;
  REQUIRE_THAT(l[0] + l[1] + l[2], WithinAbs(trace, tol * trace));
  REQUIRE_THAT(l[0] * l[1] + l[1] * l[2] + l[2] * l[0], WithinAbs(minors, 4 * tol * trace * trace));
  REQUIRE_THAT(l[0] * l[1] * l[2], WithinAbs(det, 8 * tol * trace * trace * trace));
}

TEST_CASE("three-atom-molecule: the planar tensor and its 2x2 block by hand") {
  const double M = 12, m1 = 1.1, m2 = 2.7, d1 = 0.9, d2 = 1.4, al = 1.2;
  const Key key = solve_with("three-atom-molecule",
                             {"M=12", "m1=1.1", "m2=2.7", "d1=0.9", "d2=1.4", "alpha=1.2"});
  const double x2 = d2 * std::cos(al), y2 = d2 * std::sin(al);
  const double Ixx = m2 * y2 * y2, Iyy = m1 * d1 * d1 + m2 * x2 * x2, Ixy = -m2 * x2 * y2;
  require_values(answer(key, "I"), {Ixx, Ixy, 0, Ixy, Iyy, 0, 0, 0, Ixx + Iyy});
  const double mean = (Ixx + Iyy) / 2, r = std::hypot((Ixx - Iyy) / 2, Ixy);
  require_values(answer(key, "principal_moments"), {mean - r, mean + r, Ixx + Iyy});
  // About the centre of mass.
  const double Mt = M + m1 + m2, cx = (m1 * d1 + m2 * x2) / Mt, cy = m2 * y2 / Mt;
  require_values(answer(key, "center_of_mass"), {cx, cy, 0});
  const double Jxx = Ixx - Mt * cy * cy, Jyy = Iyy - Mt * cx * cx, Jxy = Ixy + Mt * cx * cy;
  require_values(answer(key, "I_cm"), {Jxx, Jxy, 0, Jxy, Jyy, 0, 0, 0, Jxx + Jyy});
  const double jm = (Jxx + Jyy) / 2, jr = std::hypot((Jxx - Jyy) / 2, Jxy);
  require_values(answer(key, "principal_moments_cm"), {jm - jr, jm + jr, Jxx + Jyy});
}

TEST_CASE("three-atom-molecule-symmetric: diagonal tensors, a straight molecule is collinear") {
  const double M = 16, m = 1.3, d = 0.96, al = 1.85;
  const Key key =
      solve_with("three-atom-molecule-symmetric", {"M=16", "m=1.3", "d=0.96", "alpha=1.85"});
  const double c = std::cos(al / 2), s = std::sin(al / 2);
  const double Ixx = 2 * m * d * d * s * s, Iyy = 2 * m * d * d * c * c;
  require_values(answer(key, "I"), {Ixx, 0, 0, 0, Iyy, 0, 0, 0, Ixx + Iyy});
  const double xc = 2 * m * d * c / (M + 2 * m);
  require_values(answer(key, "center_of_mass"), {xc, 0, 0});
  require_values(answer(key, "I_cm"), {Ixx, 0, 0, 0, Iyy - (M + 2 * m) * xc * xc, 0, 0, 0,
                                       Ixx + Iyy - (M + 2 * m) * xc * xc});
  // alpha = pi: all three atoms on the y axis. lambda1 = 0, and the key says so.
  const Key straight = solve_with("three-atom-molecule-symmetric", {"alpha=pi"});
  const Answer& l = answer(straight, "principal_moments");
  REQUIRE_THAT(l.value.data[0], WithinAbs(0.0, 16 * kEps * l.value.scale()));
  bool said = false;
  for (const auto& n : l.notes) said = said || n.find("λ1 = 0") != std::string::npos;
  REQUIRE(said);
}

TEST_CASE("values mean what was typed: pi is pi, 90deg is pi/2, 0.1 is one tenth") {
  // The exact route substitutes the number the user meant, not the double nearest to it, so a
  // straight molecule has lambda1 = 0 exactly and a right-angled one an exactly degenerate pair.
  const Key straight = solve_with("three-atom-molecule", {"alpha=pi"});
  REQUIRE(answer(straight, "principal_moments").value.data[0] == 0.0);
  const Key right = solve_with("three-atom-molecule-symmetric", {"alpha=90deg", "m=0.5", "d=1"});
  REQUIRE(answer(right, "principal_moments").value.data == std::vector<double>{0.5, 0.5, 1.0});
  REQUIRE(answer(right, "I").value.data[0] == 0.5);  // 2 m d^2 sin^2(45 deg) = 1/2 exactly
}

TEST_CASE(
    "torque-free extremes: alpha = 1e-8 and alpha near pi/2 are finite and match the series") {
  for (const std::string id : {"rect-solid", "flying-plate"}) {
    // Small alpha: max_angle = 2 k alpha (1 + (1 - k^2) alpha^2 / 3 + ...), k = I1/I3; at
    // alpha = 1e-8 the correction is ~1e-16 relative, so the leading term must agree to a few eps.
    const Key small = solve_with(id, {"alpha=1e-8"});
    const double lead = answer(small, "max_angle_small_alpha").value.data[0];
    REQUIRE_THAT(answer(small, "max_angle").value.data[0],
                 Catch::Matchers::WithinRel(lead, 4 * kEps));
    for (const auto& part : small.parts) {
      for (const auto& a : part.answers) {
        for (double v : a.value.data) REQUIRE(std::isfinite(v));
      }
    }
    // Near the limit: with e = pi/2 - alpha, theta_L = pi/2 - atan(e'/k) where e' = cot(alpha)
    // ~ e, so max_angle = pi - 2 atan(cot(alpha)/k); evaluated here with the exact e = 1e-9.
    const double e = 1e-9;
    const Key edge = solve_with(id, {"alpha=pi/2 - 1e-9"});
    const auto& I = answer(edge, "I").value;
    const double k = I.at(0, 0) / I.at(2, 2);
    const double expected = M_PI - 2 * std::atan(std::tan(e) / k);
    REQUIRE_THAT(answer(edge, "max_angle").value.data[0], WithinAbs(expected, 4 * kEps * M_PI));
    REQUIRE(std::isfinite(answer(edge, "t_max").value.data[0]));
  }
}

TEST_CASE("torque-free alpha = 0: no wobble, said in the key, nothing divided by zero") {
  const Key still = solve_with("flying-plate", {"alpha=0"});
  REQUIRE(answer(still, "max_angle").value.data[0] == 0.0);
  REQUIRE(answer(still, "t_max").value.data[0] == 0.0);
  REQUIRE(answer(still, "space_cone_half_angle").value.data[0] == 0.0);
  REQUIRE_THAT(answer(still, "t_max").notes.at(0), Catch::Contains("no wobble"));
}

namespace {
using M3 = std::array<std::array<double, 3>, 3>;
M3 mul(const M3& a, const M3& b) {
  M3 c{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) c[i][j] += a[i][k] * b[k][j];
    }
  }
  return c;
}
M3 rz(double a) {
  return {{{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}}};
}
M3 ry(double a) {
  return {{{std::cos(a), 0, std::sin(a)}, {0, 1, 0}, {-std::sin(a), 0, std::cos(a)}}};
}
M3 rx(double a) {
  return {{{1, 0, 0}, {0, std::cos(a), -std::sin(a)}, {0, std::sin(a), std::cos(a)}}};
}
std::vector<double> flat(const M3& m) {
  std::vector<double> v;
  for (const auto& row : m) v.insert(v.end(), row.begin(), row.end());
  return v;
}
std::vector<double> matvec(const std::vector<double>& m, const std::vector<double>& x) {
  std::vector<double> y(3, 0.0);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) y[i] += m[3 * i + j] * x[j];
  }
  return y;
}
}  // namespace

TEST_CASE("euler-angles: matrices by hand, angles read back, gimbal lock, both conventions") {
  // A grid over the ranges, with the ends: theta = 0 and pi (gimbal lock), phi and psi = pi.
  const std::vector<std::string> phis{"-170deg", "-30deg", "0", "40deg", "180deg"};
  const std::vector<std::string> thetas{"0", "1deg", "30deg", "90deg", "179deg", "180deg"};
  const std::vector<std::string> psis{"-90deg", "0", "70deg", "180deg"};
  for (const auto& ph : phis) {
    for (const auto& th : thetas) {
      for (const auto& ps : psis) {
        INFO(ph << " " << th << " " << ps);
        const Problem p = find_problem("euler-angles");
        const sym::Values v = parameter_values(p, {"phi=" + ph, "theta=" + th, "psi=" + ps});
        const Key key = solve(p, v);
        const double f = v.at("phi"), t = v.at("theta"), s = v.at("psi");
        const M3 R = mul(mul(rz(f), ry(t)), rz(s));
        require_values(answer(key, "R_zyz"), flat(R));
        M3 Rt{};
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) Rt[i][j] = R[j][i];
        }
        require_values(answer(key, "R_phy711"), flat(Rt));
        require_values(answer(key, "angles_phy711"), {f, t, s});
        // Goldstein's angles and both readings give the same rotation back (z-x-z by hand).
        const auto& zxz = answer(key, "angles_zxz").value.data;
        require_values(matrix_answer("zxz", flat(R)),
                       flat(mul(mul(rz(zxz[0]), rx(zxz[1])), rz(zxz[2]))));
        const auto& back = answer(key, "angles_back_zyz").value.data;
        require_values(matrix_answer("back", flat(R)),
                       flat(mul(mul(rz(back[0]), ry(back[1])), rz(back[2]))));
        const auto& back_x = answer(key, "angles_back_zxz").value.data;
        require_values(matrix_answer("back_x", flat(R)),
                       flat(mul(mul(rz(back_x[0]), rx(back_x[1])), rz(back_x[2]))));
        if (t != 0.0 && t != M_PI) {  // theta = 0 or pi exactly: gimbal lock
          require_values(answer(key, "angles_back_zyz"), {f, t, s});  // the angles given
        } else {
          REQUIRE(back[2] == 0.0);  // gimbal lock: psi = 0 by convention
          REQUIRE_THAT(answer(key, "angles_back_zyz").notes.at(0), Catch::Contains("Gimbal"));
        }
        for (const auto* a : {&back, &back_x}) {
          REQUIRE((*a)[0] > -M_PI);
          REQUIRE((*a)[0] <= M_PI);
        }
        // w in three bases is one vector: space = R body, primed = Rz(psi) body; T = w.L/2.
        const auto& wb = answer(key, "omega_body").value.data;
        require_values(answer(key, "omega_space"), matvec(flat(R), wb));
        require_values(answer(key, "omega_primed"), matvec(flat(rz(s)), wb));
        const auto& Lp = answer(key, "L_primed").value.data;
        const auto& wp = answer(key, "omega_primed").value.data;
        REQUIRE_THAT(answer(key, "kinetic_energy").value.data[0],
                     WithinAbs(0.5 * (wp[0] * Lp[0] + wp[1] * Lp[1] + wp[2] * Lp[2]),
                               16 * kEps * answer(key, "kinetic_energy").value.data[0]));
      }
    }
  }
}

TEST_CASE("asymmetric-top: spun exactly about e3, the period is the small-oscillation one") {
  const Key key = solve_with("asymmetric-top", {"w1=0", "w2=0"});
  const double I1 = 2, I2 = 3, I3 = 4, w3 = 5;
  require_values(answer(key, "k2"), {0.0});
  require_values(answer(key, "energy"), {0.5 * I3 * w3 * w3});
  require_values(answer(key, "L_magnitude"), {I3 * w3});
  const double T = 2 * M_PI / (w3 * std::sqrt((I3 - I2) * (I3 - I1) / (I1 * I2)));
  require_values(answer(key, "period"), {T});
  require_values(answer(key, "period_small_oscillation"), {T});
  // Stable about the smallest and largest axes, unstable about the middle one (|w(0)| = w3).
  REQUIRE_THAT(answer(key, "rate_axis1").notes.at(0), Catch::StartsWith("Stable"));
  REQUIRE_THAT(answer(key, "rate_axis2").notes.at(0), Catch::StartsWith("Unstable"));
  REQUIRE(answer(key, "rate_axis2").unit == "1/s");
  REQUIRE_THAT(answer(key, "rate_axis3").notes.at(0), Catch::StartsWith("Stable"));
  require_values(answer(key, "rate_axis2"), {w3 * std::sqrt((I2 - I1) * (I3 - I2) / (I1 * I3))});
}

TEST_CASE("heavy-top: the sleeping top's verdict flips at the threshold p_psi^2 = 4 M g l I1") {
  const double M = 0.5, R = 0.05, l = 0.08, g = 9.81;
  const double I1 = M * R * R / 4 + M * l * l, I3 = M * R * R / 2;
  const double w_min = 2 * std::sqrt(M * g * l * I1) / I3;
  const Key at = solve_with("heavy-top", {});
  require_values(answer(at, "omega3_min"), {w_min});
  for (const double f : {0.999, 1.001}) {
    INFO(f);
    const Key key = solve_with("heavy-top", {fmt::format("psidot0={:.17g}", f * w_min)});
    REQUIRE_THAT(answer(key, "omega3_min").notes.at(0),
                 Catch::Contains(f > 1 ? "would sleep" : "would fall"));
  }
}

TEST_CASE("heavy-top: too slow to precess steadily, part d says so and has no answers") {
  const Key key = solve_with("heavy-top", {"psidot0=80"});
  const PartKey& d = key.parts.at(3);
  REQUIRE(d.id == "d");
  REQUIRE(d.answers.empty());
  REQUIRE(d.absent == std::vector<std::string>{"phidot_slow", "phidot_fast"});
  // The least spin for steady precession at theta0 = 30 deg: 2 sqrt(I1 M g l cos)/I3.
  const double M = 0.5, R = 0.05, l = 0.08, g = 9.81;
  const double I1 = M * R * R / 4 + M * l * l, I3 = M * R * R / 2;
  const double need = 2 * std::sqrt(I1 * M * g * l * std::cos(M_PI / 6)) / I3;
  REQUIRE_THAT(d.steps.back().text,
               Catch::Contains("No steady precession") && Catch::Contains(format_number(need)));
}

TEST_CASE("heavy-top: a horizontal axle has the gyroscope's one precession, without cos theta0") {
  const Key key = solve_with("heavy-top", {"theta0=90deg"});
  const double M = 0.5, R = 0.05, l = 0.08, g = 9.81, psidot = 150;
  const double I3 = M * R * R / 2;
  const PartKey& d = key.parts.at(3);
  REQUIRE(d.absent == std::vector<std::string>{"phidot_fast"});
  REQUIRE_THAT(d.steps.back().text, Catch::Contains("horizontal"));
  REQUIRE_THAT(d.absent_why.at(0), Catch::StartsWith("θ0 = 90°: the axle is horizontal"));
  const Answer& slow = answer(key, "phidot_slow");
  // M g l/(I3 ψ̇0): three roundings in each route.
  REQUIRE_THAT(slow.value.data.at(0),
               Catch::Matchers::WithinRel(M * g * l / (I3 * psidot), 4 * kEps));
  REQUIRE_THAT(slow.symbolic, !Catch::Contains("theta0"));
  REQUIRE_THAT(slow.notes.at(0), Catch::Contains("the exact root itself"));
  REQUIRE(key.held == std::vector<std::string>{"theta0"});
}

TEST_CASE("heavy-top: a nearly horizontal axle's fast precession against 50 digits") {
  // The fast root q/(2 I1 cos θ0) grows as 1/cos θ0 near 90°, where a double route takes the
  // rounding of θ0 amplified by tan θ0. A tilt typed as a decimal in radians is exact in the
  // key; one in degrees (not a simple fraction of π) reaches it as its double in radians.
  using mp = boost::multiprecision::cpp_bin_float_50;
  const mp M("0.5"), R("0.05"), l("0.08"), g("9.81"), psidot("150");
  const mp I1 = M * R * R / 4 + M * l * l, I3 = M * R * R / 2, p = I3 * psidot;
  const mp deg = boost::math::constants::pi<mp>() / 180;
  struct Tilt {
    std::string typed;
    mp theta;
    bool exact;  // radians: the decimal itself
  };
  const std::vector<Tilt> tilts{{"1.5707963", mp("1.5707963"), true},
                                {"1.57079632679", mp("1.57079632679"), true},
                                {"89.9999999deg", mp("89.9999999") * deg, false},
                                {"90.0000001deg", mp("90.0000001") * deg, false}};
  for (const auto& [typed, theta, exact] : tilts) {
    INFO(typed);
    const mp c = cos(theta);
    const mp fast = (p + sqrt(p * p - 4 * I1 * M * g * l * c)) / (2 * I1 * c);
    const Key key = solve_with("heavy-top", {"theta0=" + typed});
    // Exact: the route's rounding to double and its few operations after. In degrees: θ0's
    // rounding to double (eps/2 relative) times d ln(fast)/d ln θ0 = θ0 tan θ0.
    const double theta_d = static_cast<double>(theta);
    const double tolerance = exact ? 4 * kEps : kEps * std::abs(theta_d * std::tan(theta_d));
    REQUIRE_THAT(answer(key, "phidot_fast").value.data.at(0),
                 Catch::Matchers::WithinRel(static_cast<double>(fast), tolerance));
  }
}
