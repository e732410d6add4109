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

}  // namespace wobble::test
