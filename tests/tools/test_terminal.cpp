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

