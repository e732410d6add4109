#include "bench/components.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "bench/mp_reference.hpp"
#include "core/elliptic.hpp"
#include "core/exact_free_body.hpp"
#include "core/principal_axes.hpp"
#include "solvers/catalog.hpp"

namespace wobble::bench {

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
volatile double g_sink = 0.0;  // keeps timed results alive

struct Point {
  double u, kc2;
  double sn, cn, dn;  // 50-digit reference
};

std::vector<Point> elliptic_points(int per_decade) {
  using mp = boost::multiprecision::cpp_bin_float_50;
  std::vector<Point> pts;
  for (const double kc2 : {0.5, 1e-4, 1e-8, 1e-12, 1e-16}) {
    const double K = complete_K(kc2);
    const mp k = sqrt(mp(1) - mp(kc2));
    std::vector<double> us;
    for (int i = 0; i <= per_decade; ++i) us.push_back(K * i / per_decade);
    for (const double d : {1e-4, 1e-8, 1e-12}) us.push_back(K - d);
    us.back() = std::nextafter(K, 0.0);
    for (const double u : us) {
      mp cn, dn;
      const mp sn = boost::math::jacobi_elliptic(k, mp(u), &cn, &dn);
      pts.push_back(
          {u, kc2, static_cast<double>(sn), static_cast<double>(cn), static_cast<double>(dn)});
    }
  }
  return pts;
}

// Relative error of sn and dn, and of cn relative to 1 (cn vanishes at K and its absolute
// error is what a bounded |cn| <= 1 carries): one figure, in units of eps.
double sncndn_error(const Point& p, double sn, double cn, double dn) {
  const auto rel = [](double a, double b) {
    return b == 0 ? std::abs(a) : std::abs(a - b) / std::abs(b);
  };
  return std::max({rel(sn, p.sn), std::abs(cn - p.cn), rel(dn, p.dn)}) / kEps;
}
}  // namespace

std::vector<ComponentRow> elliptic_bench(const TimingPlan& plan) {
  const std::vector<Point> pts = elliptic_points(40);
  std::vector<ComponentRow> out;
  const std::string cases = "k'^2 0.5 to 1e-16, u in [0, K]";
  double worst = 0.0;
  for (const auto& p : pts) {
    const SnCnDn e = jacobi_sncndn(p.u, p.kc2);
    worst = std::max(worst, sncndn_error(p, e.sn, e.cn, e.dn));
  }
  const auto time_mine = [&] {
    for (const auto& p : pts) g_sink = g_sink + jacobi_sncndn(p.u, p.kc2).dn;
  };
  double worst_boost = 0.0;
  for (const auto& p : pts) {
    double cn, dn;
    const double k = std::sqrt((1 - p.kc2));  // Boost takes the modulus: k'^2 is lost near 1
    const double sn = boost::math::jacobi_elliptic(k, p.u, &cn, &dn);
    worst_boost = std::max(worst_boost, sncndn_error(p, sn, cn, dn));
  }
  const auto time_boost = [&] {
    for (const auto& p : pts) {
      double cn, dn;
      g_sink = g_sink + boost::math::jacobi_elliptic(std::sqrt(1 - p.kc2), p.u, &cn, &dn);
    }
  };
  // The exact solution's w(t) near the separatrix (I = (1, 2, 3), m0 = (1e-4, 1, 1e-4)).
  const ExactFreeMotion motion(Vec3(1, 2, 3), Vec3(1e-4, 1, 1e-4), Quat::Identity());
  // Its accuracy: |w(t) - w_ref(t)| / |w_ref(t)| from k'^2 ~ 1e-4 to 1e-16 (m0 = (s, 1, 2s)),
  // at times across two periods and next to the quarter periods (u near K).
  // Two figures: over the first quarter period (u from u0 to K, where the phase u = u0 + lambda t
  // is small) and over two periods, where the rounding of lambda t (eps u) shifts the phase.
  double worst_quarter = 0.0, worst_w = 0.0;
  for (const double s : {1e-2, 1e-4, 1e-6, 1e-8}) {
    const Vec3 I(1, 2, 3), m0(s, 1, 2 * s);  // circling e3: D = m3^2/3 - m1^2 > 0
    const ExactFreeMotion mine(I, m0, Quat::Identity());
    const MpMotion ref(I, m0);
    const double P = ref.period(), quarter = ref.first_K_time();
    std::vector<double> times;
    for (int i = 0; i <= 40; ++i) times.push_back(quarter * i / 40);
    for (const double d : {-1e-6, -1e-9, -1e-12}) times.push_back(quarter + d);
    const std::size_t n_quarter = times.size();
    for (int i = 0; i <= 40; ++i) times.push_back(2 * P * i / 40);
    for (int q = 1; q <= 7; ++q) times.push_back(quarter + q * P / 4);
    for (std::size_t i = 0; i < times.size(); ++i) {
      const double t = times[i];
      const Vec3 w = mine.momentum_at(t).cwiseQuotient(I), wr = ref.m_at(t).cwiseQuotient(I);
      const double e = (w - wr).norm() / wr.norm() / kEps;
      if (i < n_quarter) worst_quarter = std::max(worst_quarter, e);
      worst_w = std::max(worst_w, e);
    }
  }
  const auto time_w = [&] {
    for (int i = 0; i < 64; ++i) g_sink = g_sink + motion.momentum_at(3.1 * i).x();
  };
  const auto time_attitude = [&] {
    for (int i = 0; i < 64; ++i) g_sink = g_sink + motion.at(3.1 * i).q_BtoS.w();
  };
  // Side by side (median_times_s): the exact w(t) is read against one Boost call.
  const std::vector<double> t =
      median_times_s({time_mine, time_boost, time_w, time_attitude}, plan);
  const double per_point = 1e9 / static_cast<double>(pts.size());
  out.push_back(
      {"elliptic", "wobble jacobi_sncndn(u, k'^2)", cases, worst, "eps", t[0] * per_point});
  out.push_back({"elliptic", "Boost.Math jacobi_elliptic(k, u), default policy", cases, worst_boost,
                 "eps", t[1] * per_point});
  const double t_w = t[2] / 64, t_att = t[3] / 64;
  out.push_back({"elliptic", "wobble exact w(t) (m(t) / I)",
                 "m0 = (s, 1, 2s), s 1e-2 to 1e-8, to u = K", worst_quarter, "eps (|dw| / |w|)",
                 t_w * 1e9});
  out.push_back({"elliptic", "wobble exact w(t), over two periods", "the same, t to 2 periods",
                 worst_w, "eps (|dw| / |w|)", t_w * 1e9});
  out.push_back({"elliptic", "wobble exact w(t) and attitude", "P3 body, t from 0 to 195", -1.0, "",
                 t_att * 1e9});
  return out;
}

std::vector<ComponentRow> principal_axes_bench(const TimingPlan& plan) {
  struct Case {
    std::string name;
    Vec3 moments;
  };
  const Case cases[] = {{"separated (1, 2, 3)", Vec3(1, 2, 3)},
                        {"degenerate (1, 1, 3)", Vec3(1, 1, 3)},
                        {"nearly degenerate (1, 1 + 1e-12, 3)", Vec3(1, 1 + 1e-12, 3)},
                        {"badly scaled (1e-6, 1, 1e6)", Vec3(1e-6, 1, 1e6)},
                        {"needle (1e-12, 1, 1)", Vec3(1e-12, 1, 1)}};
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  std::vector<ComponentRow> out;
  for (const auto& c : cases) {
    const Mat3 I = R * c.moments.asDiagonal() * R.transpose();
    // Error: eigenvalues relative to the largest, and the axes' residual |I e - l e| / l_max.
    const auto error_of = [&](const Vec3& l, const Mat3& axes) {
      Vec3 sorted = l;
      std::sort(sorted.data(), sorted.data() + 3);
      double e = (sorted - c.moments).cwiseAbs().maxCoeff();
      for (int i = 0; i < 3; ++i) e = std::max(e, (I * axes.col(i) - l[i] * axes.col(i)).norm());
      e = std::max(e, (axes.transpose() * axes - Mat3::Identity()).cwiseAbs().maxCoeff() *
                          c.moments.maxCoeff());
      return e / c.moments.maxCoeff() / kEps;
    };
    const PrincipalAxes pa = principal_axes(I);
    Eigen::SelfAdjointEigenSolver<Mat3> es(I);
    Eigen::SelfAdjointEigenSolver<Mat3> ed;
    ed.computeDirect(I);
    // Side by side (median_times_s): the three are read against each other.
    const std::vector<double> t =
        median_times_s({[&] { g_sink = g_sink + principal_axes(I).moments[0]; },
                        [&] {
                          Eigen::SelfAdjointEigenSolver<Mat3> s(I);
                          g_sink = g_sink + s.eigenvalues()[0];
                        },
                        [&] {
                          Eigen::SelfAdjointEigenSolver<Mat3> s;
                          s.computeDirect(I);
                          g_sink = g_sink + s.eigenvalues()[0];
                        }},
                       plan);
    out.push_back({"principal axes", "wobble principal_axes", c.name, error_of(pa.moments, pa.axes),
                   "eps l_max", t[0] * 1e9});
    out.push_back({"principal axes", "Eigen compute()", c.name,
                   error_of(es.eigenvalues(), es.eigenvectors()), "eps l_max", t[1] * 1e9});
    out.push_back({"principal axes", "Eigen computeDirect()", c.name,
                   error_of(ed.eigenvalues(), ed.eigenvectors()), "eps l_max", t[2] * 1e9});
  }
  return out;
}

namespace {
// Seconds from spawning the program with `args` (its output to /dev/null) to its exit, or -1 if
// it fails. Spawned directly, not through std::system: /bin/sh's own start (3.5 ms on the
// machine of the README's figures) is not the program's.
double run_seconds(const std::string& exe, const std::vector<std::string>& args) {
  std::vector<char*> argv{const_cast<char*>(exe.c_str())};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&files, STDOUT_FILENO, STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, exe.c_str(), &files, nullptr, argv.data(), environ);
  int status = 0;
  const bool ok = spawned == 0 && waitpid(pid, &status, 0) == pid && WIFEXITED(status) &&
                  WEXITSTATUS(status) == 0;
  const auto end = std::chrono::steady_clock::now();
  posix_spawn_file_actions_destroy(&files);
  return ok ? std::chrono::duration<double>(end - start).count() : -1.0;
}
}  // namespace

std::vector<ComponentRow> process_bench(const std::string& exe, int repeats) {
  // The median of `repeats` runs, or -1 if a run fails.
  const auto time_command = [&](const std::vector<std::string>& args) {
    std::vector<double> t;
    for (int r = 0; r < repeats; ++r) {
      t.push_back(run_seconds(exe, args));
      if (t.back() < 0) return -1.0;
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
  };
  std::vector<ComponentRow> out;
  for (const auto& p : load_catalog()) {
    out.push_back(
        {"process", "wobble solve " + p.id, "", -1.0, "", time_command({"solve", p.id}) * 1e9});
  }
  out.push_back(
      {"process", "wobble keys --check", "", -1.0, "", time_command({"keys", "--check"}) * 1e9});
  return out;
}

std::string machine_description() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  return fmt::format("{}, {} hardware threads", model, std::thread::hardware_concurrency());
}

}  // namespace wobble::bench
