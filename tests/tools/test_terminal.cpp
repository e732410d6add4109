// The worksheet in a real terminal (label tmux; skipped without tmux).
#include <fmt/format.h>

#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/run.hpp"
#include "temp_files.hpp"

using namespace wobble::test;
namespace fs = std::filesystem;

TEST_CASE("worksheet at a UTF-8 terminal (tmux): non-ASCII input is kept and read back") {
  WOBBLE_NEEDS_TOOL("tmux");
  // A real terminal, so that the line editor (libedit) reads the keys: it dropped multibyte
  // characters in the C locale. A private tmux server, bounded waits, killed at the end.
  const std::string exe = std::string("'") + WOBBLE_EXE + "'";
  const std::string tmux = "LANG=C.UTF-8 tmux -u -L wobble-test-" + std::to_string(::getpid());
  REQUIRE(run_shell(tmux + " -f /dev/null new-session -d -x 120 -y 50 \"LANG=C.UTF-8 " + exe +
                    " worksheet flying-plate; sleep 20\"")
              .exit_code == 0);
  const auto screen = [&] { return run_shell(tmux + " capture-pane -p -S -100").out; };
  const auto wait_for = [&](const std::string& text) {
    for (int i = 0; i < 100 && screen().find(text) == std::string::npos; ++i) ::usleep(50000);
    return screen();
  };
  wait_for("I0 [kg m²] =");  // the unit as the key prints it
  const auto type = [&](const std::string& keys) {
    REQUIRE(run_shell(tmux + " send-keys -l '" + keys + "'").exit_code == 0);
    REQUIRE(run_shell(tmux + " send-keys Enter").exit_code == 0);
  };
  type("m·R²/4");
  wait_for("I [kg m²] =");
  type("[ 0.00072 0 0 ] [ 0 0.00072 0 ] [ 0 0 0.00144 ] kg m²");
  wait_for("(b)");
  type("s");
  wait_for("angle_omega_e3 [rad] =");
  type("15°");
  const std::string shown = wait_for("correct: angle_omega_e3");
  (void)run_shell(tmux + " kill-server");
  INFO(shown);
  REQUIRE_THAT(shown, Catch::Contains("m·R²/4") && Catch::Contains("correct: I0") &&
                          Catch::Contains("correct: I\n") && Catch::Contains("15°") &&
                          Catch::Contains("correct: angle_omega_e3"));
}

TEST_CASE("worksheet and check at a narrow terminal (tmux): lines break at spaces, not in words") {
  WOBBLE_NEEDS_TOOL("tmux");
  // 60 columns: the statement's lines (about 90) and the feedback on the Earth's observed wobble
  // (220) are wider. capture-pane -J joins what the terminal folded, so a line wider than the
  // terminal there is one the program left for the terminal to fold.
  constexpr std::size_t kColumns = 60;
  const std::string exe = std::string("'") + WOBBLE_EXE + "'";
  const std::string tmux = "LANG=C.UTF-8 tmux -u -L wobble-narrow-" + std::to_string(::getpid());
  REQUIRE(run_shell(fmt::format("{} -f /dev/null new-session -d -x {} -y 80 \"LANG=C.UTF-8 {} "
                                "check earth-free-precession precession_period_body '433 days'; "
                                "LANG=C.UTF-8 {} worksheet earth-free-precession; sleep 20\"",
                                tmux, kColumns, exe, exe))
              .exit_code == 0);
  const auto screen = [&] { return run_shell(tmux + " capture-pane -p -J -S -200").out; };
  const auto wait_for = [&](const std::string& text) {
    for (int i = 0; i < 100 && screen().find(text) == std::string::npos; ++i) ::usleep(50000);
    return screen();
  };
  wait_for("Omega_body_rate [rad/s] =");
  REQUIRE(run_shell(tmux + " send-keys -l '2.395e-7 rad/s'").exit_code == 0);
  REQUIRE(run_shell(tmux + " send-keys Enter").exit_code == 0);
  wait_for("precession_period_body [s] =");
  REQUIRE(run_shell(tmux + " send-keys -l '433 days'").exit_code == 0);
  REQUIRE(run_shell(tmux + " send-keys Enter").exit_code == 0);
  const std::string shown = wait_for("the observed one\n  precession_period_body");
  (void)run_shell(tmux + " kill-server");
  INFO(shown);
  // Both said it (check first, then the worksheet), each over several lines.
  std::size_t said = 0;
  for (std::size_t at = shown.find("Chandler's"); at != std::string::npos;
       at = shown.find("Chandler's", at + 1))
    ++said;
  REQUIRE(said >= 3);  // the title, check's feedback, the worksheet's
  std::istringstream lines(shown);
  for (std::string line; std::getline(lines, line);) {
    std::size_t columns = 0;  // UTF-8: count the bytes that start a character
    for (const char c : line) columns += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    INFO(line);
    CHECK(columns <= kColumns);
  }
}
