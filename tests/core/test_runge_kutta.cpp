// Runge-Kutta methods on the rigid body: measured orders, tolerance control, drift of the
// invariants, and the torques (gravity about a pivot, a constant torque in space).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "core/exact_free_body.hpp"
#include "core/runge_kutta.hpp"
#include "core/runge_kutta_tableaux.hpp"

using namespace wobble;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
const Vec3 kI(2.0, 1.0, 2.0 / 3.0);
const Vec3 kM0(std::cos(1.1), 0.0, std::sin(1.1));

RigidBodyModel free_model() {
  RigidBodyModel m;
  m.I_P = kI;
  return m;
}

double error_at(const RigidBodyModel& model, RkMethod method, double tol_or_h, bool fixed, double T,
                IntegrationCost* cost = nullptr) {
  RungeKutta rk(model, method, tol_or_h, 1.0, fixed);
  State7 y = pack(kM0, Quat::Identity());
  rk.advance(y, 0.0, T);
  if (cost) *cost = rk.cost();
  const FreeBodyState ex = ExactFreeMotion(kI, kM0, Quat::Identity()).at(T);
  return std::max((momentum_of(y) - ex.m_B).norm(),
                  (attitude_of(y).toRotationMatrix() - ex.q_BtoS.toRotationMatrix()).norm());
}
}  // namespace

TEST_CASE("each Runge-Kutta method converges at its order when the step halves (measured)") {
  const RigidBodyModel model = free_model();
  // Steps chosen in each method's asymptotic range and with errors >= 3e-14, well above the
  // exact solution's round-off (~1e-15): the observed order log2(e(h)/e(h/2)) is then the
  // method's up to higher-order terms, which the halvings below leave within 0.3.
  // Verner's 9(8) has a small leading error coefficient (he chose the pair so): at steps whose
  // error stays above round-off the order-10 term still shows, and the observed order is 9.6
  // to 9.8; there the test asks for at least p - 0.3 and at most p + 1 (the order conditions'
  // test below checks its order exactly). 10 / 9 s: nine, eighteen, 36 whole steps over 10 s.
  for (const auto& [method, h0] : {std::pair{RkMethod::rk4, 0.2}, std::pair{RkMethod::dopri5, 0.2},
                                   std::pair{RkMethod::rkf78, 0.5},
                                   std::pair{RkMethod::dop853, 0.6},
                                   std::pair{RkMethod::vern9, 10.0 / 9.0}}) {
    const double e1 = error_at(model, method, h0, true, 10.0),
                 e2 = error_at(model, method, h0 / 2, true, 10.0),
                 e3 = error_at(model, method, h0 / 4, true, 10.0);
    const double p = order_of(method);
    const double above = method == RkMethod::vern9 ? 1.0 : 0.3;
    INFO(name_of(method) << ": errors " << e1 << ", " << e2 << ", " << e3);
    REQUIRE(e3 >= 3e-14);
    for (const double observed : {std::log2(e1 / e2), std::log2(e2 / e3)}) {
      REQUIRE(observed >= p - 0.3);
      REQUIRE(observed <= p + above);
    }
  }
}

TEST_CASE("adaptive pairs meet their tolerance, and tighter costs more") {
  const RigidBodyModel model = free_model();
  for (const RkMethod method :
       {RkMethod::dopri5, RkMethod::rkf78, RkMethod::dop853, RkMethod::vern9}) {
    std::int64_t last_evals = 0;
    for (const double tol : {1e-6, 1e-9, 1e-12}) {
      IntegrationCost cost;
      const double e = error_at(model, method, tol, false, 10.0, &cost);
      INFO(name_of(method) << " tol " << tol << ": error " << e << ", " << cost.rhs_evals);
      // Per-step control to tol over ~20-300 steps of a non-expanding flow: the global error
      // stays within 100 tol (measured 0.03-2.3 tol).
      REQUIRE(e <= 100 * tol);
      REQUIRE(cost.rhs_evals > last_evals);
      last_evals = cost.rhs_evals;
    }
  }
}

TEST_CASE("dense output: states between the steps as accurate as at them, the steps unchanged") {
  const RigidBodyModel model = free_model();
  const ExactFreeMotion exact(kI, kM0, Quat::Identity());
  constexpr double kTol = 1e-10, kT = 10.0;
  const auto times_of = [&](std::size_t n) {
    std::vector<double> t(n);
    for (std::size_t i = 0; i < n; ++i) t[i] = kT * static_cast<double>(i + 1) / static_cast<double>(n);
    return t;
  };
  for (const RkMethod method : {RkMethod::dopri5, RkMethod::dop853}) {
    const auto run = [&](std::size_t n, double* worst) {
      RungeKutta rk(model, method, kTol, 1.0);
      State7 y = pack(kM0, Quat::Identity());
      const std::vector<double> times = times_of(n);
      rk.sample(y, 0.0, times, [&](std::size_t k, const State7& s) {
        const FreeBodyState ex = exact.at(times[k]);
        const double e = std::max((momentum_of(s) - ex.m_B).norm(),
                                  (attitude_of(s).toRotationMatrix() -
                                   ex.q_BtoS.toRotationMatrix()).norm());
        if (worst) *worst = std::max(*worst, e);
        // Unit quaternion as given, not only after attitude_of normalises it.
        REQUIRE_THAT(s.tail<4>().norm(), WithinAbs(1.0, 4 * std::numeric_limits<double>::epsilon()));
      });
      return std::pair{rk.cost(), y};
    };
    double worst = 0.0;
    const auto [few, y_few] = run(10, nullptr);
    const auto [many, y_many] = run(10000, &worst);
    RungeKutta plain(model, method, kTol, 1.0);
    State7 y_plain = pack(kM0, Quat::Identity());
    plain.advance(y_plain, 0.0, kT);
    INFO(name_of(method) << ": worst sample error " << worst << "; steps " << few.steps << " / "
                         << many.steps << ", evaluations " << few.rhs_evals << " / "
                         << many.rhs_evals);
    // The same bound as the step ends' (above): the interpolants' error is of the local
    // error's size (orders 4 and 7, one less than the steps').
    REQUIRE(worst <= 100 * kTol);
    REQUIRE(worst > 0.0);
    // The output times never shorten a step: the same steps, and the same end state as
    // advance() (bit for bit).
    REQUIRE(many.steps == few.steps);
    REQUIRE(few.steps == plain.cost().steps);
    REQUIRE(y_many == y_plain);
    REQUIRE(y_few == y_plain);
    // Dormand-Prince's interpolant costs no evaluation; DOP853's three per step with an output.
    const std::int64_t extra = method == RkMethod::dopri5 ? 0 : 3 * many.steps;
    REQUIRE(many.rhs_evals <= plain.cost().rhs_evals + extra);
  }
}

TEST_CASE("samples and end states are unit quaternions however far |q| starts from 1") {
  // |q|^2 - 1 = d: near 1 (|d| <= 2^-18) the factor 1 / |q| is a two-term series, beyond it a
  // square root. The first step's samples are interpolated from the start, so they see d as
  // given; a wrong series term (3/8 d^2 off by 0.075 d^2 = 7e-13 at d = 3e-6) fails here.
  const RigidBodyModel model = free_model();
  const ExactFreeMotion exact(kI, kM0, Quat::Identity());
  constexpr double kTol = 1e-10, kT = 2.0;
  const double eps = std::numeric_limits<double>::epsilon();
  std::vector<double> times;
  for (double t = 1e-7; t < 1e-3; t *= 1.5) times.push_back(t);  // inside the first step
  for (int i = 1; i <= 100; ++i) times.push_back(kT * i / 100);
  for (const double d : {0x1p-18, -0x1p-18, 3e-6, 1e-6, -1e-6, 1e-9, 0.5, -0.3}) {
    for (const RkMethod method : {RkMethod::dopri5, RkMethod::dop853}) {
      INFO(name_of(method) << ", |q|^2 - 1 = " << d << " at the start");
      RungeKutta rk(model, method, kTol, 1.0);
      State7 y = pack(kM0, Quat::Identity());
      y.tail<4>() *= std::sqrt(1.0 + d);
      std::size_t seen = 0;
      rk.sample(y, 0.0, times, [&](std::size_t k, const State7& s) {
        ++seen;
        // The sample's |q|^2: within four roundings of 1.
        REQUIRE_THAT(s.tail<4>().squaredNorm(), WithinAbs(1.0, 4 * eps));
        const FreeBodyState ex = exact.at(times[k]);
        REQUIRE((momentum_of(s) - ex.m_B).norm() <= 100 * kTol);
        REQUIRE((attitude_of(s).toRotationMatrix() - ex.q_BtoS.toRotationMatrix()).norm() <=
                100 * kTol);
      });
      REQUIRE(seen == times.size());
      REQUIRE_THAT(y.tail<4>().squaredNorm(), WithinAbs(1.0, 4 * eps));
    }
  }
}

TEST_CASE("the tableaux: weights sum to one, error weights to zero, interpolants end at y_new") {
  namespace tab = rk_tableau;
  const double eps = std::numeric_limits<double>::epsilon();
  // Each sum has at most 16 terms of size up to ~500 (DOP853's D): rounding within
  // 16 * 500 eps of the exact sum.
  const double bound = 16 * 500 * eps;
  const auto sum = [](const auto& row) {
    double s = 0.0;
    for (const double c : row) s += c;
    return s;
  };
  REQUIRE_THAT(sum(tab::Dop853::B), WithinAbs(1.0, bound));
  REQUIRE_THAT(sum(tab::Dop853::E), WithinAbs(0.0, bound));
  REQUIRE_THAT(sum(tab::Dop853::E3), WithinAbs(0.0, bound));
  REQUIRE_THAT(sum(tab::Dopri5::B), WithinAbs(1.0, bound));
  // Shampine's interpolant at x = 1 is the step's own solution: sum_p P[j][p] = B[j].
  // It also has the end slopes, y'(0) = k_1 and y'(1) = k_7 (sum_p (p + 1) P[j][p] is 1 for the
  // last stage, 0 for the others): so it is the cubic Hermite interpolant plus x^2 (1-x)^2
  // times its x^4 coefficient.
  for (std::size_t j = 0; j < tab::Dopri5::S; ++j) {
    const auto& P = tab::Dopri5::P[j];
    REQUIRE_THAT(sum(P), WithinAbs(tab::Dopri5::B[j], bound));
    REQUIRE_THAT(P[0], WithinAbs(j == 0 ? 1.0 : 0.0, bound));
    REQUIRE_THAT(P[0] + 2 * P[1] + 3 * P[2] + 4 * P[3],
                 WithinAbs(j == tab::Dopri5::S - 1 ? 1.0 : 0.0, 4 * bound));
  }
  // Every row of A sums to its node c_i; the nodes lie in [0, 1] (DOP853's three extra stages
  // at 0.1, 0.2 and 7/9, Hairer's values).
  for (const auto& row : tab::Dop853::A) {
    REQUIRE(sum(row) >= -bound);
    REQUIRE(sum(row) <= 1.0 + bound);
  }
  REQUIRE_THAT(sum(tab::Dop853::kExtraA[0]), WithinAbs(0.1, bound));
  REQUIRE_THAT(sum(tab::Dop853::kExtraA[1]), WithinAbs(0.2, bound));
  REQUIRE_THAT(sum(tab::Dop853::kExtraA[2]), WithinAbs(7.0 / 9.0, bound));
}

namespace {
// Butcher's order conditions: a tableau (A, b) has order p when sum_i b_i Phi_i(t) = 1 / gamma(t)
// for every rooted tree t of at most p nodes, where Phi_i(leaf) = 1, Phi_i(t) = prod over the
// root's subtrees c of (A Phi(c))_i, and gamma(t) = |t| prod gamma(c).
struct RootedTree {
  std::vector<std::size_t> children;  // indices of earlier trees, in nondecreasing order
  int nodes = 1;
  double gamma = 1.0;
};

// Every rooted tree of up to max_nodes nodes, each once (children as a multiset of earlier trees).
std::vector<RootedTree> rooted_trees(int max_nodes) {
  std::vector<RootedTree> trees{RootedTree{}};
  for (int n = 2; n <= max_nodes; ++n) {
    const std::size_t known = trees.size();
    std::vector<std::size_t> chosen;
    // Children from index `from` on, with `left` nodes still to place.
    const auto extend = [&](const auto& self, std::size_t from, int left) -> void {
      if (left == 0) {
        RootedTree t{chosen, n, static_cast<double>(n)};
        for (const std::size_t c : chosen) t.gamma *= trees[c].gamma;
        trees.push_back(t);
        return;
      }
      for (std::size_t c = from; c < known; ++c) {
        if (trees[c].nodes > left) continue;
        chosen.push_back(c);
        self(self, c, left - trees[c].nodes);
        chosen.pop_back();
      }
    };
    extend(extend, 0, n - 1);
  }
  return trees;
}

// The largest |b . Phi(t) - 1/gamma(t)| over the trees of exactly `nodes` nodes, relative to
// the rounding bound (nodes + S) eps |b| . |Phi|(t): each term of the expanded sum is a product
// of `nodes` coefficients, each rounded to double, summed over at most S stages per level.
template <std::size_t S>
double worst_order_residual(const std::array<std::array<double, S>, S>& A,
                            const std::array<double, S>& b, const std::vector<RootedTree>& trees,
                            int nodes) {
  using Vec = std::array<double, S>;
  std::vector<Vec> phi(trees.size()), phi_abs(trees.size());
  double worst = 0.0;
  for (std::size_t t = 0; t < trees.size(); ++t) {
    phi[t].fill(1.0);
    phi_abs[t].fill(1.0);
    for (const std::size_t c : trees[t].children) {
      for (std::size_t i = 0; i < S; ++i) {
        double a_phi = 0.0, a_phi_abs = 0.0;
        for (std::size_t j = 0; j < S; ++j) {
          a_phi += A[i][j] * phi[c][j];
          a_phi_abs += std::abs(A[i][j]) * phi_abs[c][j];
        }
        phi[t][i] *= a_phi;
        phi_abs[t][i] *= a_phi_abs;
      }
    }
    if (trees[t].nodes != nodes) continue;
    double sum = 0.0, sum_abs = 0.0;
    for (std::size_t i = 0; i < S; ++i) {
      sum += b[i] * phi[t][i];
      sum_abs += std::abs(b[i]) * phi_abs[t][i];
    }
    const double bound =
        static_cast<double>(nodes + static_cast<int>(S)) * std::numeric_limits<double>::epsilon() *
        sum_abs;
    worst = std::max(worst, std::abs(sum - 1.0 / trees[t].gamma) / bound);
  }
  return worst;
}

}  // namespace

TEST_CASE("the tableaux meet every order condition up to their order, and not the next") {
  namespace tab = rk_tableau;
  const std::vector<RootedTree> trees = rooted_trees(10);
  // The count of rooted trees with n nodes (OEIS A000081): the enumeration misses none.
  const std::vector<int> expected{1, 1, 2, 4, 9, 20, 48, 115, 286, 719};
  for (int n = 1; n <= 10; ++n) {
    REQUIRE(std::count_if(trees.begin(), trees.end(),
                          [&](const RootedTree& t) { return t.nodes == n; }) ==
            expected[static_cast<std::size_t>(n - 1)]);
  }
  // Each weight row: every condition of order <= p within its rounding bound (ratio <= 1), and
  // some condition of order p + 1 missed by far more (the order is p, not more).
  const auto check = [&](const auto& A, const auto& b, int p, const char* what) {
    INFO(what << ", order " << p);
    for (int n = 1; n <= p; ++n) {
      INFO("trees of " << n << " nodes");
      REQUIRE(worst_order_residual(A, b, trees, n) <= 1.0);
    }
    REQUIRE(worst_order_residual(A, b, trees, p + 1) > 1e6);
  };
  check(tab::Rk4::A, tab::Rk4::B, 4, "rk4");
  check(tab::Dopri5::A, tab::Dopri5::B, 5, "dopri5");
  check(tab::Dopri5::A, tab::difference(tab::Dopri5::B, tab::Dopri5::E), 4, "dopri5's estimate");
  check(tab::Rkf78::A, tab::Rkf78::B, 8, "rkf78");
  check(tab::Rkf78::A, tab::difference(tab::Rkf78::B, tab::Rkf78::E), 7, "rkf78's estimate");
  check(tab::Dop853::A, tab::Dop853::B, 8, "dop853");
  check(tab::Vern9::A, tab::Vern9::B, 9, "vern9");
  check(tab::Vern9::A, tab::Vern9::kBHat, 8, "vern9's order-8 member");
  check(tab::Vern9::A, tab::difference(tab::Vern9::B, tab::Vern9::E), 8,
        "vern9 from its estimate");
}

TEST_CASE("output times out of order are refused") {
  RungeKutta rk(free_model(), RkMethod::dop853, 1e-8, 1.0);
  State7 y = pack(kM0, Quat::Identity());
  const std::vector<double> times{1.0, 0.5};
  REQUIRE_THROWS_AS(rk.sample(y, 0.0, times, [](std::size_t, const State7&) {}),
                    std::invalid_argument);
}

TEST_CASE("Runge-Kutta energy error drifts at most linearly in time (a bound)") {
  // Not structure-preserving: the energy error grows, roughly linearly for this periodic
  // motion. Bound: over 10x the time, at most 10x the error, with a factor 3 for the phase of
  // the oscillation at which each run ends.
  const RigidBodyModel model = free_model();
  const double E0 = model.kinetic(kM0);
  RungeKutta rk(model, RkMethod::dopri5, 1e-8, 1.0);
  State7 y = pack(kM0, Quat::Identity());
  double t = 0, worst100 = 0, worst1000 = 0;
  for (int k = 1; k <= 1000; ++k) {
    rk.advance(y, t, k * 1.0);
    t = k;
    const double e = std::abs(model.kinetic(momentum_of(y)) - E0);
    (k <= 100 ? worst100 : worst1000) = std::max(k <= 100 ? worst100 : worst1000, e);
  }
  worst1000 = std::max(worst1000, worst100);
  INFO("energy error to T=100: " << worst100 << ", to T=1000: " << worst1000);
  REQUIRE(worst100 > 0.0);
  REQUIRE(worst1000 <= 30 * worst100);
}

TEST_CASE("heavy symmetric top: energy, p_phi and p_psi conserved to the tolerance") {
  RigidBodyModel m;
  m.I_P = Vec3(0.0035, 0.0035, 0.000625);  // about the pivot; e3 the axle
  m.gravity = true;
  m.mass_kg = 0.5;
  m.d_P_m = Vec3(0, 0, 0.08);
  m.g_S = Vec3(0, 0, -9.81);
  const Quat q0(Eigen::AngleAxisd(0.5, Vec3::UnitY()));
  const Vec3 m0(0, 0, m.I_P.z() * 150);
  RungeKutta rk(m, RkMethod::rkf78, 1e-11, m0.norm());
  State7 y = pack(m0, q0);
  const double E0 = m.kinetic(m0) + m.potential(q0);
  const double pphi0 = (q0 * m0).z(), ppsi0 = m0.z();
  double t = 0;
  for (int k = 1; k <= 200; ++k) {
    rk.advance(y, t, k * 0.01);
    t = k * 0.01;
    // Between steps |q| may stray (it never enters the motion); advance() hands back a unit q.
    REQUIRE_THAT(y.tail<4>().norm(), WithinAbs(1.0, 4 * std::numeric_limits<double>::epsilon()));
    const Vec3 mm = momentum_of(y);
    const Quat q = attitude_of(y);
    // Per-step tolerance 1e-11 relative to |m0| over ~1000 steps: within 1000 tol (linear
    // accumulation); measured ~50 tol.
    const double bound = 1e3 * 1e-11;
    REQUIRE_THAT(m.kinetic(mm) + m.potential(q), WithinAbs(E0, bound * std::abs(E0)));
    REQUIRE_THAT((q * mm).z(), WithinAbs(pphi0, bound * m0.norm()));
    REQUIRE_THAT(mm.z(), WithinAbs(ppsi0, bound * m0.norm()));
  }
  // Gravity does act: the axle has moved (precession), unlike a torque-free top released so.
  REQUIRE((attitude_of(y) * Vec3::UnitZ() - q0 * Vec3::UnitZ()).norm() > 1e-2);
}

TEST_CASE("the torques rotate by q / |q|: a stage's quaternion off unit length changes nothing") {
  RigidBodyModel m;
  m.I_P = Vec3(1, 2, 3);
  m.gravity = true;
  m.mass_kg = 0.7;
  m.d_P_m = Vec3(0.01, -0.02, 0.08);
  m.g_S = Vec3(0.1, 0.2, -9.81);
  m.torque = true;
  m.torque_in_space = true;
  m.torque_Nm = Vec3(0.3, -0.5, 0.2);
  const Quat unit(Eigen::AngleAxisd(2.1, Vec3(0.3, -1.0, 0.4).normalized()));
  // The reference: Eigen's rotation matrix of the unit quaternion, transposed.
  const Eigen::Matrix3d R = unit.toRotationMatrix();
  const Vec3 expected = m.d_P_m.cross(R.transpose() * (m.mass_kg * m.g_S)) +
                        R.transpose() * m.torque_Nm;
  // Each term is a few roundings of products of size |d| M |g| or |tau|.
  const double eps = std::numeric_limits<double>::epsilon();
  const double bound =
      16 * eps * (m.d_P_m.norm() * m.mass_kg * m.g_S.norm() + m.torque_Nm.norm());
  for (const double scale : {1.0, 1.0 + 1e-9, 0.999, 3.0}) {
    const Quat q(scale * unit.w(), scale * unit.x(), scale * unit.y(), scale * unit.z());
    INFO("|q| = " << scale);
    REQUIRE((m.torque_P(Vec3::Zero(), q) - expected).norm() <= bound);
    // rhs() takes the same torque from the state's raw quaternion.
    const State7 dy = m.rhs(pack(Vec3::Zero(), q));
    REQUIRE((dy.head<3>() - expected).norm() <= bound);
  }
}

TEST_CASE("the prepared right-hand side is the model's equations, and keeps its own copy") {
  RigidBodyModel m;
  m.I_P = Vec3(0.7, 1.9, 3.1);
  m.gravity = true;
  m.mass_kg = 1.3;
  m.d_P_m = Vec3(0.1, -0.05, 0.2);
  const Vec3 m_P(0.4, -1.2, 2.5);
  const Quat q = Quat(Eigen::AngleAxisd(0.8, Vec3(1, 2, -1).normalized()));
  // The equations as the header states them, with w = m / I (divisions) and m x w as a cross
  // product: an evaluation independent of the prepared one's reciprocals and Euler's form.
  const Vec3 w = m_P.cwiseQuotient(m.I_P);
  const Vec3 tau = m.d_P_m.cross(q.conjugate() * (m.mass_kg * m.g_S));
  const Vec3 dm = m_P.cross(w) + tau;
  const Quat dq = q * Quat(0, w.x(), w.y(), w.z());
  const State7 expected = pack(dm, Quat(0.5 * dq.w(), 0.5 * dq.x(), 0.5 * dq.y(), 0.5 * dq.z()));
  // Each component: a few roundings of terms of size |m| |w| or |d| M |g|.
  const double eps = std::numeric_limits<double>::epsilon();
  const double bound =
      16 * eps * (m_P.norm() * w.norm() + m.d_P_m.norm() * m.mass_kg * m.g_S.norm());
  const RigidBodyRhs f(m);
  const State7 y = pack(m_P, q);
  REQUIRE((f(y) - expected).cwiseAbs().maxCoeff() <= bound);
  // rhs() evaluates through the prepared form: the same values, bit for bit.
  REQUIRE(m.rhs(y) == f(y));
  // A copy: changing the model afterwards leaves the prepared right-hand side as it was.
  const State7 before = f(y);
  m.I_P = Vec3(5, 5, 5);
  m.gravity = false;
  REQUIRE(f(y) == before);
  REQUIRE(m.rhs(y) != before);
}

TEST_CASE("a constant torque in space adds tau t to L in space, exactly") {
  RigidBodyModel m;
  m.I_P = Vec3(1, 2, 3);
  m.torque = true;
  m.torque_in_space = true;
  m.torque_Nm = Vec3(0.1, -0.2, 0.3);
  const Vec3 m0(0.5, 0.2, -0.4);
  RungeKutta rk(m, RkMethod::rkf78, 1e-12, 1.0);
  State7 y = pack(m0, Quat::Identity());
  rk.advance(y, 0, 7.0);
  const Vec3 L = attitude_of(y) * momentum_of(y);
  // dL_S/dt = tau exactly; the integration error is within ~steps * tol * scale.
  REQUIRE((L - (m0 + 7.0 * m.torque_Nm)).norm() <= 1e-9);
}

TEST_CASE("integrator input is validated") {
  const RigidBodyModel model = free_model();
  REQUIRE_THROWS_AS(RungeKutta(model, RkMethod::dopri5, 0.0, 1.0), std::invalid_argument);
  REQUIRE_THROWS_AS(RungeKutta(model, RkMethod::dopri5, 1e-8, NAN), std::invalid_argument);
  RigidBodyModel bad = model;
  bad.I_P = Vec3(1, 0, 1);
  REQUIRE_THROWS_AS(RungeKutta(bad, RkMethod::rk4, 0.1, 1.0), std::invalid_argument);
}
