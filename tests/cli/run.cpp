#include "cli/run.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "temp_files.hpp"

namespace wobble::test {

namespace {
std::string quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

RunResult run_shell(const std::string& command_line) {
  static int counter = 0;
  const auto dir = scratch_dir();
  const auto out = dir / ("run-" + std::to_string(++counter) + ".out");
  const auto err = dir / ("run-" + std::to_string(counter) + ".err");
  const std::string cmd = "( " + command_line + " ) < /dev/null > " + quote(out.string()) + " 2> " +
                          quote(err.string());
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

RunResult run_wobble(const std::vector<std::string>& args,
                     const std::map<std::string, std::string>& env) {
  std::string line;
  for (const auto& [k, v] : env) line += k + "=" + quote(v) + " ";
  line += quote(WOBBLE_EXE);
  for (const auto& a : args) line += " " + quote(a);
  return run_shell(line);
}

std::vector<std::string> problem_ids() {
  std::istringstream list(run_wobble({"list"}).out);
  std::vector<std::string> ids;
  bool in_problems = false;
  for (std::string line; std::getline(list, line);) {
    if (line.rfind("  ", 0) != 0) {
      in_problems = line.rfind("problems", 0) == 0;
    } else if (in_problems) {
      ids.push_back(line.substr(2, line.find(' ', 2) - 2));
    }
  }
  return ids;
}

bool have_tool(const std::string& name) {
  return run_shell("command -v " + quote(name)).exit_code == 0;
}

}  // namespace wobble::test
