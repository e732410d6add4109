#pragma once
// Runs the wobble executable as a user would, capturing exit code, stdout and stderr.
#include <map>
#include <string>
#include <vector>

namespace wobble::test {

struct RunResult {
  int exit_code = -1;
  std::string out, err;
};

/// Runs WOBBLE_EXE with `args` (each quoted for the shell), stdin from /dev/null, with the
/// extra environment variables `env`.
RunResult run_wobble(const std::vector<std::string>& args,
                     const std::map<std::string, std::string>& env = {});

/// Runs a shell command line; returns its exit code (stdout/stderr captured likewise).
RunResult run_shell(const std::string& command_line);

/// The problem ids, as `wobble list` prints them.
std::vector<std::string> problem_ids();

/// Whether the program `name` is on the PATH.
bool have_tool(const std::string& name);

}  // namespace wobble::test

/// Ends the test case as skipped when `tool` is missing: ctest reports it skipped, not passed
/// (tests/CMakeLists.txt sets SKIP_REGULAR_EXPRESSION on the message), so a machine without
/// pdflatex or gnuplot shows what it did not test.
#define WOBBLE_NEEDS_TOOL(tool)                                      \
  do {                                                               \
    if (!::wobble::test::have_tool(tool)) {                          \
      WARN("SKIPPED: this test needs " << (tool) << " on the PATH"); \
      return;                                                        \
    }                                                                \
  } while (false)
