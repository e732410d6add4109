// README's console examples are run: each "$ wobble ..." line in a ```console block is executed
// and its output must be the lines that follow it in the README, exactly (run times aside).
#include <catch2/catch.hpp>
#include <fstream>
#include <regex>
#include <sstream>

#include "cli/run.hpp"

using namespace wobble::test;

namespace {
struct Example {
  std::string command;
  std::string expected;
};

std::vector<Example> readme_examples() {
  std::ifstream in(std::string(WOBBLE_SOURCE_DIR) + "/README.md");
  std::vector<Example> out;
  std::string line;
  bool in_console = false;
  while (std::getline(in, line)) {
    if (line == "```console") {
      in_console = true;
    } else if (in_console && line == "```") {
      in_console = false;
    } else if (in_console && line.rfind("$ wobble", 0) == 0) {
      out.push_back({line.substr(std::string("$ wobble").size()), ""});
    } else if (in_console && !out.empty()) {
      out.back().expected += line + "\n";
    }
  }
  return out;
}
// Run times differ from run to run: compare everything else.
std::string without_times(const std::string& text) {
  static const std::regex kTime(
      R"((run time |cost of the key: |evaluations, )[0-9.]+ (us|ms|s)\b)");
  return std::regex_replace(text, kTime, "$1<time>");
}
}  // namespace

TEST_CASE("README console examples produce exactly the output shown") {
  const auto examples = readme_examples();
  REQUIRE(examples.size() >= 2);
  for (const auto& ex : examples) {
    const RunResult r = run_shell("'" + std::string(WOBBLE_EXE) + "'" + ex.command);
    INFO("$ wobble" << ex.command << "\n" << r.err);
    REQUIRE(r.exit_code == 0);
    REQUIRE(without_times(r.out) == without_times(ex.expected));
  }
}
