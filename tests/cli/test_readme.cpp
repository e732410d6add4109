// README's console examples are run: each "$ wobble ..." line in a ```console block is executed
// and its output must be the lines that follow it in the README, exactly (run times aside).
#include <catch2/catch.hpp>
#include <cctype>
#include <fstream>
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
// Run times differ from run to run: compare everything else. (Plain string scanning: GCC 12
// reports -Wmaybe-uninitialized inside std::regex under the sanitizer build.)
std::string without_times(std::string text) {
  for (const std::string lead : {"run time ", "cost of the key: ", "evaluations, "}) {
    for (std::size_t at = text.find(lead); at != std::string::npos; at = text.find(lead, at + 1)) {
      const std::size_t from = at + lead.size();
      std::size_t to = from;
      while (to < text.size() &&
             (std::isdigit(static_cast<unsigned char>(text[to])) || text[to] == '.'))
        ++to;
      if (to == from || to >= text.size() || text[to] != ' ') continue;
      std::size_t unit = to + 1;
      while (unit < text.size() && std::isalpha(static_cast<unsigned char>(text[unit]))) ++unit;
      text.replace(from, unit - from, "<time>");
    }
  }
  return text;
}
}  // namespace

TEST_CASE("README console examples produce exactly the output shown") {
  const auto examples = readme_examples();
  REQUIRE(examples.size() >= 2);
  for (const auto& ex : examples) {
    const RunResult r = run_shell("'" + std::string(WOBBLE_EXE) + "'" + ex.command);
    INFO("$ wobble" << ex.command << "\n" << r.err);
    // `check` reports a wrong answer with exit 1, and the README shows one.
    const bool check = ex.command.rfind(" check ", 0) == 0;
    REQUIRE((r.exit_code == 0 || (check && r.exit_code == 1)));
    REQUIRE(without_times(r.out) == without_times(ex.expected));
  }
}
