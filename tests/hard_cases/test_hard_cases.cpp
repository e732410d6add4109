// The hard-case suite: one named test per case where naive formulas break. Each
// tolerance says where it comes from.
#include <Eigen/Dense>
#include <array>
#include <boost/math/constants/constants.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "bench/mp_reference.hpp"
#include "bench/odeint.hpp"
#include "core/euler_angles.hpp"
#include "core/exact_free_body.hpp"
#include "core/free_body.hpp"
#include "core/heavy_top.hpp"
#include "core/principal_axes.hpp"
#include "core/shapes.hpp"
#include "core/torque_free_symmetric.hpp"
#include "solvers/catalog.hpp"
#include "problem/values.hpp"
#include "solvers/solve.hpp"
#include "temp_files.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using Catch::Matchers::WithinULP;

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();

void require_orthonormal_right_handed(const Mat3& A, double tol) {
  REQUIRE((A.transpose() * A - Mat3::Identity()).cwiseAbs().maxCoeff() <= tol);
  REQUIRE_THAT(A.determinant(), WithinAbs(1.0, tol));
}
}  // namespace

TEST_CASE("hard 1: exactly degenerate tensors (symmetric top, cube, sphere)") {
  const Mat3 R = Eigen::AngleAxisd(0.9, Vec3(1, 1, -2).normalized()).toRotationMatrix();
  struct Case {
    const char* name;
    Vec3 moments;
  };
  for (const Case& c : {Case{"symmetric top", Vec3(1, 1, 3)}, Case{"cube", Vec3(2, 2, 2)},
                        Case{"sphere", Vec3(0.4, 0.4, 0.4)}, Case{"prolate", Vec3(1, 3, 3)}}) {
    INFO(c.name);
    const Mat3 I = R * c.moments.asDiagonal() * R.transpose();
    const PrincipalAxes pa = principal_axes(I);
    // Rotating the tensor rounds each entry (a few eps I_max); the solver's backward error is
    // ~eps I_max; the snapped moments sit within 4 eps I_max of the exact ones.
    const double Imax = c.moments.maxCoeff();
    for (int i = 0; i < 3; ++i) {
      REQUIRE_THAT(pa.moments[i], WithinAbs(c.moments[i], 4 * kEps * Imax));
    }
    require_orthonormal_right_handed(pa.axes, 8 * kEps);
    // The degenerate pair is reported and its basis is the documented one, the same each time.
    REQUIRE(pa.degeneracy != Degeneracy::none);
    const PrincipalAxes again = principal_axes(I);
    REQUIRE(again.axes == pa.axes);
  }
}

TEST_CASE("hard 2: nearly degenerate, lambda2 = lambda1 (1 + 1e-12): no spurious split") {
  const Mat3 R = Eigen::AngleAxisd(0.4, Vec3(2, -1, 1).normalized()).toRotationMatrix();
  const Vec3 l(1.0, 1.0 + 1e-12, 3.0);
  const PrincipalAxes pa = principal_axes(R * l.asDiagonal() * R.transpose());
  // The input's split is 1e-12; the tensor carries ~4 eps of rounding: the computed split
  // equals 1e-12 within 8 eps (4 eps on each moment), not more and not snapped to zero
  // (1e-12 > 16 eps lambda3 = 1.1e-14, the degeneracy tolerance).
  REQUIRE(pa.degeneracy == Degeneracy::none);
  REQUIRE_THAT(pa.moments[1] - pa.moments[0], WithinAbs(1e-12, 8 * kEps * l.maxCoeff()));
  require_orthonormal_right_handed(pa.axes, 8 * kEps);
}

TEST_CASE("hard 3: badly scaled moments and extreme units") {
  const Mat3 R = Eigen::AngleAxisd(1.1, Vec3(0.3, 1, -0.2).normalized()).toRotationMatrix();
  const Vec3 l(1e-6, 1.0, 1e6);
  const PrincipalAxes pa = principal_axes(R * l.asDiagonal() * R.transpose());
  // Absolute accuracy is relative to the largest moment (the tensor's entries carry
  // eps * 1e6): 4 eps lambda_max each; the smallest moment is known to 4 eps * 1e6 = 1e-9.
  for (int i = 0; i < 3; ++i) REQUIRE_THAT(pa.moments[i], WithinAbs(l[i], 4 * kEps * 1e6));
  require_orthonormal_right_handed(pa.axes, 8 * kEps);
  // m = 1e30 kg, a = 1e-10 m: the box formula m (b^2 + c^2) / 12 stays in range (1e10) and
  // relative accuracy is unchanged by the units (each operation rounds once).
  const Mat3 box = shape_inertia_about_cm(ShapeKind::box, 1e30, {1e-10, 2e-10, 3e-10});
  REQUIRE_THAT(box(0, 0), WithinRel(1e30 * (4e-20 + 9e-20) / 12, 4 * kEps));
  REQUIRE_THAT(box(2, 2), WithinRel(1e30 * (1e-20 + 4e-20) / 12, 4 * kEps));
  const PrincipalAxes pb = principal_axes(box);
  REQUIRE(pb.moments.allFinite());
  REQUIRE_THAT(pb.moments[2], WithinRel(1e30 * 13e-20 / 12, 4 * kEps));
}

TEST_CASE("hard 4: alpha = 1e-8 and pi/2 - 1e-8 in the symmetric-top answers") {
  const double I1 = 2.0, I3 = 3.0, w = 5.0;
  // Small alpha: theta_L = atan(I1 tan(alpha) / I3) = (I1/I3) alpha (1 + O(alpha^2)); the
  // series' next term is alpha^2 ~ 1e-16 relative: 1e-13 bounds rounding and truncation.
  const SymmetricTop small{I1, I3, w, 1e-8};
  REQUIRE_THAT(small.angle_L_e3(), WithinRel(I1 / I3 * 1e-8, 1e-13));
  REQUIRE_THAT(small.max_angle(), WithinRel(2 * I1 / I3 * 1e-8, 1e-13));
  // Near pi/2: theta_L -> pi/2 - (I3/I1) (pi/2 - alpha); w3 = w sin(1e-8) -> w 1e-8.
  const double d = 1e-8;
  const SymmetricTop steep{I1, I3, w, M_PI / 2 - d};
  REQUIRE_THAT(M_PI / 2 - steep.angle_L_e3(), WithinRel(I3 / I1 * d, 1e-7));
  REQUIRE_THAT(steep.omega3(), WithinRel(w * d, 1e-7));
  for (const auto& t : {small, steep}) {
    for (const double v : {t.angle_L_e3(), t.angle_omega_L(), t.omega_body_rate(),
                           t.omega_space_rate(), t.max_angle(), t.t_max()}) {
      REQUIRE(std::isfinite(v));
    }
  }
}

TEST_CASE(
    "hard 5: an almost spherical top, lambda3 - lambda1 = 1e-12: rates without cancellation") {
  // I3 - I1 of two doubles within a factor 2 is exact (Sterbenz), so Omega_body is the exact
  // (I3 - I1)/I1 w3 rounded a few times: 4 eps relative, not the 1e-4 a subtraction of
  // rounded rates (w3 I3/I1 - w3) would leave.
  const double I1 = 1.0, I3 = 1.0 + 1e-12, w = 3.0, alpha = 0.3;
  const SymmetricTop top{I1, I3, w, alpha};
  const double exact = (I3 - I1) / I1 * w * std::cos(alpha);
  REQUIRE_THAT(top.omega_body_rate(), WithinRel(exact, 4 * kEps));
  // And the exact solver's symmetric branch turns the body cone at that rate: period 2 pi / c.
  const Vec3 m0 = Vec3(I1, I1, I3).cwiseProduct(top.omega0());
  const ExactFreeMotion motion(Vec3(I1, I1, I3), m0, Quat::Identity());
  REQUIRE_THAT(motion.period_s(), WithinRel(2 * M_PI / std::abs(exact), 8 * kEps));
}

TEST_CASE("hard 6: near the separatrix, k'^2 from 1e-4 to 1e-16, against 50 digits") {
  const Vec3 I(1, 2, 3);
  for (const double s : {1e-2, 1e-4, 1e-6, 1e-8}) {
    const Vec3 m0(s, 1, 2 * s);  // circles e3; k'^2 ~ 4 s^2 / 3
    const ExactFreeMotion exact(I, m0, Quat::Identity());
    const bench::MpMotion ref(I, m0);
    const double P = ref.period(), quarter = ref.first_K_time();
    std::vector<double> times;
    for (int i = 0; i <= 20; ++i) times.push_back(2 * P * i / 20);
    for (const double d : {-1e-9, 0.0}) times.push_back(quarter + d);  // dn near u = K
    for (const double t : times) {
      // The measured condition at t: how far m(t) moves when one component of m0 moves by
      // eps |m0| (the input's own rounding). The answer may be off by that much, plus the
      // evaluation's few eps: 8 eps |m0| (1 + condition).
      double cond = 0.0;
      for (int i = 0; i < 3; ++i) {
        Vec3 m = m0;
        m[i] += kEps * m0.norm();
        cond = std::max(
            cond,
            (ExactFreeMotion(I, m, Quat::Identity()).momentum_at(t) - exact.momentum_at(t)).norm() /
                (kEps * m0.norm()));
      }
      INFO("s = " << s << ", t = " << t << ", condition " << cond);
      REQUIRE((exact.momentum_at(t) - ref.m_at(t)).norm() <= 8 * kEps * m0.norm() * (1 + cond));
    }
  }
}

TEST_CASE("hard 7: exactly on the separatrix and exactly on a principal axis") {
  const Vec3 I(1, 2, 3);
  // On a principal axis (each): steady rotation, no elliptic functions, no division by zero.
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 m0 = 2.0 * Vec3::Unit(axis);
    const ExactFreeMotion motion(I, m0, Quat::Identity());
    REQUIRE(motion.kind() == ExactFreeMotion::Kind::steady);
    const FreeBodyState s = motion.at(7.0);
    REQUIRE(s.m_B == m0);
    REQUIRE(s.q_BtoS.coeffs().allFinite());
  }
  // On the separatrix: D = m3^2 (I3-I2)/I3 - m1^2 (I2-I1)/I1 = 0 exactly for m1 = 1, m3 = 3
  // (9/3 - 1 * 1 = 2... scaled: m3^2/3 = m1^2 -> m1 = 1, m3 = sqrt 3 is not exact; use I with
  // (I3-I2)/I3 = 1/4 and (I2-I1)/I1 = 1: I = (1, 2, 8/3)? (8/3 - 2)/(8/3) = 1/4; m3 = 2 m1.
  const Vec3 J(1.0, 2.0, 8.0 / 3.0);
  const Vec3 m0(0.25, 1.0, 0.5);
  const ExactFreeMotion sep(J, m0, Quat::Identity());
  REQUIRE(sep.kc2() >= 0.0);
  REQUIRE(sep.kc2() <= 1e-15);  // 8/3 rounds: D is a few eps, not exactly 0
  for (const double t : {0.0, 1.0, 10.0, 100.0, 1000.0}) {
    const FreeBodyState s = sep.at(t);
    REQUIRE(s.m_B.allFinite());
    REQUIRE(s.q_BtoS.coeffs().allFinite());
    REQUIRE_THAT(s.m_B.norm(), WithinRel(m0.norm(), 16 * kEps));
  }
}

TEST_CASE("hard 8: Euler angles at theta = 0, pi and 1e-12 from them") {
  for (const EulerConvention c : {EulerConvention::zyz, EulerConvention::zxz}) {
    for (const double theta : {0.0, 1e-12, M_PI - 1e-12, M_PI}) {
      for (const double phi : {-2.0, 0.5, 3.0}) {
        for (const double psi : {-1.0, 0.0, 2.5}) {
          const Mat3 R = rotation_from_euler(Vec3(phi, theta, psi), c);
          const Vec3 back = euler_from_rotation(R, c);
          INFO("theta " << theta << " phi " << phi << " psi " << psi);
          REQUIRE(back.allFinite());
          // At and next to gimbal lock only phi +- psi is defined: compare rotations. Each
          // angle passes through atan2 of entries with eps errors; 256 eps bounds the matrix
          // difference (measured < 8 eps).
          REQUIRE((rotation_from_euler(back, c) - R).cwiseAbs().maxCoeff() <= 256 * kEps);
        }
      }
    }
  }
}

TEST_CASE("hard 9: the sleeping top on either side of its threshold, 1e-10 apart") {
  const double M = 0.5, g = 9.81, l = 0.08, I1 = 0.0035125;
  const double threshold = 2 * std::sqrt(M * g * l * I1);
  // 1e-10 relative is ~5e5 eps: far above the few-eps error of the factored discriminant,
  // while p^2 - 4 M g l I1 in plain form would still get it right here; at 1e-15 only the
  // factored form gives the sign of (|p| - c) exactly.
  for (const double rel : {1e-10, 1e-14}) {
    REQUIRE(sleeping_top_is_stable(threshold * (1 + rel), M, g, l, I1));
    REQUIRE_FALSE(sleeping_top_is_stable(threshold * (1 - rel), M, g, l, I1));
    REQUIRE(sleeping_top_is_stable(-threshold * (1 + rel), M, g, l, I1));  // either sense of spin
  }
  REQUIRE_THROWS_AS(sleeping_top_is_stable(1.0, -M, g, l, I1), std::invalid_argument);
}

TEST_CASE("hard 10: a million splitting steps keep |L| and the attitude to round-off") {
  const FreeBody body{Vec3(2.0, 1.0, 2.0 / 3.0)};
  const Vec3 m0(std::cos(1.1), 0.0, std::sin(1.1));
  FreeBodyState s{m0, Quat::Identity()};
  std::int64_t subflows = 0;
  const std::int64_t steps = 1000000;
  split_free_body(body, s, 0.01, steps, SplittingOrder::strang2, &subflows);
  // Each sub-flow is an exact rotation rounded: errors of ~eps add like a random walk, so
  // 4 eps sqrt(sub-flows) bounds |L| and the rotation matrix's orthonormality.
  const double walk = 4 * kEps * std::sqrt(static_cast<double>(subflows));
  REQUIRE_THAT(s.m_B.norm(), WithinAbs(m0.norm(), walk));
  const Mat3 R = s.q_BtoS.toRotationMatrix();
  REQUIRE((R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff() <= walk);
  REQUIRE(((s.q_BtoS * s.m_B) - m0).norm() <= walk);
}

namespace {
// Four unit masses on the x and y axes and two small ones off them: the x-y moments differ by
// a few times `small`, so in double precision the axes lose eps |I| / gap.
std::string near_degenerate_problem(const std::string& small) {
  return R"TOML(id = "near-degenerate"
title = "t"
solver = "inertia"
statement = "s"

[[parameters]]
name = "m"
unit = "kg"
default = 1
range = "(0, inf)"

[[parameters]]
name = "e"
unit = "kg"
default = )TOML" + small + R"TOML(
range = "(0, inf)"

[body]
masses = [ { mass = "m", at = ["1", "0", "0"] }, { mass = "m", at = ["-1", "0", "0"] },
           { mass = "m", at = ["0", "1", "0"] }, { mass = "m", at = ["0", "-1", "0"] },
           { mass = "e", at = ["1", "2", "3"] }, { mass = "2*e", at = ["-2", "1", "1"] } ]

[[parts]]
id = "a"
question = "q"
answers = ["principal_moments", "principal_axes"]
)TOML";
}
}  // namespace

namespace {
using Big = boost::multiprecision::cpp_bin_float_50;
using BigVec = std::array<Big, 3>;

// Eigenvalues (ascending) of a symmetric 3x3 by the trigonometric closed form (Smith 1961), and
// each eigenvector as the cross product of two rows of A - lambda 1: another algorithm than the
// implementation's Jacobi rotations, in another library's arithmetic. In 50 digits its
// ill-conditioning near equal moments (digits lost ~ eps_50 / gap) leaves over 30 digits.
std::array<std::pair<Big, BigVec>, 3> smith_eigen(const std::array<BigVec, 3>& A) {
  const Big p1 = A[0][1] * A[0][1] + A[0][2] * A[0][2] + A[1][2] * A[1][2];
  const Big q = (A[0][0] + A[1][1] + A[2][2]) / 3;
  const Big p2 = (A[0][0] - q) * (A[0][0] - q) + (A[1][1] - q) * (A[1][1] - q) +
                 (A[2][2] - q) * (A[2][2] - q) + 2 * p1;
  const Big p = sqrt(p2 / 6);
  std::array<BigVec, 3> B;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) B[i][j] = (A[i][j] - (i == j ? q : Big(0))) / p;
  const Big r = (B[0][0] * (B[1][1] * B[2][2] - B[1][2] * B[2][1]) -
                 B[0][1] * (B[1][0] * B[2][2] - B[1][2] * B[2][0]) +
                 B[0][2] * (B[1][0] * B[2][1] - B[1][1] * B[2][0])) / 2;
  const Big phi = acos(r < -1 ? Big(-1) : r > 1 ? Big(1) : r) / 3;
  const Big pi = boost::math::constants::pi<Big>();
  const Big largest = q + 2 * p * cos(phi), smallest = q + 2 * p * cos(phi + 2 * pi / 3);
  const std::array<Big, 3> lambda{smallest, 3 * q - largest - smallest, largest};
  std::array<std::pair<Big, BigVec>, 3> out;
  for (int k = 0; k < 3; ++k) {
    std::array<BigVec, 3> M = A;
    for (int i = 0; i < 3; ++i) M[i][i] -= lambda[k];
    // The largest cross product of two rows is the best conditioned.
    BigVec best{0, 0, 0};
    Big best_norm = 0;
    for (int a = 0; a < 3; ++a) {
      for (int b = a + 1; b < 3; ++b) {
        const BigVec c{M[a][1] * M[b][2] - M[a][2] * M[b][1], M[a][2] * M[b][0] - M[a][0] * M[b][2],
                       M[a][0] * M[b][1] - M[a][1] * M[b][0]};
        const Big n = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        if (n > best_norm) {
          best_norm = n;
          best = c;
        }
      }
    }
    for (auto& x : best) x /= best_norm;
    out[k] = {lambda[k], best};
  }
  return out;
}

// t and the n doubles on either side of it: around the end of a half period the reduction by
// 2K changes j, and which double first lands past the end depends on rounding.
std::vector<double> doubles_around(double t, int n) {
  for (int k = 0; k < n; ++k) t = std::nextafter(t, -INFINITY);
  std::vector<double> out;
  for (int k = -n; k <= n; ++k, t = std::nextafter(t, INFINITY)) out.push_back(t);
  return out;
}
}  // namespace

TEST_CASE("hard 13: nearly equal moments of an exact tensor: the axes right to the last digit") {
  for (const std::string small : {"1e-9", "1e-12"}) {
    INFO("small mass " << small);
    const Problem p = load_problem(
        wobble::test::write_file("hard/near-" + small + ".toml", near_degenerate_problem(small)));
    const Key key = solve(p, parameter_values(p, {}));
    const auto& moments = key.parts.at(0).answers.at(0).value.data;
    const auto& axes = key.parts.at(0).answers.at(1).value.data;
    // The reference: the same tensor summed in 50 digits from the masses.
    const Big e(small);
    const std::vector<std::pair<Big, BigVec>> masses{{1, {1, 0, 0}}, {1, {-1, 0, 0}},
                                                     {1, {0, 1, 0}}, {1, {0, -1, 0}},
                                                     {e, {1, 2, 3}}, {2 * e, {-2, 1, 1}}};
    std::array<BigVec, 3> I{};
    for (const auto& [m, r] : masses) {
      const Big r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) I[i][j] += m * ((i == j ? r2 : Big(0)) - r[i] * r[j]);
      }
    }
    const auto reference = smith_eigen(I);
    for (std::size_t k = 0; k < 3; ++k) {
      // Rounded once from many digits: within an ulp of the reference.
      REQUIRE_THAT(moments.at(k), WithinULP(static_cast<double>(reference[k].first), 1));
      Big dot = 0;
      for (std::size_t i = 0; i < 3; ++i) dot += reference[k].second[i] * axes.at(3 * i + k);
      const double sign = dot < 0 ? -1.0 : 1.0;
      for (std::size_t i = 0; i < 3; ++i) {
        // Each component rounded once (half an ulp of numbers below 1), eps as the bound.
        REQUIRE_THAT(axes.at(3 * i + k),
                     WithinAbs(sign * static_cast<double>(reference[k].second[i]), kEps));
      }
    }
  }
}

TEST_CASE("hard 14: the heavy top's closed form against 50 digits, up to a million seconds") {
  // The bench's top P4 (released at rest at 30 degrees, spin 150 rad/s: cusps), waves, loops, a
  // wide slow swing, a top near hanging down, one released there, one near upright, and a
  // slow top thrown over the top that swings to 0.04 rad from hanging down, and two all but
  // spinless tops released at 30 degrees that swing 1.6e-5 and 1.6e-4 rad past hanging down
  // (1 + u1 = 1.3e-10 and 1.3e-8, where (1 + u0) + d_min had kept 3e-6 and 3e-8 of it: phi
  // turned that much short at each passage), and one thrown over the top that passes 2.4e-6 rad
  // from upright (1 - u2 = 3e-12, of which (1 - u0) - d_max had kept 1e-5).
  const HeavyTop top{0.5, 0.08, 9.81, 0.0035125, 0.000625};
  struct Case {
    double theta, thetadot, phidot, psidot;
  };
  for (const Case c : {Case{M_PI / 6, 0, 0, 150}, Case{0.8, 0, 4, 150}, Case{0.8, 0, -3, 150},
                       Case{0.5, -1.0, 0.5, 30}, Case{2.9, 0.5, 0, 10}, Case{2.6, 0, 0, 20},
                       Case{0.05, 0.3, 1, 300}, Case{1.2, 2, -2, 5}, Case{M_PI / 6, 0, 0, 1e-3},
                       Case{M_PI / 6, 0, 0, 1e-2}, Case{M_PI / 6, -11.5, 0, 1e-3}}) {
    const Quat q0(Eigen::AngleAxisd(c.theta, Vec3::UnitY()));
    const double st = std::sin(c.theta);
    const Vec3 m0(-top.I1_kgm2 * c.phidot * st, top.I1_kgm2 * c.thetadot,
                  top.I3_kgm2 * (c.phidot * std::cos(c.theta) + c.psidot));
    const ExactHeavyTop exact(top, m0, q0);
    const bench::MpHeavyTop ref(top, m0, q0);
    // Everything that grows with t is in double-double (the nutation's phase and its reduction
    // by the period, the elliptic integrals' complete parts, the linear phases, and the
    // constants behind them from the start state, the cubic's roots polished there), so the
    // error does not grow. What is left: the reduced phase rounded to eps K, a time error of
    // about eps T / 2 (T the nutation period), which moves the state by its own rate; and a few
    // eps from each side composing four rotations in double. The closed form promises this with
    // the fastest Euler rate r in place of the state's rate (simulate's method choice reads it):
    const double euler_bound =
        kEps * (16 + 2 * exact.euler_rate_bound() * exact.nutation_period_s());
    // m's error against the largest |m| of the motion, at its lowest point u1: energy gives
    // |m(u)|^2 = |m0|^2 + I1^2 beta (u0 - u). Against |m0| an all but spinless top (|m0| 6e-7,
    // swinging with 0.05) would read its rounding 1e5 times too large.
    const double m_scale =
        std::sqrt(m0.squaredNorm() + top.I1_kgm2 * top.I1_kgm2 * static_cast<double>(ref.beta) *
                                         static_cast<double>(ref.u0 - ref.u1));
    // The state's own rate, which r overstates a millionfold for a top that passes a pole
    // (its Euler rates grow as 1/(1 -+ u) there, its w does not; m is formed free of them, and
    // cn near the highest point, r = K, from K - |r| in double-double, where r in double would
    // carry eps K, a time error that psi' turns into m): the attitude turns at
    // sqrt(2) |w| in Frobenius norm, |w| largest with |m| (m3 fixed); m changes at
    // |m x w + tau| <= |m| |w| + M g l.
    const double m3 = m0.z(), T = exact.nutation_period_s();
    const double w_max = std::sqrt((m_scale * m_scale - m3 * m3) / (top.I1_kgm2 * top.I1_kgm2) +
                                   m3 * m3 / (top.I3_kgm2 * top.I3_kgm2));
    const double state_rate = std::sqrt(2.0) * w_max + top.M_kg * top.g_m_s2 * top.l_m / m_scale;
    const double bound = std::min(euler_bound, kEps * (16 + 2 * state_rate * T));
    // Times: spread out to a million seconds; the lowest point (tau = 2 j K: the passages near
    // hanging down) and the highest (tau = (2 j + 1) K: near upright, and where the reduction
    // by 2K changes j), each after one period and after a million, the highest with the three
    // doubles either side (j is off by one on one side of it, and r lands past K: the integrals
    // of r read it mirrored back inside: 6.9e5 eps in attitude after a million periods).
    std::vector<double> times{0.013, 0.5, 2.0, 100.0, 1e4, 1e6};
    constexpr int kUlpsAround = 3;
    for (const double j : {1.0, 1e6}) {
      times.push_back(static_cast<double>((2 * j * ref.Kc - ref.tau0) / ref.rate));
      for (const double t : doubles_around(
               static_cast<double>(((2 * j + 1) * ref.Kc - ref.tau0) / ref.rate), kUlpsAround))
        times.push_back(t);
    }
    for (const double t : times) {
      const FreeBodyState e = exact.at(t), r = ref.at(t);
      const double dq = (e.q_BtoS.toRotationMatrix() - r.q_BtoS.toRotationMatrix()).norm();
      const double dm = (e.m_B - r.m_B).norm() / m_scale;
      INFO("theta0 " << c.theta << " t " << t << ": attitude " << dq / kEps << " eps, momentum "
                     << dm / kEps << " eps, bound " << bound / kEps << " eps");
      CHECK(dq <= bound);
      CHECK(dm <= bound);
    }
  }
}

TEST_CASE("hard 15: the free body after a million periods, m(t) and attitude against 50 digits") {
  // The phase u0 + lambda t and its reduction by 2K in double-double: in double their rounding,
  // eps u, was the error (measured 2.9e-13 after T = 1e4 on this body, ~1300 eps). Against the
  // same formulas at 50 digits from the same double inputs: each component within 8 eps of
  // |m0| at every time, out to 1e6 periods and T = 1e7 s (the inputs' own rounding moves the
  // true motion much further by then, but both sides start from the same doubles).
  const std::vector<std::pair<Vec3, Vec3>> bodies{
      {Vec3(2.0, 1.0, 2.0 / 3.0), Vec3(std::cos(1.1), 0.0, std::sin(1.1))},  // the bench's P1/P2
      {Vec3(1.0, 2.0, 3.0), Vec3(0.3, 1.0, 0.8)},
      {Vec3(1.0, 2.0, 3.0), Vec3(1e-3, 1.0, 2e-3)},  // k'^2 ~ 1e-6: near the separatrix
  };
  // The attitude likewise: its precession angle's growing terms (phi_rate t and the complete
  // third-kind integral times the half periods) in double-double, reduced by 2 pi there; the
  // reference's angle by Legendre's Pi (Boost.Math ellint_3) at 50 digits. Within 16 eps (the
  // rotations composed in double on either side, a few eps each) plus what the reduced phase's
  // own rounding moves: r is a double in [-K, K], off by up to eps K, and the attitude turns at
  // |w| per unit of t, 1 / lambda per unit of u, so by sqrt(2) |w| eps K / lambda in Frobenius
  // norm; four times that, for r's rounding and sn's. Near the separatrix (K ~ 8) this is
  // ~60 eps at the fast flip, within the first period as after a million (measured alike).
  // And at the ends of half periods, where u0 + lambda t = (2j + 1) K: there the reduction's
  // j, the rounded quotient of the high parts, is off by one on one side of the time, and r
  // lands past K by up to an ulp of u / 2K times 2K (2e-10 after a million half periods): the
  // precession angle's G(r) read r mirrored back inside, and the attitude was off by up to 1e7
  // eps at one double time in the seven around each end below (now within the bound).
  constexpr int kUlpsAround = 3;
  const Quat q0(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  for (const auto& [I, m0] : bodies) {
    const ExactFreeMotion exact(I, m0, q0);
    std::vector<double> times{10.0, 1e3, 1e5, 1e7, 1e6 * exact.period_s() + 0.37};
    {
      const bench::MpWorkingFrame w = bench::mp_working_frame(I, m0);
      const bench::MpMotion ref(w.J, w.m);
      const Big K = boost::math::ellint_1(ref.k);
      for (const double j : {1.0, 2e5 + 1, 2e6, 2e6 + 1}) {
        for (const double t : doubles_around(
                 static_cast<double>(((2 * j + 1) * K - ref.u0) / ref.lambda), kUlpsAround))
          times.push_back(t);
      }
    }
    for (const double t : times) {
      const FreeBodyState s = exact.at(t);
      const double error = (s.m_B - bench::mp_free_momentum(I, m0, t)).norm();
      const double attitude =
          (s.q_BtoS.toRotationMatrix() -
           bench::mp_free_attitude(I, m0, q0, t).toRotationMatrix()).norm();
      const bench::MpWorkingFrame w = bench::mp_working_frame(I, m0);
      const bench::MpMotion ref(w.J, w.m);
      const double K = static_cast<double>(boost::math::ellint_1(ref.k));
      const double speed = s.m_B.cwiseQuotient(I).norm();
      const double phase_rounding =
          4 * std::sqrt(2.0) * speed * kEps * K / static_cast<double>(ref.lambda);
      INFO("I = " << I.transpose() << ", t = " << t << ": " << error / (kEps * m0.norm())
                  << " eps |m0|, attitude " << attitude / kEps << " eps, bound "
                  << (16 * kEps + phase_rounding) / kEps << " eps");
      REQUIRE(error <= 8 * kEps * m0.norm());
      REQUIRE(attitude <= 16 * kEps + phase_rounding);
    }
  }
}

TEST_CASE(
    "hard 16: a top too slow to sleep released near upright, against a 50-digit integration") {
  // It falls and comes back as near: the upper limit u2 and the cubic's third root u3 are both
  // within ~theta0^2 of 1, and u3 - u2 (k'^2's numerator) was a rounding when u3 came from the
  // sum of the roots (w 3e-2 off after 2 s at 1e-8; below about 1e-8 the start's own integral
  // of the third kind met R_J(p = 0) and stopped with an internal error). The reference is no
  // closed form: body-frame Euler's equations with gravity's torque and R' = R [w]x at 50
  // digits, from the same double inputs, by Boost.Odeint's Fehlberg 7(8) in fixed steps of
  // 1/4000 s, (h w)^9 ~ 1e-23 a step at the 20 rad/s the fall reaches: its error is far below
  // the closed form's. Over 4 s each top falls and comes back once (released 1e-14 rad from
  // upright, it falls at about 3 s). The same motion by the closed form at 50 digits
  // (bench::MpHeavyTop, hard 17's reference: Boost.Math's Legendre forms, roots from the
  // start's offsets) agrees with this integration within the rounding of the rotations it
  // composes in double (16 eps).
  using mp = boost::multiprecision::cpp_bin_float_50;
  using MpState = std::array<mp, 12>;
  const HeavyTop top{0.5, 0.08, 9.81, 0.0035125, 0.000625};
  for (const double theta0 : {1e-4, 1e-8, 1e-14}) {
    const Quat q0(Eigen::AngleAxisd(theta0, Vec3::UnitY()));
    const Vec3 m0(0, 0, top.I3_kgm2 * 10.0);  // at rest but for the spin, 10 rad/s
    const ExactHeavyTop exact(top, m0, q0);
    const bench::MpHeavyTop closed_form_50(top, m0, q0);
    const mp I1 = top.I1_kgm2, I3 = top.I3_kgm2, Mgl = mp(top.M_kg) * mp(top.g_m_s2) * mp(top.l_m);
    const Mat3 R0 = q0.normalized().toRotationMatrix();
    MpState y{mp(m0.x()), mp(m0.y()), mp(m0.z())};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) y[static_cast<std::size_t>(3 + 3 * i + j)] = R0(i, j);
    const auto f = [&](const MpState& s, MpState& d, const mp&) {
      const mp w[3] = {s[0] / I1, s[1] / I1, s[2] / I3};
      // Gravity's torque about the pivot, in the body: l e3 x R^T (0, 0, -M g) =
      // Mgl (R32, -R31, 0).
      const mp tx = Mgl * s[10], ty = -Mgl * s[9];
      d[0] = s[1] * w[2] - s[2] * w[1] + tx;
      d[1] = s[2] * w[0] - s[0] * w[2] + ty;
      d[2] = s[0] * w[1] - s[1] * w[0];
      for (std::size_t i = 0; i < 3; ++i) {
        const mp* r = &s[3 + 3 * i];
        d[3 + 3 * i] = r[1] * w[2] - r[2] * w[1];
        d[4 + 3 * i] = r[2] * w[0] - r[0] * w[2];
        d[5 + 3 * i] = r[0] * w[1] - r[1] * w[0];
      }
    };
    boost::numeric::odeint::runge_kutta_fehlberg78<MpState, mp> stepper;
    constexpr int kStepsPerSecond = 4000;
    mp t = 0;
    for (int k = 1; k <= 8; ++k) {
      boost::numeric::odeint::integrate_n_steps(stepper, f, y, t, mp(1) / kStepsPerSecond,
                                                kStepsPerSecond / 2);
      t = mp(k) / 2;
      const FreeBodyState e = exact.at(0.5 * k);
      const Vec3 w_ref(static_cast<double>(y[0] / I1), static_cast<double>(y[1] / I1),
                       static_cast<double>(y[2] / I3));
      const Vec3 e3_ref(static_cast<double>(y[5]), static_cast<double>(y[8]),
                        static_cast<double>(y[11]));
      const Vec3 w = e.m_B.cwiseQuotient(Vec3(top.I1_kgm2, top.I1_kgm2, top.I3_kgm2));
      const double dw = (w - w_ref).norm() / w_ref.norm(),
                   de3 = (e.q_BtoS * Vec3::UnitZ() - e3_ref).norm();
      // The closed form's own bound (hard 14): eps (16 + 2 r T), r the fastest Euler rate, T the
      // nutation period.
      const double bound = kEps * (16 + 2 * exact.euler_rate_bound() * exact.nutation_period_s());
      INFO("theta0 " << theta0 << " t " << 0.5 * k << ": w " << dw / kEps << " eps, axis "
                     << de3 / kEps << " eps, bound " << bound / kEps << " eps");
      CHECK(dw <= bound);
      CHECK(de3 <= bound);
      const FreeBodyState r = closed_form_50.at(0.5 * k);
      Mat3 R_ref;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          R_ref(i, j) = static_cast<double>(y[static_cast<std::size_t>(3 + 3 * i + j)]);
      const Vec3 m_ref(static_cast<double>(y[0]), static_cast<double>(y[1]),
                       static_cast<double>(y[2]));
      const double closed_attitude = (r.q_BtoS.toRotationMatrix() - R_ref).norm(),
                   closed_m = (r.m_B - m_ref).norm() / m_ref.norm();
      INFO("50-digit closed form: attitude " << closed_attitude / kEps << " eps, m "
                                             << closed_m / kEps << " eps");
      CHECK(closed_attitude <= 16 * kEps);
      CHECK(closed_m <= 16 * kEps);
    }
  }
}

TEST_CASE("hard 17: a top released near upright is exact at any time, against 50 digits to 1e7 s") {
  // What grows with t is formed in double-double from constants refined from the start (the
  // roots polished, tau', K, c+-, the complete integrals). Near upright the refinement had
  // taken u3 - u2 ~ theta0^2 from the sum of the roots, which even in double-double leaves it
  // 1e-32 absolute (1e-9 relative at 1e-12 rad, so the refinement was refused and the double
  // chain's rounding grew with t: 5.6e4 eps after 1e4 s), and the complete integral's 1 - n+
  // from n+ (no digit left at 1e-16 rad). What is left is bounded: the reduced phase's rounding
  // and the integrals' incomplete parts in double, the same in every period; so the error at any
  // later time stays within the largest over the first period, sampled (kSamplingMargin for the
  // samples' spacing, 16 eps for four rotations composed in double on each side). The 50-digit
  // closed form (roots from the start's offsets) agrees with a 50-digit integration: hard 16.
  constexpr double kSamplingMargin = 2.0;
  constexpr int kSamplesPerPeriod = 40;
  const HeavyTop top{0.5, 0.08, 9.81, 0.0035125, 0.000625};
  for (const double theta0 : {1e-4, 1e-8, 1e-12, 1e-16}) {
    const Quat q0(Eigen::AngleAxisd(theta0, Vec3::UnitY()));
    const Vec3 m0(0, 0, top.I3_kgm2 * 10.0);  // at rest but for the spin, 10 rad/s
    const ExactHeavyTop exact(top, m0, q0);
    const bench::MpHeavyTop ref(top, m0, q0);
    struct Error {
      double attitude, momentum;
    };
    const auto error_at = [&](double t) {
      const FreeBodyState e = exact.at(t), r = ref.at(t);
      return Error{(e.q_BtoS.toRotationMatrix() - r.q_BtoS.toRotationMatrix()).norm(),
                   (e.m_B - r.m_B).norm() / r.m_B.norm()};
    };
    Error first{0.0, 0.0};
    const double period = exact.nutation_period_s();
    for (int k = 0; k < kSamplesPerPeriod; ++k) {
      const Error e = error_at((k + 0.5) * period / kSamplesPerPeriod);
      first = {std::max(first.attitude, e.attitude), std::max(first.momentum, e.momentum)};
    }
    // And that error is the reduced phase's rounding: eps K, a time error of eps T / 2, which
    // the fastest Euler rate r turns into eps r T / 2 (16 eps as below). The top swings to
    // 0.17 rad from hanging down: n- = -du / (1 + u1) = -140, and Pi(n-) as tau + n- G had put
    // G's rounding in double, times its coefficient -1670, on phi and psi (1e3 eps beyond this).
    const double phase_bound = kEps * (16 + 0.5 * exact.euler_rate_bound() * period);
    INFO("theta0 " << theta0 << ": first period attitude " << first.attitude / kEps
                   << " eps, momentum " << first.momentum / kEps << " eps, phase rounding "
                   << phase_bound / kEps << " eps");
    CHECK(first.attitude <= phase_bound);
    CHECK(first.momentum <= phase_bound);
    for (const double t : {1e2 + 0.3, 1e4 + 0.1, 1e6 + 0.2, 1e7 + 0.4}) {
      const Error e = error_at(t);
      INFO("theta0 " << theta0 << " t " << t << ": attitude " << e.attitude / kEps
                     << " eps, momentum " << e.momentum / kEps << " eps; first period "
                     << first.attitude / kEps << ", " << first.momentum / kEps << " eps");
      CHECK(e.attitude <= kSamplingMargin * first.attitude + 16 * kEps);
      CHECK(e.momentum <= kSamplingMargin * first.momentum + 16 * kEps);
    }
  }
}

namespace {
// A quaternion at 50 digits, (w, x, y, z).
using BigQuat = std::array<Big, 4>;

BigQuat big_product(const BigQuat& a, const BigQuat& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
          a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
          a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

// The turn by `angle` about the unit vector along `axis`, at 50 digits.
BigQuat big_turn(const Big& angle, const BigVec& axis) {
  const Big size = sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  const Big s = sin(angle / 2) / size;
  return {cos(angle / 2), s * axis[0], s * axis[1], s * axis[2]};
}

// The largest difference of two quaternions' components, up to their common sign.
double quaternion_distance(const Quat& q, const BigQuat& r) {
  const std::array<double, 4> c{q.w(), q.x(), q.y(), q.z()};
  double same = 0.0, opposite = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    same = std::max(same, std::abs(c[k] - static_cast<double>(r[k])));
    opposite = std::max(opposite, std::abs(c[k] + static_cast<double>(r[k])));
  }
  return std::min(same, opposite);
}
}  // namespace

TEST_CASE("hard 18: symmetric and steady free bodies exact at any time, against 50 digits") {
  // The symmetric top's closed form turns the body by c t about its axis and the whole by |L| t /
  // I_perp about L; a steady spin by |w| t. In double each rate's rounding, a few eps, grew into
  // the angle with t (a flying plate's attitude 7e-9 off after 1e7 s, 9e-6 after 1e10): the
  // rates are double-double now, and the angles reduced by 2 pi there. The reference forms the
  // same closed form from the same doubles at 50 digits. Bounds: the quaternion built and
  // normalised in double, its components within 4 eps; m turned once, within 4 eps |m0|.
  const Quat q0(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  const BigQuat big_q0{Big(q0.w()), Big(q0.x()), Big(q0.y()), Big(q0.z())};
  const double m = 0.2, R = 0.12, a = boost::math::constants::pi<double>() / 12;  // 15 deg
  const Vec3 plate(m * R * R / 4, m * R * R / 4, m * R * R / 2);
  const std::vector<std::pair<Vec3, Vec3>> symmetric{
      {plate, plate.cwiseProduct(Vec3(10 * std::sin(a), 0, 10 * std::cos(a)))},  // flying plate
      {Vec3(1.0, 1.0, 1.5), Vec3(0.3, -0.4, 1.0)},                               // oblate
      {Vec3(2.0, 2.0, 1.0), Vec3(0.7, 0.2, -0.5)},                               // prolate
  };
  for (const auto& [I, m0] : symmetric) {
    const ExactFreeMotion exact(I, m0, q0);
    REQUIRE(exact.kind() == ExactFreeMotion::Kind::symmetric);
    const Big I1 = I[0], I3 = I[2];
    const Big c = (I1 - I3) / (I3 * I1) * Big(m0[2]);
    const BigVec m_big{Big(m0[0]), Big(m0[1]), Big(m0[2])};
    const BigQuat m_quat{Big(0), m_big[0], m_big[1], m_big[2]};
    const BigQuat conj{big_q0[0], -big_q0[1], -big_q0[2], -big_q0[3]};
    const BigQuat L_S = big_product(big_product(big_q0, m_quat), conj);
    const Big L = sqrt(m_big[0] * m_big[0] + m_big[1] * m_big[1] + m_big[2] * m_big[2]);
    for (const double t : {10.0, 1e4, 1e7, 1e10}) {
      const FreeBodyState s = exact.at(t);
      const BigQuat space = big_turn(L / I1 * Big(t), {L_S[1], L_S[2], L_S[3]});
      const BigQuat body = big_turn(c * Big(t), {Big(0), Big(0), Big(1)});
      const BigQuat q = big_product(big_product(space, big_q0), body);
      const Big angle = -c * Big(t);
      const Vec3 m_t(static_cast<double>(m_big[0] * cos(angle) - m_big[1] * sin(angle)),
                     static_cast<double>(m_big[0] * sin(angle) + m_big[1] * cos(angle)), m0[2]);
      INFO("I = " << I.transpose() << ", t = " << t << ": attitude "
                  << quaternion_distance(s.q_BtoS, q) / kEps << " eps, m "
                  << (s.m_B - m_t).norm() / (kEps * m0.norm()) << " eps |m0|");
      REQUIRE(quaternion_distance(s.q_BtoS, q) <= 4 * kEps);
      REQUIRE((s.m_B - m_t).norm() <= 4 * kEps * m0.norm());
    }
  }
  // A steady spin about an axis of an asymmetric body.
  const Vec3 I(1.0, 2.0, 3.0), m0(0.0, 0.0, 2.7);
  const ExactFreeMotion steady(I, m0, q0);
  REQUIRE(steady.kind() == ExactFreeMotion::Kind::steady);
  for (const double t : {10.0, 1e7, 1e10}) {
    const BigQuat q =
        big_product(big_q0, big_turn(Big(m0[2]) / Big(I[2]) * Big(t), {Big(0), Big(0), Big(1)}));
    INFO("t = " << t << ": " << quaternion_distance(steady.at(t).q_BtoS, q) / kEps << " eps");
    REQUIRE(quaternion_distance(steady.at(t).q_BtoS, q) <= 4 * kEps);
  }
}
