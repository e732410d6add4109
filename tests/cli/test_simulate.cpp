// `wobble simulate` and `solve --cross-check` as a user runs them.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include "cli/run.hpp"
#include "core/exact_free_body.hpp"
#include "core/exact_heavy_top.hpp"
#include "temp_files.hpp"

using namespace wobble::test;
namespace fs = std::filesystem;

TEST_CASE("simulate prints header, samples and footer for every example scene") {
  for (const std::string id :
       {"tennis-racket", "flying-plate", "thrown-plate", "heavy-top", "spin-up", "wheel-brake"}) {
    const RunResult r = run_wobble({"simulate", id});
    INFO(id << "\n" << r.err);
    REQUIRE(r.exit_code == 0);
    // Piped (not a terminal): no progress on stderr.
    REQUIRE(r.err.empty());
    for (const std::string& w :
         {"scene " + id, std::string("principal moments"), std::string("effects: "),
          std::string("method: "), std::string("time: 0 to"), std::string("cost: ")}) {
      CHECK_THAT(r.out, Catch::Contains(w));
    }
  }
  const RunResult racket = run_wobble({"simulate", "tennis-racket"});
  CHECK_THAT(racket.out, Catch::Contains("method: exact (torque-free") &&
                             Catch::Contains("changes sign every") &&
                             Catch::Contains("rotational_energy"));
  // A pendulum swinging in a plane passes through hanging down: the header says what the
  // Euler angles do there.
  const RunResult swing = run_wobble(
      {"simulate", "heavy-top", "--set", "psidot0=0", "--set", "thetadot0=2", "--samples", "3"});
  CHECK_THAT(swing.out, Catch::Contains("theta nods between 27.88010542 and 180 deg") &&
                            Catch::Contains("passes through the vertical (hanging straight down)"));
  const RunResult top = run_wobble({"simulate", "heavy-top", "--method", "dopri5"});
  CHECK_THAT(top.out, Catch::Contains("method: dopri5 (requested)") && Catch::Contains("p_phi") &&
                          Catch::Contains("p_psi") &&
                          Catch::Contains("right-hand-side evaluations"));
}

TEST_CASE("simulate --out writes CSV or JSON atomically and never overwrites without --force") {
  const fs::path dir = scratch_dir() / "simulate";
  fs::create_directories(dir);
  const fs::path csv = dir / "racket.csv", json = dir / "racket.json";
  fs::remove(csv);
  fs::remove(json);
  const RunResult r =
      run_wobble({"simulate", "tennis-racket", "--out", csv.string(), "--set", "w=10"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE_THAT(r.out, Catch::Contains("wrote 41 samples to"));
  std::istringstream lines(slurp(csv));
  std::string header, line;
  std::getline(lines, header);
  REQUIRE_THAT(header, Catch::StartsWith("t [s],omega_body_x [rad/s]"));
  int rows = 0;
  while (std::getline(lines, line)) ++rows;
  REQUIRE(rows == 41);

  REQUIRE(run_wobble({"simulate", "tennis-racket", "--out", json.string()}).exit_code == 0);
  const auto j = nlohmann::json::parse(slurp(json));
  REQUIRE(j["method"] == "exact");
  REQUIRE(j["rows"].size() == 41);
  REQUIRE(j["columns"][1] == "omega_body_x");
  REQUIRE(j["invariants"].size() == 3);

  std::ofstream(csv) << "mine\n";
  const RunResult again = run_wobble({"simulate", "tennis-racket", "--out", csv.string()});
  REQUIRE(again.exit_code == 2);
  REQUIRE(slurp(csv) == "mine\n");
  REQUIRE(run_wobble({"simulate", "tennis-racket", "--out", csv.string(), "--force"}).exit_code ==
          0);
  REQUIRE(slurp(csv) != "mine\n");
  for (const auto& entry : fs::directory_iterator(dir)) {
    CHECK(entry.path().filename().string()[0] != '.');  // no temporaries left
  }
}

namespace {
wobble::Vec3 vec3(const nlohmann::json& a) {
  return wobble::Vec3(a[0].get<double>(), a[1].get<double>(), a[2].get<double>());
}

// A scene file's text with its outputs replaced.
std::string with_outputs(const std::string& id, const std::string& outputs) {
  std::string text = slurp(fs::path(WOBBLE_SOURCE_DIR) / "scenes" / (id + ".toml"));
  const std::size_t at = text.find("outputs = ");
  text.replace(at, text.find('\n', at) - at, "outputs = " + outputs);
  return text;
}
}  // namespace

TEST_CASE(
    "simulate's JSON carries the equations as run: the exact solution from them is its rows") {
  // The model is written as the shortest text of each double, so a check started from it starts
  // from the very numbers the run used: here the exact solutions, rebuilt from the JSON alone,
  // give every row's L_body and e3_space bit for bit (a value rounded to fewer digits, or one
  // from before the axes were ordered, would not).
  for (const std::string id : {"heavy-top", "tennis-racket"}) {
    const fs::path scene =
        write_file(id + "-L.toml", with_outputs(id, R"(["L_body", "e3_space"])"));
    const fs::path out = scratch_dir() / (id + "-L.json");
    const RunResult r = run_wobble({"simulate", scene.string(), "--method", "exact", "--out",
                                    out.string(), "--t-end", "50", "--samples", "7"});
    INFO(id << "\n" << r.err);
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(slurp(out));
    const auto& m = j["model"];
    const wobble::Vec3 I = vec3(m["I_P"]), m0 = vec3(m["L0_P"]);
    const wobble::Quat q0(m["q0_PtoS"][0], m["q0_PtoS"][1], m["q0_PtoS"][2], m["q0_PtoS"][3]);
    wobble::Mat3 axes;
    for (int c = 0; c < 3; ++c) axes.col(c) = vec3(m["axes_in_B"][c]);
    std::function<wobble::FreeBodyState(double)> at;
    if (id == "heavy-top") {
      REQUIRE(m.contains("mass"));
      const wobble::HeavyTop top{m["mass"], vec3(m["com_from_pivot_P"]).z(), -vec3(m["g_S"]).z(),
                                 I.x(), I.z()};
      at = [motion = wobble::ExactHeavyTop(top, m0, q0)](double t) { return motion.at(t); };
    } else {
      REQUIRE_FALSE(m.contains("mass"));
      at = [motion = wobble::ExactFreeMotion(I, m0, q0)](double t) { return motion.at(t); };
    }
    REQUIRE(j["rows"].size() == 7);
    for (const auto& row : j["rows"]) {
      const wobble::FreeBodyState s = at(row[0]);
      const wobble::Vec3 L_B = axes * s.m_B, e3_S = s.q_BtoS.toRotationMatrix().col(2);
      for (int i = 0; i < 3; ++i) {
        CHECK(row[1 + i].get<double>() == L_B[i]);
        CHECK(row[4 + i].get<double>() == e3_S[i]);
      }
    }
  }
}

TEST_CASE("solve --cross-check compares the closed forms with a simulation") {
  for (const std::string id : {"rect-solid", "flying-plate", "flying-square-plate"}) {
    const RunResult r = run_wobble({"solve", id, "--cross-check", "--set", "alpha=40deg"});
    INFO(r.out << r.err);
    REQUIRE(r.exit_code == 0);
    for (const std::string w : {"max_angle", "t_max", "Omega_body_rate", "Omega_space_rate",
                                "cost of the key", "right-hand-side evaluations"}) {
      CHECK_THAT(r.out, Catch::Contains(w));
    }
  }
  REQUIRE(run_wobble({"solve", "taylor-10-35", "--cross-check"}).exit_code == 2);
  // No wobble (alpha = 0 is valid) or one below what the simulation resolves: nothing to
  // compare, said so, no 100% "difference".
  for (const std::string alpha : {"0", "1e-12"}) {
    const RunResult none = run_wobble({"solve", "rect-solid", "--cross-check", "--set",
                                       "alpha=" + alpha});
    INFO(none.out << none.err);
    REQUIRE(none.exit_code == 0);
    REQUIRE_THAT(none.out, Catch::Contains("not compared") && !Catch::Contains("relative"));
  }
}

TEST_CASE("simulate --variant: every scene, its own values, the same on every call") {
  for (const std::string id :
       {"flying-plate", "heavy-top", "spin-up", "tennis-racket", "thrown-plate", "wheel-brake"}) {
    const RunResult a = run_wobble({"simulate", id, "--variant", "7", "--samples", "3"});
    const RunResult b = run_wobble({"simulate", id, "--variant", "7", "--samples", "3"});
    const RunResult d = run_wobble({"simulate", id, "--samples", "3"});
    INFO(id << "\n" << a.err);
    REQUIRE(a.exit_code == 0);
    // The body and run are the same; the timing line differs between calls.
    const auto head = [](const std::string& s) { return s.substr(0, s.find("conserved")); };
    REQUIRE(head(a.out) == head(b.out));
    REQUIRE(head(a.out) != head(d.out));
  }
}

TEST_CASE("bench --quick (the CI smoke run) reports every problem, component and target") {
  const fs::path svg = scratch_dir() / "bench" / "wp.svg";
  fs::create_directories(svg.parent_path());
  fs::remove(svg);
  const RunResult r = run_wobble({"bench", "--quick", "--format", "json", "--plot", svg.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  for (const std::string p : {"P1", "P2", "P3", "P4"}) {
    CHECK(std::any_of(j["runs"].begin(), j["runs"].end(),
                      [&](const auto& run) { return run["problem"] == p; }));
  }
  for (const std::string g : {"elliptic", "principal axes", "process"}) {
    CHECK(std::any_of(j["components"].begin(), j["components"].end(),
                      [&](const auto& c) { return c["group"] == g; }));
  }
  // Timings are not judged here (CI machines are noisy); that every target was measured is.
  // Per problem P1, P3, P4: four method-for-method ratios and best against best (15); the
  // heavy top's closed form: time and error (2); the elliptic functions (2), the splitting (2),
  // dense output of dopri5 and dop853 (2), the exact solutions' error against t (P2 to 1e7 s,
  // P4 to 2e6 s: 2), the keys' process times (2).
  REQUIRE(j["targets"].size() == 27);
  // P2 at t = 10 ... 1e7 s (7), P4 at t = 2 ... 2e6 s (7).
  REQUIRE(j["exact_error_against_time"].size() == 14);
  for (const std::string p : {"P2", "P4"}) {
    CHECK(std::count_if(j["exact_error_against_time"].begin(), j["exact_error_against_time"].end(),
                        [&](const auto& d) { return d["problem"] == p; }) == 7);
  }
  for (const auto& t : j["targets"]) {
    INFO(t["target"]);
    CHECK(t["measured"].template get<double>() >= 0.0);
  }
  REQUIRE_THAT(slurp(svg), Catch::Contains("<svg") && Catch::Contains("odeint_rkf78") &&
                               Catch::Contains("gsl_rk8pd") && Catch::Contains("cvode_adams") &&
                               Catch::Contains("dop853") && Catch::Contains("vern9"));
  // A run with error 0 (the heavy top's closed form, equal to 50 digits in every double) has no
  // place on the log scale: its method's title says where it is drawn.
  for (const auto& run : j["runs"]) {
    if (run["error"].template get<double>() != 0.0) continue;
    const std::string title = run["method"].template get<std::string>() + " (0, at ε/2)";
    INFO(run["problem"] << " " << run["method"]);
    CHECK_THAT(slurp(svg), Catch::Contains(title));
  }
}

TEST_CASE("simulate --t-end sets the time span (an expression), --samples the count") {
  const RunResult r =
      run_wobble({"simulate", "tennis-racket", "--t-end", "2*pi", "--samples", "5"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE_THAT(r.out, Catch::Contains("time: 0 to 6.283185307 s, 5 samples"));
  // As typed with π: a number glued to it is a product.
  const RunResult glued =
      run_wobble({"simulate", "tennis-racket", "--t-end", "2π", "--samples", "5"});
  INFO(glued.err);
  REQUIRE(glued.exit_code == 0);
  REQUIRE_THAT(glued.out, Catch::Contains("time: 0 to 6.283185307 s, 5 samples"));
}

TEST_CASE("simulate refuses an exact run past where its phases keep their digits, before output") {
  // 1e13 s of the flying plate is within 2^50 rad of its fastest angle; 1e300 s is not, and
  // the samples there would print digits the solution does not hold.
  const RunResult far =
      run_wobble({"simulate", "flying-plate", "--t-end", "1e13", "--samples", "2"});
  INFO(far.err);
  REQUIRE(far.exit_code == 0);
  // The heavy top's phases grow at its spin and secular precession rates (not at the Euler
  // rates' bound, large for a moment near a pole, where phi turns by pi and no more).
  for (const auto& [scene, t_end, shown] :
       {std::tuple{"flying-plate", "1e300", "1e+300"},
        std::tuple{"tennis-racket", "1e300", "1e+300"}, std::tuple{"heavy-top", "1e16", "1e+16"}}) {
    const RunResult r = run_wobble({"simulate", scene, "--t-end", t_end, "--samples", "2"});
    INFO(scene << "\n" << r.err);
    REQUIRE(r.exit_code == 2);
    REQUIRE(r.out.empty());
    REQUIRE_THAT(r.err, Catch::StartsWith(std::string("wobble: run.t_end: ") + shown +
                                          " s is past what the exact solution resolves here") &&
                            Catch::Contains("at most"));
  }
  const RunResult top = run_wobble({"simulate", "heavy-top", "--t-end", "1e12", "--samples", "2"});
  INFO(top.err);
  REQUIRE(top.exit_code == 0);
}

namespace {
// The rows of a printed table: the lines after its units' line, to the blank line after them.
std::vector<std::vector<double>> table_rows(const std::string& out) {
  std::istringstream lines(out);
  std::string line;
  while (std::getline(lines, line) && line.find("[s]") == std::string::npos) {
  }
  std::vector<std::vector<double>> rows;
  while (std::getline(lines, line) && !line.empty()) {
    std::istringstream cells(line);
    rows.emplace_back(std::istream_iterator<double>(cells), std::istream_iterator<double>());
  }
  return rows;
}

std::vector<std::vector<double>> csv_rows(const std::string& text) {
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);  // the header
  std::vector<std::vector<double>> rows;
  while (std::getline(lines, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream cells(line);
    rows.emplace_back(std::istream_iterator<double>(cells), std::istream_iterator<double>());
  }
  return rows;
}
}  // namespace

TEST_CASE("simulate prints only the digits its estimated error supports, and no table with none") {
  // Splitting at tolerance 1e-2 on the thrown plate: an estimated error of 4.1e-2 of each
  // column's largest value (against the closed form), so one digit.
  const std::vector<std::string> coarse_run{"simulate", "thrown-plate", "--method",
                                            "split2",   "--tolerance",  "1e-2"};
  const RunResult coarse = run_wobble(coarse_run);
  INFO(coarse.err);
  REQUIRE(coarse.exit_code == 0);
  REQUIRE_THAT(coarse.out, Catch::Contains("; the table prints 1 digit\n"));
  const fs::path csv = scratch_dir() / "thrown-plate-exact.csv";
  fs::remove(csv);
  REQUIRE(run_wobble({"simulate", "thrown-plate", "--out", csv.string()}).exit_code == 0);
  const auto printed = table_rows(coarse.out), exact = csv_rows(slurp(csv));
  REQUIRE(printed.size() == exact.size());
  REQUIRE(printed.size() == 17);
  for (std::size_t j = 0; j < exact[0].size(); ++j) {
    double largest = 0.0;
    for (const auto& row : exact) largest = std::max(largest, std::abs(row[j]));
    // One digit: the place of the first digit of the column's largest value. The run's error,
    // below 1e-1 of that value, is below the place, and the printing rounds by half of it more.
    const double place = std::pow(10.0, std::floor(std::log10(largest)));
    const double bound = 1.5 * place;
    for (std::size_t i = 0; i < exact.size(); ++i) {
      INFO("column " << j << ", row " << i);
      REQUIRE(printed[i].size() == exact[i].size());
      CHECK_THAT(printed[i][j], Catch::Matchers::WithinAbs(exact[i][j], j == 0 ? 1e-12 : bound));
    }
  }
  // The sample times are printed whole, whatever the digits of the results.
  CHECK_THAT(coarse.out, Catch::Contains("\n     0.15 "));

  // RK4 with a step of 10 s (0.05 s, the samples' spacing) on the top spun at 150 rad/s: not one
  // digit would be right.
  std::string text = slurp(fs::path(WOBBLE_SOURCE_DIR) / "scenes" / "heavy-top.toml");
  text.replace(text.find("tolerance = 1e-10"), 17, "method = \"rk4\"\nstep = 10");
  const fs::path scene = write_file("rk4-long-step.toml", text);
  const fs::path plot = scratch_dir() / "rk4-long-step.svg";
  const RunResult refused = run_wobble({"simulate", scene.string(), "--plot", plot.string()});
  REQUIRE(refused.exit_code == 2);
  REQUIRE(refused.out.empty());
  CHECK_FALSE(fs::exists(plot));
  CHECK_THAT(refused.err,
             Catch::StartsWith("wobble: run.step: 10 s leaves not one digit of the table right: "
                               "the samples' estimated error is ") &&
                 Catch::Contains("shorten it, or write the samples as computed with --out"));
  // The samples as computed, at full precision, with that said.
  const fs::path raw = scratch_dir() / "rk4-long-step.csv";
  fs::remove(raw);
  const RunResult written = run_wobble({"simulate", scene.string(), "--out", raw.string()});
  REQUIRE(written.exit_code == 0);
  CHECK_THAT(written.out, Catch::Contains("; not one digit of the samples is right\n"));
}

TEST_CASE("simulate --samples takes a count as 1e3, --method a name in any case") {
  // Counts are written as --max-evaluations takes them (5e7); the tables print DOP853.
  const RunResult r = run_wobble(
      {"simulate", "tennis-racket", "--samples", "1e3", "--method", "DOP853", "--t-end", "1"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, Catch::Contains("time: 0 to 1 s, 1000 samples"));
  CHECK_THAT(r.out, Catch::Contains("method: dop853 (requested)"));
}

TEST_CASE("simulate --t-end takes a unit of time, as a value is typed elsewhere") {
  for (const auto& [typed, shown] :
       {std::pair{"500 ms", "time: 0 to 0.5 s"}, std::pair{"2 min", "time: 0 to 120 s"},
        std::pair{"3 s", "time: 0 to 3 s"}}) {
    const RunResult r =
        run_wobble({"simulate", "tennis-racket", "--t-end", typed, "--samples", "3"});
    INFO(typed << "\n" << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, Catch::Contains(shown));
  }
  // Typed without quotes the shell parts the value: the line says so and gives the command.
  for (const auto& [typed, line] :
       {std::pair<std::vector<std::string>, std::string>{
            {"simulate", "tennis-racket", "--t-end", "2", "min", "--samples", "3"},
            "give it in quotes: wobble simulate tennis-racket --t-end '2 min' --samples 3"},
        {{"simulate", "tennis-racket", "--t-end=2", "min"},
         "give it in quotes: wobble simulate tennis-racket --t-end='2 min'"}}) {
    const RunResult r = run_wobble(typed);
    INFO(r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Catch::StartsWith("wobble: --t-end: the shell parted its value") &&
                          Catch::Contains(line));
  }
  // A word left over elsewhere is not called a part of the value.
  const RunResult other = run_wobble({"simulate", "tennis-racket", "--samples", "3", "extra"});
  CHECK(other.exit_code == 2);
  CHECK_THAT(other.err, !Catch::Contains("--t-end") && Catch::Contains("extra"));
}

TEST_CASE("a million samples are written in bounded memory") {
  // Rows stream from a temporary file to the output: the run needs about 35 MB whatever the
  // number of samples (545 MB for a million when every row and the whole JSON text were held).
  // Under 400 MB of address space it must succeed.
#if defined(__SANITIZE_ADDRESS__)
  SUCCEED("AddressSanitizer reserves terabytes of address space: not measurable here");
#else
  const fs::path out = scratch_dir() / "million.json";
  fs::remove(out);
  const RunResult r = run_shell("ulimit -v 400000; '" + std::string(WOBBLE_EXE) +
                                "' simulate tennis-racket --samples 1000000 --out '" +
                                out.string() + "'");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  CHECK(j["rows"].size() == 1000000);
  CHECK(j["rows"][999999][0] == j["t_end"]);
#endif
}
