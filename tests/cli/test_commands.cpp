#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/run.hpp"
#include "problem/scene.hpp"
#include "solvers/catalog.hpp"
#include "temp_files.hpp"

using namespace wobble::test;
namespace fs = std::filesystem;

TEST_CASE("list names every problem of the catalog and every scene") {
  const RunResult r = run_wobble({"list"});
  REQUIRE(r.exit_code == 0);
  for (const auto& p : wobble::load_catalog()) REQUIRE_THAT(r.out, Catch::Contains(p.id + "  "));
  const auto scenes = wobble::load_scenes();
  REQUIRE(scenes.size() >= 6);
  const std::size_t at = r.out.find("scenes (wobble simulate ID):");
  REQUIRE(at != std::string::npos);
  for (const auto& s : scenes) {
    REQUIRE(r.out.find("  " + s.model.id + "  ", at) != std::string::npos);
  }
}

TEST_CASE("version and help exit 0") {
  REQUIRE_THAT(run_wobble({"--version"}).out, Catch::StartsWith("wobble "));
  const RunResult help = run_wobble({"--help"});
  REQUIRE(help.exit_code == 0);
  REQUIRE_THAT(help.out,
               Catch::Contains("solve") && Catch::Contains("keys") && Catch::Contains("list"));
  REQUIRE(run_wobble({"solve", "--help"}).exit_code == 0);
}

TEST_CASE("a variant number may be written as counts are elsewhere: 1e3 is variant 1000") {
  const RunResult plain = run_wobble({"solve", "flying-plate", "--variant", "1000"});
  REQUIRE(plain.exit_code == 0);
  const RunResult power = run_wobble({"solve", "flying-plate", "--variant", "1e3"});
  REQUIRE(power.exit_code == 0);
  REQUIRE(power.out == plain.out);
  REQUIRE(plain.out != run_wobble({"solve", "flying-plate", "--variant", "999"}).out);
}

TEST_CASE("solve --format json has the documented shape, at values not in the repository") {
  const RunResult r = run_wobble(
      {"solve", "taylor-10-35", "--set", "m=0.35", "--set", "a=2.2", "--format", "json"});
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["problem"] == "taylor-10-35");
  REQUIRE(j["parameters"]["m"]["value"] == 0.35);
  REQUIRE(j["parameters"]["a"]["unit"] == "m");
  const auto& b = j["parts"][1];
  REQUIRE(b["id"] == "b");
  REQUIRE(b["answers"][0]["name"] == "principal_moments");
  REQUIRE(b["answers"][0]["symbolic"] == "[5*m*a^2, 7*m*a^2, 10*m*a^2]");
  REQUIRE(b["answers"][0]["unit"] == "kg m^2");
  // Independent: m a^2 (5, 7, 10); the value went through JSON's shortest round trip.
  const double ma2 = 0.35 * 2.2 * 2.2;
  for (int k = 0; k < 3; ++k) {
    REQUIRE_THAT(b["answers"][0]["value"][k].get<double>(),
                 Catch::Matchers::WithinRel(std::vector<double>{5, 7, 10}[k] * ma2, 4e-16));
  }
  REQUIRE(b["answers"][1]["value"].size() == 3);  // a matrix: 3 rows
  REQUIRE(b["steps"].size() >= 3);
  REQUIRE(b["steps"][0].contains("latex"));
}

TEST_CASE("solve --part prints only that part, in every format") {
  for (const std::string format : {"text", "markdown", "latex", "json"}) {
    const RunResult r = run_wobble({"solve", "four-masses", "--part", "b", "--format", format});
    INFO(format);
    REQUIRE(r.exit_code == 0);
    REQUIRE_THAT(r.out, Catch::Contains("Find the principal moments and the principal axes."));
    // Part (a)'s question appears only in the statement, which JSON and text also carry once.
    REQUIRE_THAT(r.out, !Catch::Contains("(a) Find the inertia tensor about the origin.") &&
                            !Catch::Contains("\"id\": \"a\""));
  }
}

TEST_CASE("solve accepts a problem file outside problems/ and a collinear body") {
  const auto file = write_file("cmd/line.toml", R"TOML(id = "line"
title = "Three masses on a line"
solver = "inertia"
statement = "Masses on the line x = y."
[[parameters]]
name = "m"
unit = "kg"
default = 2
range = "(0, inf)"
[body]
masses = [ { mass = "m", at = ["1", "1", "0"] }, { mass = "m", at = ["2", "2", "0"] }, { mass = "3*m", at = ["-1", "-1", "0"] } ]
[[parts]]
id = "a"
question = "Principal moments?"
answers = ["principal_moments", "principal_axes"]
)TOML");
  const RunResult r = run_wobble({"solve", file.string()});
  REQUIRE(r.exit_code == 0);
  REQUIRE_THAT(r.out, Catch::Contains("λ₁ = 0") && Catch::Contains("Degenerate: λ₂ = λ₃"));
}

TEST_CASE("keys --check passes on the repository's solutions") {
  const RunResult r = run_wobble({"keys", "--check"});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE_THAT(r.out, Catch::Contains("keys: all"));
}

TEST_CASE("keys --update writes a folder, then --check finds a changed number and a stale file") {
  const fs::path dir = scratch_dir() / "solutions-copy";
  fs::remove_all(dir);
  const std::map<std::string, std::string> env{{"WOBBLE_SOLUTIONS", dir.string()}};
  const RunResult first = run_wobble({"keys", "--update"}, env);
  REQUIRE(first.exit_code == 0);
  REQUIRE(fs::exists(dir / "taylor-10-35.json"));
  REQUIRE(fs::exists(dir / "taylor-10-35.md"));
  REQUIRE_THAT(run_wobble({"keys", "--update"}, env).out, Catch::Contains(", 0 files changed"));
  REQUIRE(run_wobble({"keys", "--check"}, env).exit_code == 0);

  // Change one value the way a wrong edit would: 10 -> 10.5 in taylor's moments.
  auto j = nlohmann::ordered_json::parse(slurp(dir / "taylor-10-35.json"));
  j["parts"][1]["answers"][0]["value"][2] = 10.5;
  std::ofstream(dir / "taylor-10-35.json") << j.dump(2) << "\n";
  std::ofstream(dir / "old-problem.json") << "{}\n";
  const RunResult check = run_wobble({"keys", "--check"}, env);
  REQUIRE(check.exit_code == 1);
  REQUIRE_THAT(check.out,
               Catch::Contains("taylor-10-35.json: parts[1].answers[0].value[2]: 10.5 -> 10"));
  REQUIRE_THAT(check.out, Catch::Contains("old-problem.json: no problem has this key"));
}

TEST_CASE("keys --update into a read-only folder fails cleanly and leaves the files as they were") {
  if (::geteuid() == 0) {
    // Root ignores permission bits; use a folder that cannot exist instead.
    const RunResult r = run_wobble({"keys", "--update"}, {{"WOBBLE_SOLUTIONS", "/proc/wobble-no"}});
    REQUIRE(r.exit_code == 2);
    REQUIRE(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    return;
  }
  const fs::path dir = scratch_dir() / "readonly";
  fs::create_directories(dir);
  std::ofstream(dir / "taylor-10-35.json") << "old\n";
  fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
  const RunResult r = run_wobble({"keys", "--update"}, {{"WOBBLE_SOLUTIONS", dir.string()}});
  fs::permissions(dir, fs::perms::owner_all);
  REQUIRE(r.exit_code == 2);
  REQUIRE(slurp(dir / "taylor-10-35.json") == "old\n");
}

TEST_CASE("a write that fails midway (a file-size limit, as a full disk) keeps the old files") {
  const fs::path dir = scratch_dir() / "fsize";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "taylor-10-35.json") << "old\n";
  const fs::path csv = dir / "run.csv";
  std::ofstream(csv) << "old\n";
  // ulimit -f 1: no file may grow past 1 KiB; every key and the samples are larger.
  const std::string limit = "ulimit -f 1; ";
  const RunResult keys = run_shell(limit + "WOBBLE_SOLUTIONS='" + dir.string() + "' '" +
                                   WOBBLE_EXE + "' keys --update");
  INFO(keys.err);
  REQUIRE(keys.exit_code == 2);
  REQUIRE_THAT(keys.err, Catch::Contains("cannot write") && Catch::Contains("too large"));
  const RunResult sim =
      run_shell(limit + "'" + std::string(WOBBLE_EXE) +
                "' simulate tennis-racket --samples 2000 --force --out '" + csv.string() + "'");
  INFO(sim.err);
  REQUIRE(sim.exit_code == 2);
  REQUIRE(slurp(dir / "taylor-10-35.json") == "old\n");
  REQUIRE(slurp(csv) == "old\n");
  for (const auto& e : fs::directory_iterator(dir)) {
    INFO(e.path());
    REQUIRE(e.path().filename().string().find(".tmp.") == std::string::npos);  // none left
  }
}

TEST_CASE("keys are byte-identical across processes and equal to the stored solutions") {
  // Each process has its own address layout and symbol history, which change GiNaC's internal
  // term order; `keys --update` solved all problems in one process, `solve` one per process.
  for (const auto& p : wobble::load_catalog()) {
    const std::string stored = slurp(fs::path(WOBBLE_SOURCE_DIR) / "solutions" / (p.id + ".json"));
    for (int run = 0; run < 3; ++run) {
      const RunResult r = run_wobble({"solve", p.id, "--format", "json"});
      INFO(p.id << " run " << run);
      REQUIRE(r.exit_code == 0);
      REQUIRE(r.out == stored);
    }
  }
}

TEST_CASE("a file of one's own with pi in its exact forms is solved alike in every process") {
  // pi in a coordinate or a size (a rate in rpm, an angle in degrees bring it too): each once
  // gave GiNaC's internal error, a principal axis of the wrong sign, an elliptic modulus "not a
  // real number", or one of two forms, as the process's term order fell (one run in five).
  struct Change {
    std::string id, from, to;
  };
  const std::vector<Change> changes{
      {"four-masses", "at = [\"-a/2\", \"-a/2\", \"a/2\"]",
       "at = [\"(-a/2)*pi/3\", \"-a/2\", \"a/2\"]"},
      {"tennis-racket", "sizes = [\"a\", \"b\", \"c\"]", "sizes = [\"a\", \"b*pi/3\", \"c\"]"},
      {"taylor-10-35", "at = [\"a\", \"0\", \"0\"]", "at = [\"a*pi/3\", \"0\", \"0\"]"},
      {"asymmetric-top", "w1 = \"w1\"", "w1 = \"3 rpm\""},
  };
  for (const auto& c : changes) {
    std::string text = slurp(fs::path(WOBBLE_SOURCE_DIR) / "problems" / (c.id + ".toml"));
    const auto at = text.find(c.from);
    REQUIRE(at != std::string::npos);
    text.replace(at, c.from.size(), c.to);
    const auto file = write_file("pi/" + c.id + ".toml", text);
    const RunResult first = run_wobble({"solve", file.string()});
    INFO(c.id << ": " << first.err);
    REQUIRE(first.exit_code == 0);
    REQUIRE_THAT(first.out, Catch::Contains("π"));
    for (int run = 0; run < 7; ++run)
      REQUIRE(run_wobble({"solve", file.string()}).out == first.out);
  }
}

TEST_CASE(
    "Euler's equations as the text and LaTeX keys print them are pasted back as the "
    "coefficients") {
  for (const std::string id : {"asymmetric-top", "tennis-racket"}) {
    for (const std::string format : {"text", "latex"}) {
      const RunResult key = run_wobble({"solve", id, "--format", format, "--set", "a=0.4"});
      INFO(id << " " << format << ": " << key.err);
      // tennis-racket has a, asymmetric-top is refused it: the key at the defaults then.
      const RunResult printed =
          key.exit_code == 0 ? key : run_wobble({"solve", id, "--format", format});
      REQUIRE(printed.exit_code == 0);
      const std::string lead = "For these moments: ";
      const auto at = printed.out.find(lead);
      REQUIRE(at != std::string::npos);
      std::string equations =
          printed.out.substr(at + lead.size(), printed.out.find('\n', at) - at - lead.size());
      REQUIRE_THAT(equations, Catch::EndsWith("."));
      REQUIRE_THAT(equations, format == "text" ? Catch::StartsWith("dω₁/dt = ")
                                               : Catch::StartsWith("$\\mathrm{d}\\omega_{1}/"));
      equations.pop_back();  // the sentence's full stop
      std::vector<std::string> args{"check",    id,       "--name", "euler_coefficients",
                                    "--answer", equations};
      if (key.exit_code == 0) args.insert(args.end(), {"--set", "a=0.4"});
      const RunResult judged = run_wobble(args);
      INFO(equations << "\n" << judged.out << judged.err);
      REQUIRE(judged.exit_code == 0);
      REQUIRE_THAT(judged.out, Catch::Contains("read as the coefficients of Euler's equations"));
    }
  }
  // The step before, the equations with the moments, "I₁ dω₁/dt = (I₂ − I₃) ω₂ ω₃, ..", as the
  // terminal shows it (the racket's moments are no symbols of its problem).
  const RunResult text = run_wobble({"solve", "asymmetric-top"});
  const std::string lead = "in the principal frame: ";
  const auto at = text.out.find(lead);
  REQUIRE(at != std::string::npos);
  const std::string general =
      text.out.substr(at + lead.size(), text.out.find('\n', at) - at - lead.size());
  REQUIRE_THAT(general, Catch::StartsWith("I₁ dω₁/dt = (I₂ − I₃) ω₂ ω₃, "));
  const RunResult judged =
      run_wobble({"check", "asymmetric-top", "--name", "euler_coefficients", "--answer", general});
  INFO(general << "\n" << judged.out << judged.err);
  REQUIRE(judged.exit_code == 0);
  REQUIRE_THAT(judged.out, Catch::Contains("read as the coefficients of Euler's equations"));
}

TEST_CASE("check: exit 0 for a right answer, 1 for a wrong one with its feedback") {
  const RunResult right =
      run_wobble({"check", "taylor-10-35", "a", "--answer", "[[10,0,0],[0,6,1],[0,1,6]] kg m^2"});
  REQUIRE(right.exit_code == 0);
  REQUIRE(right.out == "correct: I\n");
  const RunResult wrong =
      run_wobble({"check", "taylor-10-35", "a", "--answer", "[[10,0,0],[0,6,-1],[0,-1,6]]"});
  REQUIRE(wrong.exit_code == 1);
  REQUIRE_THAT(wrong.out, Catch::StartsWith("incorrect: I\n") &&
                              Catch::Contains("products of inertia have the wrong sign"));
  REQUIRE(wrong.err.empty());
  // At values not in the repository, symbolically.
  REQUIRE(run_wobble({"check", "flying-plate", "a", "--name", "I0", "--answer", "m*R^2/4", "--set",
                      "m=0.35", "--set", "R=0.15"})
              .exit_code == 0);
}

TEST_CASE("check and export: --tolerance is a fraction or a percentage") {
  // 118 rad/s is 0.675% below the least spin of the heavy top, 118.801697 rad/s.
  for (const auto& [tolerance, exit_code] :
       {std::pair{"1%", 0}, std::pair{"0.01", 0}, std::pair{"0.5 %", 1}, std::pair{"0.005", 1}}) {
    const RunResult r =
        run_wobble({"check", "heavy-top", "omega3_min", "118 rad/s", "--tolerance", tolerance});
    INFO(tolerance << "\n" << r.err);
    CHECK(r.exit_code == exit_code);
  }
  const RunResult wide = run_wobble(
      {"export", "moodle", "four-masses", "--tolerance", "200%", "--out", "/tmp/never.xml"});
  CHECK(wide.exit_code == 2);
  // Named as typed, not as the fraction it was read as.
  CHECK_THAT(wide.err, Catch::Contains("--tolerance: '200%' must be between 0% and 100%"));
  CHECK_THAT(wide.err, !Catch::Contains(" 2 "));
  const RunResult fine =
      run_wobble({"check", "heavy-top", "omega3_min", "118 rad/s", "--tolerance", "0.00000001%"});
  CHECK(fine.exit_code == 2);
  CHECK_THAT(fine.err, Catch::Contains("--tolerance: '0.00000001%' (1e-10) is below"));
}

TEST_CASE(
    "check: a part of several answers without --name, the answer's label, rightness or reading "
    "decides") {
  // asymmetric-top's part (a) asks for the coefficients of Euler's equations and dω/dt at 0.
  const auto judged = [](const std::string& answer) {
    return run_wobble({"check", "asymmetric-top", "a", "--answer", answer});
  };
  // Labelled with the answer's name, as the key prints it: that answer, right or wrong.
  const RunResult labelled = judged("euler_coefficients = [-0.5, 0.6667, -0.25]");
  REQUIRE(labelled.exit_code == 0);
  REQUIRE(labelled.out == "correct: euler_coefficients\n");
  const RunResult labelled_wrong = judged("dw_dt0: [1, 2, 3] rad/s^2");
  REQUIRE(labelled_wrong.exit_code == 1);
  REQUIRE_THAT(labelled_wrong.out, Catch::StartsWith("incorrect: dw_dt0\n"));
  // Right for one of them only: that one. The equations are the coefficients', the rates dω/dt's.
  REQUIRE(judged("ω̇₁ = −½ ω₂ω₃, ω̇₂ = ⅔ ω₃ω₁, ω̇₃ = −¼ ω₁ω₂").out ==
          "correct: euler_coefficients\n"
          "  read as the coefficients of Euler's equations: (c₁, c₂, c₃) = [-1/2, 2/3, -1/4]\n");
  REQUIRE(judged("(-0.5, 1, -0.015) rad/s²").out == "correct: dw_dt0\n");
  // Euler's equations wrong are still the coefficients': judged so, the wrong one named.
  const RunResult wrong_equations =
      judged("dw1/dt = -0.5 w2 w3, dw2/dt = 0.7 w3 w1, dw3/dt = -0.25 w1 w2");
  REQUIRE(wrong_equations.exit_code == 1);
  REQUIRE_THAT(wrong_equations.out, Catch::StartsWith("incorrect: euler_coefficients\n") &&
                                        Catch::Contains("c₂ is off by 5%"));
  const RunResult wrong_products =
      judged("dω₁/dt = -0.5 ω₂ ω₃, dω₂/dt = (2/3) ω₃ ω₁, dω₃/dt = -0.25 ω₁ ω₃");
  REQUIRE(wrong_products.exit_code == 1);
  REQUIRE_THAT(wrong_products.out, Catch::Contains("dω₃/dt = c₃ ω₁ ω₂, and yours has ω₁ ω₃"));
  // Right for neither, but a value of one only (dω/dt's unit): judged as that one.
  const RunResult wrong_rates = judged("[1, 2, 3] rad/s^2");
  REQUIRE(wrong_rates.exit_code == 1);
  REQUIRE_THAT(wrong_rates.out, Catch::StartsWith("incorrect: dw_dt0\n"));
  // The axes' matrix read by rows, labelled e₁ .. e₃ (no answer's name), for four-masses' part of
  // moments and axes: only the axes read three vectors, and the mistake is named.
  const RunResult rows = run_wobble(
      {"check", "four-masses", "b", "--answer", "e1 = (1,0,1)/√2, e2 = (1,0,-1)/√2, e3 = (0,1,0)"});
  REQUIRE(rows.exit_code == 1);
  REQUIRE_THAT(rows.out, Catch::StartsWith("incorrect: principal_axes\n") &&
                             Catch::Contains("these are the rows of the axes' matrix"));
  // Right for neither, and a value of either (pure numbers, or no unit): the name is asked for,
  // nothing judged.
  const RunResult neither = judged("[1, 2, 3]");
  REQUIRE(neither.exit_code == 2);
  REQUIRE(neither.out.empty());
  REQUIRE_THAT(
      neither.err,
      Catch::Contains("part a has several answers; name one (euler_coefficients, dw_dt0)"));
  // The same, labelled with a word that names none of them: that word is refused, not a name
  // asked for that the line has given; another part's answer is named as that part's. (ω̇ as
  // w_dot names dw_dt0, as the question writes dω/dt: judged, and wrong.)
  REQUIRE_THAT(judged("w_dot = [1, 2, 3]").out, Catch::StartsWith("incorrect: dw_dt0\n"));
  const RunResult unknown_label = judged("accel = [1, 2, 3]");
  REQUIRE(unknown_label.exit_code == 2);
  REQUIRE(unknown_label.out.empty());
  REQUIRE(unknown_label.err ==
          "wobble: part: part a has no answer 'accel' (answers: euler_coefficients, dw_dt0)\n");
  const RunResult other_part =
      run_wobble({"check", "heavy-top", "d", "--answer", "ω₃ = 700 rad/s"});
  REQUIRE(other_part.exit_code == 2);
  REQUIRE(other_part.err ==
          "wobble: part: part d has no answer 'ω₃' (answers: phidot_slow, "
          "phidot_fast); omega3 is part c's\n");
}

TEST_CASE("check: --name alone finds its part; neither part nor name says what to give") {
  const RunResult by_name = run_wobble({"check", "flying-plate", "--name", "Omega_space_rate",
                                        "--answer", "omega*sqrt(3*cos^2(alpha) + 1)"});
  REQUIRE(by_name.exit_code == 0);
  REQUIRE(by_name.out == "correct: Omega_space_rate (your expression simplifies to the key's)\n");
  const RunResult wrong =
      run_wobble({"check", "flying-plate", "--name", "Omega_space_rate", "--answer", "omega"});
  REQUIRE(wrong.exit_code == 1);
  const RunResult unknown =
      run_wobble({"check", "flying-plate", "--name", "Omega", "--answer", "1"});
  REQUIRE(unknown.exit_code == 2);
  REQUIRE(unknown.out.empty());
  REQUIRE_THAT(unknown.err,
               Catch::StartsWith(
                   "wobble: --name: problem flying-plate has no answer 'Omega' (answers: I0, ") &&
                   Catch::Contains("Omega_space_rate"));
  // An answer that does not exist at these values: a number is wrong, "none" is right, and
  // either verdict names its part and says why (a spin too slow for steady precession).
  const RunResult absent = run_wobble(
      {"check", "heavy-top", "--name", "phidot_slow", "--set", "psidot0=10", "--answer", "1"});
  REQUIRE(absent.exit_code == 1);
  REQUIRE_THAT(absent.out,
               Catch::StartsWith("incorrect: phidot_slow does not exist at these values\n"
                                 "  No steady precession at θ0 = 0.5235987756 rad"));
  const RunResult none =
      run_wobble({"check", "heavy-top", "d", "--set", "psidot0=10", "--answer", "none"});
  REQUIRE(none.exit_code == 0);
  REQUIRE_THAT(none.out, Catch::StartsWith("correct: phidot_slow, phidot_fast do not "
                                           "exist at these values\n  No steady precession"));
  // One absent beside others (a horizontal axle has no fast precession): the line says why;
  // "none" for the one that exists is wrong.
  const RunResult horizontal =
      run_wobble({"check", "heavy-top", "--set", "theta0=90deg", "phidot_fast = does not exist"});
  REQUIRE(horizontal.exit_code == 0);
  REQUIRE_THAT(horizontal.out,
               Catch::StartsWith("correct: phidot_fast does not exist at these values\n"
                                 "  θ0 = 90°: the axle is horizontal"));
  const RunResult exists =
      run_wobble({"check", "heavy-top", "--set", "theta0=90deg", "phidot_slow = none"});
  REQUIRE(exists.exit_code == 1);
  REQUIRE(exists.out == "incorrect: phidot_slow exists at these values\n");
  // Its line with nothing after the '=' is refused as any answer's is, not judged wrong.
  const RunResult empty = run_wobble({"check", "heavy-top", "--set", "psidot0=10", "φ̇_slow ="});
  REQUIRE(empty.exit_code == 2);
  REQUIRE(empty.out.empty());
  REQUIRE_THAT(empty.err, Catch::StartsWith("wobble: phidot_slow: nothing after the '='"));
  const RunResult neither = run_wobble({"check", "flying-plate", "--answer", "1"});
  REQUIRE(neither.exit_code == 2);
  // Neither a part nor a name: the line says how, with this problem's answers by part.
  REQUIRE_THAT(neither.err, Catch::StartsWith("wobble: check: give an answer's name (or its "
                                              "part) and the answer, as wobble check "
                                              "flying-plate I0 ANSWER") &&
                                Catch::Contains("flying-plate's answers: (a) I0, I; (b) L0_body, "
                                                "L0_space; (c) angle_omega_e3"));
  REQUIRE(neither.out.empty());
  REQUIRE(run_wobble({"check", "flying-plate"}).exit_code == 2);
}

TEST_CASE("check: one word that is a key's line, NAME = ANSWER, names its answer") {
  // As the worksheet prompts and a submission file is written; the name as the key prints it.
  for (const auto& [args, out] : std::vector<std::pair<std::vector<std::string>, std::string>>{
           {{"check", "asymmetric-top", "rate_axis2 = 1.772 1/s"}, "correct: rate_axis2\n"},
           {{"check", "asymmetric-top", "rate_axis2=1.772"}, "correct: rate_axis2\n"},
           // As a submission's line reads: NAME: ANSWER, a part's mark before it, the
           // worksheet's prompt with its unit.
           {{"check", "asymmetric-top", "rate_axis2: 1.772 1/s"}, "correct: rate_axis2\n"},
           {{"check", "asymmetric-top", "(b) rate_axis2 = 1.772 1/s"}, "correct: rate_axis2\n"},
           {{"check", "asymmetric-top", "rate_axis2 [rad/s or 1/s] = 1.772 1/s"},
            "correct: rate_axis2\n"},
           {{"check", "flying-plate", "I₀ = m·R²/4 = 0.00072 kg m²"},
            "correct: I0 (your expression simplifies to the key's)\n"},
           {{"check", "asymmetric-top", "rate_axis2 = 2.894 1/s"},
            "incorrect: rate_axis2\n  this is rate_axis3 (part b), not rate_axis2\n"}}) {
    const RunResult r = run_wobble(args);
    INFO(args.back() << "\n" << r.err);
    REQUIRE(r.exit_code == (out.rfind("correct", 0) == 0 ? 0 : 1));
    REQUIRE(r.out == out);
  }
  // A name of no answer is refused as that name, not as the whole line.
  const RunResult unknown = run_wobble({"check", "flying-plate", "J0 = m R^2/2"});
  REQUIRE(unknown.exit_code == 2);
  REQUIRE(unknown.out.empty());
  REQUIRE_THAT(unknown.err, Catch::StartsWith("wobble: part: problem flying-plate has no part or "
                                              "answer 'J0' (answers by part: (a) I0, I;"));
  // A part's id on the left: the answer after the '=' is judged as if typed after the part,
  // also where the id is a symbol of the problem (box-corner's side a and part a).
  const RunResult part_id = run_wobble({"check", "asymmetric-top", "b = 1.772 1/s"});
  INFO(part_id.err);
  REQUIRE(part_id.exit_code == 0);
  REQUIRE(part_id.out == run_wobble({"check", "asymmetric-top", "b", "1.772 1/s"}).out);
  REQUIRE(part_id.out == "correct: rate_axis2\n");
  const RunResult symbol_id = run_wobble({"check", "box-corner",
                                          "a = [[M(b^2+c^2)/3, -M a b/4, -M a c/4], [-M a b/4, "
                                          "M(a^2+c^2)/3, -M b c/4], [-M a c/4, -M b c/4, "
                                          "M(a^2+b^2)/3]]"});
  INFO(symbol_id.err);
  REQUIRE(symbol_id.exit_code == 0);
  REQUIRE_THAT(symbol_id.out, Catch::StartsWith("correct: I_corner"));
  // The prompt's line with the answer left out: refused as that, named by the answer's name
  // (no --answer was typed).
  const RunResult left_out = run_wobble({"check", "asymmetric-top", "rate_axis2 ="});
  REQUIRE(left_out.exit_code == 2);
  REQUIRE(left_out.out.empty());
  REQUIRE(left_out.err ==
          "wobble: rate_axis2: nothing after the '=' in \"rate_axis2 =\"; the "
          "answer goes after it\n");
  const RunResult colon = run_wobble({"check", "asymmetric-top", "rate_axis2:"});
  REQUIRE(colon.exit_code == 2);
  REQUIRE_THAT(colon.err, Catch::StartsWith("wobble: rate_axis2: nothing after the ':'"));
  // The separator typed twice, as a program's comparison: the line quoted as typed, not the
  // second '=' alone.
  const RunResult doubled = run_wobble({"check", "asymmetric-top", "rate_axis2 =="});
  REQUIRE(doubled.exit_code == 2);
  REQUIRE(doubled.err ==
          "wobble: rate_axis2: nothing after the '=' in \"rate_axis2 ==\"; the "
          "answer goes after it\n");
  // A name of no answer with nothing after it is refused as that name.
  REQUIRE_THAT(run_wobble({"check", "asymmetric-top", "J0 ="}).err,
               Catch::StartsWith("wobble: part: problem asymmetric-top has no part or answer "
                                 "'J0'"));
  // An answer alone, with neither its part nor its name: which answer it is for is asked, not
  // guessed (box-corner has two 3x3 tensors), and a misspelt name is still refused as a name.
  for (const char* alone : {"[[13/3, -1/2, -3/4], [-1/2, 10/3, -3/2], [-3/4, -3/2, 5/3]]",
                            "{{13/3, -1/2, -3/4}, {-1/2, 10/3, -3/2}, {-3/4, -3/2, 5/3}}",
                            "4.33 kg m^2", "m*a^2/6", "0.5"}) {
    INFO(alone);
    const RunResult unnamed = run_wobble({"check", "box-corner", alone});
    REQUIRE(unnamed.exit_code == 2);
    REQUIRE(unnamed.out.empty());
    REQUIRE_THAT(unnamed.err,
                 Catch::StartsWith("wobble: part: '") &&
                     Catch::Contains("' has no name; say whose answer it is, as wobble check "
                                     "box-corner 'NAME = ANSWER' or wobble check box-corner PART "
                                     "ANSWER (answers by part: (a) I_corner; (b) center_of_mass"));
  }
  // Named as the steps write it (r_cm = Σ m r / Σ m), with or without its part of two answers.
  for (const auto& words : std::vector<std::vector<std::string>>{
           {"check", "box-corner", "r_cm = (0.5, 1, 1.5) m"},
           {"check", "box-corner", "b", "r_cm = (0.5, 1, 1.5) m"}}) {
    const RunResult named = run_wobble(words);
    REQUIRE(named.exit_code == 0);
    REQUIRE(named.out == "correct: center_of_mass\n");
  }
  // A line with '≈' for '=', as the judge reads it, and a primed name, the heavy top's level E′.
  for (const auto& [line, verdict] : std::vector<std::pair<std::string, std::string>>{
           {"φ̇_slow ≈ 4.995 rad/s", "correct: phidot_slow\n"},
           {"E′ = 0.3398 J", "correct: energy_prime\n"},
           {"E = 7.371 J", "correct: energy\n"}}) {
    INFO(line);
    const RunResult named = run_wobble({"check", "heavy-top", line});
    REQUIRE(named.exit_code == 0);
    REQUIRE(named.out == verdict);
  }
  // dω/dt as the question writes it names dw_dt0; Euler's equations written out, whose first
  // label names no answer, are the coefficients' answer, right or wrong.
  for (const char* line : {"dω/dt = (-0.5, 1, -0.015) rad/s²", "ω̇(0) = (-0.5, 1, -0.015) rad/s²",
                           "dw/dt = [-0.5, 1, -0.015]"}) {
    INFO(line);
    REQUIRE(run_wobble({"check", "asymmetric-top", line}).out == "correct: dw_dt0\n");
  }
  const RunResult equations = run_wobble(
      {"check", "asymmetric-top", "dω₁/dt = -0.5 ω₂ω₃, dω₂/dt = 0.7 ω₃ω₁, dω₃/dt = -0.25 ω₁ω₂"});
  REQUIRE(equations.exit_code == 1);
  REQUIRE_THAT(equations.out,
               Catch::StartsWith("incorrect: euler_coefficients\n  c₂ is off by 5%"));
  REQUIRE(run_wobble({"check", "heavy-top", "phidot_fast ≈"}).err ==
          "wobble: phidot_fast: nothing after the '≈' in \"phidot_fast ≈\"; the answer goes after "
          "it\n");
  for (const char* name : {"I_corners", "(a)", "\\dot{\\phi}"}) {
    INFO(name);
    REQUIRE_THAT(run_wobble({"check", "box-corner", name}).err,
                 Catch::StartsWith("wobble: part: problem box-corner has no part or answer"));
  }
  // The line split by the shell: quoted whole, and what is suggested is judged.
  const RunResult split =
      run_wobble({"check", "asymmetric-top", "rate_axis2", "=", "1.772", "1/s"});
  REQUIRE(split.exit_code == 2);
  REQUIRE(split.out.empty());
  const std::string suggested = "wobble check asymmetric-top 'rate_axis2 = 1.772 1/s'";
  REQUIRE_THAT(split.err, Catch::EndsWith("put it in quotes: " + suggested + "\n"));
  const std::size_t quote = suggested.find('\'');
  const RunResult pasted = run_wobble(
      {"check", "asymmetric-top", suggested.substr(quote + 1, suggested.size() - quote - 2)});
  REQUIRE(pasted.exit_code == 0);
  // The part, the name and the answer, split: the line suggested is judged right (its first word
  // labels the answer, as with '='; it once read as omega3_min times 118.8, for omega3).
  const RunResult part_name_value =
      run_wobble({"check", "heavy-top", "c", "omega3_min", "118.8", "rad/s"});
  REQUIRE(part_name_value.exit_code == 2);
  const std::string part_suggested = "wobble check heavy-top c 'omega3_min 118.8 rad/s'";
  REQUIRE_THAT(part_name_value.err, Catch::EndsWith("put it in quotes: " + part_suggested + "\n"));
  const RunResult part_pasted = run_wobble({"check", "heavy-top", "c", "omega3_min 118.8 rad/s"});
  REQUIRE(part_pasted.exit_code == 0);
  REQUIRE(part_pasted.out == "correct: omega3_min\n");
  // Where the part goes, and another answer of the part named: judged as the one named.
  REQUIRE(run_wobble({"check", "heavy-top", "omega3_min 118.8 rad/s"}).out ==
          "correct: omega3_min\n");
  const RunResult other = run_wobble({"check", "heavy-top", "c", "omega3 118.8 rad/s"});
  REQUIRE(other.exit_code == 1);
  REQUIRE_THAT(other.out, Catch::StartsWith("incorrect: omega3\n  this is omega3_min (part c)"));
}

TEST_CASE("check: the answer's name where the part goes, the answer as the third word") {
  // As a student types it after reading the key: the name the key prints, then the answer.
  const RunResult named = run_wobble({"check", "flying-plate", "I0", "m·R²/4"});
  REQUIRE(named.exit_code == 0);
  REQUIRE(named.out == "correct: I0 (your expression simplifies to the key's)\n");
  const RunResult part_and_name =
      run_wobble({"check", "flying-plate", "a", "--name", "I0", "m*R^2/2"});
  REQUIRE(part_and_name.exit_code == 1);
  REQUIRE_THAT(part_and_name.out, Catch::StartsWith("incorrect: I0"));
  // With --name, the part's place may hold the answer: it names no part and no answer.
  const RunResult name_then_answer =
      run_wobble({"check", "flying-plate", "--name", "I0", "m·R²/4"});
  INFO(name_then_answer.err);
  REQUIRE(name_then_answer.exit_code == 0);
  REQUIRE(name_then_answer.out == "correct: I0 (your expression simplifies to the key's)\n");
  const RunResult part_not_answer = run_wobble({"check", "flying-plate", "--name", "I0", "b"});
  REQUIRE(part_not_answer.exit_code == 2);
  REQUIRE_THAT(part_not_answer.err, Catch::Contains("part b has no answer 'I0'"));
  // A negative number is an answer, not an option; -- before it reads the same.
  for (const std::vector<std::string>& negative :
       {std::vector<std::string>{"check", "heavy-top", "energy", "-1 J"},
        std::vector<std::string>{"check", "heavy-top", "energy", "--", "-1 J"}}) {
    const RunResult r = run_wobble(negative);
    INFO(r.err);
    REQUIRE(r.exit_code == 1);
    REQUIRE_THAT(r.out, Catch::StartsWith("incorrect: energy"));
  }
  // A negative expression is taken for options (CLI11): the message says where it goes.
  const RunResult dash = run_wobble({"check", "flying-plate", "I0", "-m*R^2/4"});
  REQUIRE(dash.exit_code == 2);
  REQUIRE(dash.out.empty());
  REQUIRE_THAT(dash.err, Catch::Contains("-m*R^2/4; an answer that starts with '-' goes after --"));
  REQUIRE(run_wobble({"check", "flying-plate", "I0", "--", "-m*R^2/4"}).exit_code == 1);
  // After --set, the answer is still the answer, not a second value to set.
  const RunResult after_set =
      run_wobble({"check", "flying-plate", "I0", "--set", "R=0.1", "0.0005 kg m^2"});
  INFO(after_set.err);
  REQUIRE(after_set.exit_code == 0);
  REQUIRE(after_set.out == "correct: I0\n");
  // An answer's name as the statement writes it, I₀ or I_0, is the answer; a word that is
  // neither a part nor an answer lists the answers by part.
  for (const char* i0 : {"I_0", "I₀"}) {
    const RunResult spelled = run_wobble({"check", "flying-plate", i0, "m R^2/4"});
    INFO(i0 << ": " << spelled.err);
    REQUIRE(spelled.exit_code == 0);
    REQUIRE_THAT(spelled.out, Catch::StartsWith("correct: I0"));
  }
  const RunResult neither = run_wobble({"check", "flying-plate", "I_9", "1"});
  REQUIRE(neither.exit_code == 2);
  REQUIRE(neither.out.empty());
  REQUIRE_THAT(neither.err,
               Catch::Contains("no part or answer 'I_9' (answers by part: (a) I0, I;"));
  // The answer given twice is refused before anything is judged.
  const RunResult twice = run_wobble({"check", "flying-plate", "I0", "1", "--answer", "2"});
  REQUIRE(twice.exit_code == 2);
  REQUIRE(twice.out.empty());
  REQUIRE_THAT(twice.err, Catch::Contains("excludes"));
}

TEST_CASE("solve --set reads a parameter as the LaTeX key prints it, name and value") {
  // Each pair: LaTeX (as the key's Parameters line sets it, or typed), and the same in text.
  const std::vector<std::pair<std::string, std::string>> same{
      {"$\\theta_0 = 45^\\circ = 0.7853981634\\,\\mathrm{rad}$", "θ0 = 45°"},
      {"\\dot\\psi_0 = 200\\,\\mathrm{rad/s}", "psidot0=200"},
      {"R=4\\,\\mathrm{cm}", "R=0.04"},
      {"theta0=\\frac{\\pi}{5}", "theta0=36 deg"}};
  for (const auto& [latex, text] : same) {
    INFO(latex);
    const RunResult from_latex = run_wobble({"solve", "heavy-top", "--set", latex});
    const RunResult from_text = run_wobble({"solve", "heavy-top", "--set", text});
    REQUIRE(from_latex.exit_code == 0);
    REQUIRE(from_text.exit_code == 0);
    REQUIRE(from_latex.out == from_text.out);
  }
  REQUIRE_THAT(run_wobble({"solve", "heavy-top"}).out,
               !Catch::Contains("ψ̇0 = 200 rad/s"));  // the default differs: the pairs set something
  // Refused naming the parameter: the key's two sides that disagree, a symbol in a value, a
  // name the problem does not have.
  const std::vector<std::pair<std::string, std::string>> refused{
      {"\\theta_0 = 30^\\circ = 0.6\\,\\mathrm{rad}", "--set theta0: the two sides"},
      {"\\theta_0 = \\frac{M}{2}", "--set theta0: "},
      {"\\dot\\xi = 3", "--set: \\dot \\xi is not one of this problem's symbols"}};
  for (const auto& [latex, message] : refused) {
    INFO(latex);
    const RunResult r = run_wobble({"solve", "heavy-top", "--set", latex});
    REQUIRE(r.exit_code == 2);
    REQUIRE(r.out.empty());
    REQUIRE_THAT(r.err, Catch::StartsWith("wobble: " + message));
  }
}

TEST_CASE("a handout shows each value as it was given, its unit too; a --set over a variant wins") {
  const RunResult given = run_wobble({"solve", "heavy-top", "--handout", "--set", "R=5 [cm]",
                                      "--set", "θ0=45°", "--set", "psidot0 = 1432 rpm"});
  INFO(given.err);
  REQUIRE(given.exit_code == 0);
  REQUIRE_THAT(given.out, Catch::Contains("R  = 5 cm   (") && Catch::Contains("θ0 = 45°   (") &&
                              Catch::Contains("ψ̇0 = 1432 rpm   (") && !Catch::Contains("cm m"));
  const RunResult latex = run_wobble({"solve", "heavy-top", "--handout", "--format", "latex",
                                      "--set", "R=5 cm", "--set", "g=9.81 m/s²"});
  REQUIRE_THAT(latex.out, Catch::Contains("$R$ & $5\\,\\mathrm{cm}$") &&
                              Catch::Contains("$9.81\\,\\mathrm{m/s^{2}}$"));
  // Variant 3's m is 0.25 kg; the --set after it is what the key uses, and what it shows.
  const RunResult over =
      run_wobble({"solve", "flying-plate", "--variant", "3", "--set", "m=1", "--handout"});
  REQUIRE_THAT(over.out, Catch::Contains("m = 1 kg   (mass)"));
}

TEST_CASE(
    "variants: the handout has the numbers and no answers; keys per variant; check a variant") {
  const RunResult handout =
      run_wobble({"solve", "flying-plate", "--variant", "1", "--handout", "--format", "markdown"});
  REQUIRE(handout.exit_code == 0);
  REQUIRE_THAT(handout.out, Catch::Contains("(variant 1)") && Catch::Contains("| 0.12 | kg |") &&
                                Catch::Contains("| 24 | ° |") && Catch::Contains("**(h)**"));
  // The names of the answers to give (for `check --name`), never the answers.
  REQUIRE_THAT(handout.out, Catch::Contains("`t_max` [s]") && !Catch::Contains("Steps"));
  // An answer that does not exist at a variant's values is one to give all the same (its answer
  // is "none"), in its unit: a handout without it would give that away.
  for (const std::string format : {"text", "markdown"}) {
    const RunResult slow =
        run_wobble({"solve", "heavy-top", "--set", "psidot0=10", "--handout", "--format", format});
    REQUIRE(slow.exit_code == 0);
    REQUIRE_THAT(slow.out, format == "text"
                               ? Catch::EndsWith("answers to give: phidot_slow [rad/s], "
                                                 "phidot_fast [rad/s]\n")
                               : Catch::EndsWith("`phidot_slow` [rad/s], `phidot_fast` [rad/s]\n"));
  }
  // At a terminal (the default format): plain text, the angle as the handout gives it.
  const RunResult text = run_wobble({"solve", "flying-plate", "--variant", "1", "--handout"});
  REQUIRE_THAT(text.out, Catch::Contains("(variant 1)") && Catch::Contains("α = 24°") &&
                             Catch::Contains("(h)") && !Catch::Contains("$"));
  const fs::path dir = scratch_dir() / "variants";
  fs::remove_all(dir);
  const RunResult keys = run_wobble({"keys", "--variants", "1-2", "--out", dir.string()});
  INFO(keys.err);
  REQUIRE(keys.exit_code == 0);
  REQUIRE(fs::exists(dir / "flying-plate-v2.md"));
  // A variant key names its variant and shows the values as the handout does.
  REQUIRE_THAT(slurp(dir / "flying-plate-v1.md"),
               Catch::Contains("0.12") && Catch::Contains("variant 1") &&
                   Catch::Contains("24° = 0.4188790205"));
  REQUIRE(nlohmann::json::parse(slurp(dir / "flying-plate-v1.json"))["variant"] == 1);
  // One problem only.
  const fs::path one = scratch_dir() / "variants-one";
  fs::remove_all(one);
  REQUIRE(run_wobble({"keys", "--variants", "1-3", "--problem", "rect-solid", "--out",
                      one.string()})
              .exit_code == 0);
  REQUIRE(std::distance(fs::directory_iterator(one), fs::directory_iterator()) == 6);
  REQUIRE(fs::exists(one / "rect-solid-v3.json"));
  // A problem file anywhere, as for solve; one named twice (by its id and its path) is one, and
  // two files of one id, whose keys would share names, are refused before anything is written.
  const fs::path catalog_file = fs::path(WOBBLE_SOURCE_DIR) / "problems" / "rect-solid.toml";
  const fs::path by_file = scratch_dir() / "variants-file";
  fs::remove_all(by_file);
  const RunResult twice =
      run_wobble({"keys", "--variants", "1-3", "--problem", "rect-solid", "--problem",
                  catalog_file.string(), "--out", by_file.string()});
  INFO(twice.err);
  REQUIRE(twice.exit_code == 0);
  REQUIRE(std::distance(fs::directory_iterator(by_file), fs::directory_iterator()) == 6);
  REQUIRE(slurp(by_file / "rect-solid-v2.json") == slurp(one / "rect-solid-v2.json"));
  const fs::path copy = scratch_dir() / "variants-copy" / "rect-solid.toml";
  fs::create_directories(copy.parent_path());
  fs::copy_file(catalog_file, copy, fs::copy_options::overwrite_existing);
  const fs::path never = scratch_dir() / "variants-never";
  fs::remove_all(never);
  const RunResult clash = run_wobble({"keys", "--variants", "1-3", "--problem", "rect-solid",
                                      "--problem", copy.string(), "--out", never.string()});
  REQUIRE(clash.exit_code == 2);
  REQUIRE_THAT(clash.err, Catch::Contains("--problem: '") &&
                              Catch::Contains("are both problem 'rect-solid'; their keys would "
                                              "share file names"));
  REQUIRE_FALSE(fs::exists(never));
  const RunResult refused = run_wobble({"keys", "--variants", "1-2", "--out", dir.string()});
  REQUIRE(refused.exit_code == 2);
  REQUIRE_THAT(refused.err, Catch::Contains("exists; use --force to overwrite it"));
  REQUIRE(run_wobble({"keys", "--variants", "1-2", "--out", dir.string(), "--force"}).exit_code ==
          0);
  // A student checks an answer of variant 1 against variant 1's key.
  const auto j = nlohmann::json::parse(slurp(dir / "flying-plate-v1.json"));
  const double t_max = j["parts"][7]["answers"][0]["value"];
  REQUIRE_THAT(handout.out, !Catch::Contains(fmt::format("{:.4g}", t_max)));
  REQUIRE(run_wobble({"check", "flying-plate", "h", "--variant", "1", "--answer",
                      fmt::format("{:.6g} s", t_max)})
              .exit_code == 0);
  REQUIRE(run_wobble({"check", "flying-plate", "h", "--variant", "2", "--answer",
                      fmt::format("{:.6g} s", t_max)})
              .exit_code == 1);
}

TEST_CASE("check --answers: '-' reads standard input, and a pipe is read by its path") {
  const std::string exe = std::string("'") + WOBBLE_EXE + "'";
  const std::string answers = "printf 'omega3 = 150 rad/s\\nomega3_min 118.8 rad/s\\n'";
  const RunResult piped =
      run_shell(answers + " | " + exe + " check heavy-top --answers - --format json");
  INFO(piped.err);
  REQUIRE(piped.exit_code == 1);  // the other answers are not given
  const auto judged = nlohmann::json::parse(piped.out);
  int right = 0;
  for (const auto& a : judged.at("answers")) right += a.at("correct").get<bool>();
  REQUIRE(right == 2);
  // A named pipe, as the shell's "<(..)" hands one over: a file to read, not refused as none.
  const auto fifo = wobble::test::scratch_dir() / "answers.fifo";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const RunResult named = run_shell("(" + answers + " > '" + fifo.string() + "' &) ; " + exe +
                                    " check heavy-top --answers '" + fifo.string() + "'");
  INFO(named.err);
  REQUIRE_THAT(named.out, Catch::Contains("(c) correct: omega3\n(c) correct: omega3_min\n"));
  // Past the limit, standard input is refused as a file is, with no verdict printed.
  const RunResult large =
      run_shell("head -c 1100000 /dev/zero | " + exe + " check heavy-top --answers -");
  REQUIRE(large.exit_code == 2);
  REQUIRE(large.out.empty());
  REQUIRE(large.err == "wobble: --answers: standard input is larger than 1048576 bytes\n");
  // A folder is no file.
  REQUIRE_THAT(
      run_wobble({"check", "heavy-top", "--answers", wobble::test::scratch_dir().string()}).err,
      Catch::EndsWith("is not a file\n"));
}

TEST_CASE("worksheet driven end to end by piped input: feedback, hint, reveal, skip, quit") {
  const std::string exe = std::string("'") + WOBBLE_EXE + "'";
  // Part (a): the wrong sign (feedback), an unreadable line (asked again), then right.
  // Flying plate (a) I0: a wrong try twice brings the hint by itself; then '!' reveals.
  const RunResult a = run_shell(
      "printf '[[10,0,0],[0,6,-1],[0,-1,6]]\\nabc(\\n[[10,0,0],[0,6,1],[0,1,6]]\\ns\\n' | " + exe +
      " worksheet taylor-10-35");
  INFO(a.out << a.err);
  REQUIRE(a.exit_code == 0);
  REQUIRE_THAT(a.out,
               Catch::Contains("products of inertia have the wrong sign") &&
                   Catch::Contains("cannot read that: expression \"abc(\" is refused") &&
                   !Catch::Contains("--answer") && Catch::Contains("correct: I") &&
                   Catch::Contains("summary: 1 right, 0 revealed, 1 skipped, 0 not reached"));
  const RunResult b =
      run_shell("printf '1\\n2\\n!\\nq\\n' | " + exe + " worksheet flying-plate --variant 3");
  INFO(b.out << b.err);
  REQUIRE(b.exit_code == 0);
  REQUIRE_THAT(b.out,
               Catch::Contains("(variant 3)") && Catch::Contains("hint: A thin disc") &&
                   Catch::Contains("answer: m·R²/4 = 0.0009 kg m²") &&
                   Catch::Contains("summary: 0 right, 1 revealed, 0 skipped, 7 not reached"));
  // The commands as words, in any case; a part left after one of its two answers is said so.
  const RunResult d = run_shell("printf 'help\\nHint\\n0.00072 kg m²\\nQuit\\n' | " + exe +
                                " worksheet flying-plate");
  INFO(d.out << d.err);
  REQUIRE(d.exit_code == 0);
  REQUIRE_THAT(d.out,
               Catch::Contains("(help: the commands as words)") &&
                   Catch::Contains("  commands, as symbols or words in any case: ? or hint") &&
                   Catch::Contains("hint: A thin disc") && Catch::Contains("correct: I0") &&
                   !Catch::Contains("cannot read") &&
                   Catch::Contains("summary: 0 right, 0 revealed, 0 skipped, 7 not reached "
                                   "(of 8 parts; (a) left unfinished, 1 of its 2 answers "
                                   "right)"));
  // A matrix pasted as NumPy prints it, over three lines: one answer, its rows under a prompt
  // of dots; an empty line ends one left open (judged as it stands); a '(' left open does not
  // wait for more lines.
  const RunResult m = run_shell(
      "printf '[[ 4.33333333 -0.5 -0.75 ]\\n [-0.5 3.33333333 -1.5 ]\\n [-0.75 -1.5 "
      "1.66666667]]\\n[0.5,\\n\\nsqrt(2\\n[0.5, 1, 1.5]\\nq\\n' | " +
      exe + " worksheet box-corner");
  INFO(m.out << m.err);
  REQUIRE(m.exit_code == 0);
  REQUIRE_THAT(m.out, Catch::Contains("... [-0.75 -1.5 1.66666667]]") &&
                          Catch::Contains("correct: I_corner") &&
                          Catch::Contains("\"[0.5,\": it is not a complete expression") &&
                          Catch::Contains("a '(' is not closed") &&
                          Catch::Contains("correct: center_of_mass"));
  // An answer that does not exist at these values is asked as the others are (its unit in the
  // prompt), "none" right with the key's reason (a horizontal axle's fast precession), a number
  // wrong; '!' shows "none", which pasted back is right.
  const RunResult h = run_shell("printf 's\\ns\\ns\\nM g l/(M R^2/2 psidot0)\\n3\\nDNE\\n' | " +
                                exe + " worksheet heavy-top --set theta0=90deg");
  INFO(h.out << h.err);
  REQUIRE(h.exit_code == 0);
  REQUIRE_THAT(
      h.out, Catch::Contains("correct: phidot_slow (your expression") &&
                 Catch::Contains("  phidot_fast [rad/s] = 3\n  incorrect: phidot_fast "
                                 "does not exist at these values\n    θ0 = 90°: the axle "
                                 "is horizontal") &&
                 Catch::Contains("  phidot_fast [rad/s] = DNE\n  correct: phidot_fast does not") &&
                 Catch::Contains("summary: 1 right, 0 revealed, 3 skipped"));
  // A part of only such answers (a spin too slow to precess steadily) is asked too; revealed,
  // "none at these values" with why under it.
  const RunResult slow = run_shell("printf 's\\ns\\ns\\n!\\nnone at these values\\n' | " + exe +
                                   " worksheet heavy-top --set psidot0=10");
  INFO(slow.out << slow.err);
  REQUIRE(slow.exit_code == 0);
  REQUIRE_THAT(
      slow.out,
      Catch::Contains("  phidot_slow [rad/s] = !\n  answer: none at these values\n    phidot_slow "
                      "does not exist at these values: ") &&
          Catch::Contains("  phidot_fast [rad/s] = none at these values\n  correct: phidot_fast") &&
          Catch::Contains("summary: 0 right, 1 revealed, 3 skipped, 0 not reached (of 4 "
                          "parts)\n"));
  // End of input at once: no wait, a summary.
  const RunResult c = run_shell(exe + " worksheet flying-plate < /dev/null");
  REQUIRE(c.exit_code == 0);
  REQUIRE_THAT(c.out, Catch::Contains("(end of input)") && Catch::Contains("8 not reached"));
}

TEST_CASE("keys --help says what to give in words") {
  const RunResult help = run_wobble({"keys", "--help"});
  REQUIRE(help.exit_code == 0);
  REQUIRE_THAT(help.out, !Catch::Contains("follow options") && Catch::Contains("Give one of") &&
                             Catch::Contains("--problem"));
}

namespace {
// A shell line that starts `command`, sends it SIGINT a second after it has installed its
// handler (SIGINT's bit in SigCgt of /proc/PID/status; waiting at most 20 s for it), and exits
// with its status. A fixed delay is not enough: under the sanitizers on a loaded machine the
// signal came before the handler at one second, and once at three (exit 130, no message).
std::string interrupt_when_ready(const std::string& command) {
  const fs::path script = scratch_dir() / "interrupt-when-ready.sh";
  std::ofstream(script) << command << " &\n"
                        << "p=$!\n"
                        << "for i in $(seq 400); do\n"
                        << "  m=$(sed -n 's/^SigCgt:[[:space:]]*//p' /proc/$p/status 2>/dev/null)\n"
                        << "  [[ -n $m ]] && (( (16#$m >> 1) & 1 )) && break\n"
                        << "  sleep 0.05\n"
                        << "done\n"
                        << "sleep 1\n"
                        << "kill -INT $p\n"
                        << "wait $p\n";
  return "bash '" + script.string() + "'";
}
}  // namespace

TEST_CASE("Ctrl-C stops a long command cleanly: exit 130, no file and no temporary left") {
  const fs::path dir = scratch_dir() / "interrupted";
  fs::remove_all(dir);
  const std::string exe = std::string("'") + WOBBLE_EXE + "'";
  // keys for 300 variants of every problem takes minutes: the signal comes mid-run.
  const RunResult keys = run_shell(interrupt_when_ready(
      exe + " keys --variants 1-300 --out '" + dir.string() + "'"));
  INFO(keys.err);
  CHECK(keys.exit_code == 130);
  CHECK_THAT(keys.err, Catch::Contains("interrupted"));
  CHECK(!fs::exists(dir));  // nothing was staged yet: the folder was never made
  // A long simulation with files to write: neither file nor temporary appears.
  fs::create_directories(dir);
  // 2e5 s of the heavy top integrated: about 26 s in a release build (9e8 evaluations), so the
  // signal comes mid-run.
  const RunResult sim = run_shell(interrupt_when_ready(
      exe + " simulate heavy-top --method rkf78 --t-end 2e5 --max-evaluations 1e11 --out '" +
      (dir / "run.csv").string() + "' --plot '" + (dir / "run.svg").string() + "'"));
  INFO(sim.err);
  CHECK(sim.exit_code == 130);
  CHECK(fs::is_empty(dir));
}

TEST_CASE("two keys --variants runs into one folder: one wins whole, the other writes nothing") {
  // Without --force neither may replace a file; before, both could exit 0 and mix the folder.
  const std::string exe = std::string("'") + WOBBLE_EXE + "'";
  for (int trial = 0; trial < 10; ++trial) {
    const fs::path dir = scratch_dir() / ("race" + std::to_string(trial));
    fs::remove_all(dir);
    const std::string one = exe + " keys --variants 1-1 --problem flying-plate --out '" +
                            dir.string() + "' >/dev/null 2>&1";
    const RunResult r =
        run_shell("(" + one + "; echo $? > '" + dir.string() + ".a') & (" + one + "; echo $? > '" +
                  dir.string() + ".b') & wait; cat '" + dir.string() + ".a' '" + dir.string() +
                  ".b'");
    INFO("trial " << trial << ": exit codes " << r.out);
    CHECK((r.out == "0\n2\n" || r.out == "2\n0\n"));
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) {
      (void)e;
      ++files;
    }
    CHECK(files == 2);  // the winner's .md and .json, no temporary
  }
}
