#include "export/gradescope.hpp"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/input_error.hpp"

namespace wobble::exports {

namespace {
// Every Debian package (an ar archive) begins so.
constexpr std::string_view kDebMagic = "!<arch>\ndebian-binary";
// A wobble package is some tens of megabytes; a file far larger is not one.
constexpr std::uintmax_t kMaxDebBytes = 512ull << 20;

std::string setup_sh(const std::string& deb_name) {
  return fmt::format(R"SH(#!/usr/bin/env bash
# Gradescope runs this once when it builds the autograder image: it installs wobble from the
# Debian package beside it. The package needs Debian 12's libraries (libfmt9, libginac11,
# libtomlplusplus3, libzip4); where they are missing apt-get stops and names them.
set -euo pipefail
cd "$(dirname "$0")"
apt-get update -qq
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq ./{0}
wobble --version
)SH",
                     deb_name);
}

std::string run_autograder(const std::string& problem_file, const std::string& check_options) {
  return fmt::format(R"SH(#!/usr/bin/env bash
# Grades the submission with wobble's judge and writes Gradescope's results.json.
# The submission is a text file, one answer per line (NAME = ANSWER) and optionally the line
# "variant = N" for a student's own values; answers.txt is read if present, else the first .txt.
# AUTOGRADER_ROOT relocates /autograder and WOBBLE names the program (for tests elsewhere).
set -uo pipefail
root="${{AUTOGRADER_ROOT:-/autograder}}"
wobble="${{WOBBLE:-wobble}}"
results="$root/results/results.json"
mkdir -p "$root/results"
submission="$root/submission/answers.txt"
if [[ ! -f "$submission" ]]; then
  submission=$(find "$root/submission" -maxdepth 1 -type f -name '*.txt' 2>/dev/null | sort | head -n 1)
fi
if [[ -z "$submission" ]]; then
  printf '%s\n' '{{"score": 0, "output": "No answers file: submit a .txt file with one answer per line (NAME = ANSWER)."}}' > "$results"
  exit 0
fi
"$wobble" check "$root/source/{0}" --answers "$submission" --format gradescope{1} > "$results.tmp" 2> "$root/results/wobble.err"
status=$?
if [[ $status -le 1 ]]; then
  mv "$results.tmp" "$results"
else
  # A submission wobble refuses as a whole (too large, a variant that is no number): say so.
  reason=$(head -c 300 "$root/results/wobble.err" | tr -d '"\\' | tr '\n\t' '  ')
  printf '{{"score": 0, "output": "The submission could not be graded: %s"}}\n' "$reason" > "$results"
  rm -f "$results.tmp"
fi
exit 0
)SH",
                     problem_file, check_options.empty() ? "" : " " + check_options);
}

std::string read_file(const std::filesystem::path& path, const std::string& field) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || !std::filesystem::is_regular_file(path)) {
    throw InputError(fmt::format("{}: cannot read '{}'", field, path.string()));
  }
  if (size > kMaxDebBytes) {
    throw InputError(fmt::format("{}: '{}' has {} bytes, more than a wobble package", field,
                                 path.string(), size));
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream out;
  out << in.rdbuf();
  if (!in.good() && !in.eof()) {
    throw InputError(fmt::format("{}: cannot read '{}'", field, path.string()));
  }
  return out.str();
}

}  // namespace

std::vector<OutputFile> gradescope_autograder(const Problem& problem,
                                              const std::filesystem::path& deb,
                                              const std::string& check_options) {
  std::string package = read_file(deb, "--deb");
  if (package.compare(0, kDebMagic.size(), kDebMagic) != 0) {
    throw InputError(fmt::format("--deb: '{}' is not a Debian package", deb.string()));
  }
  const std::string problem_file = problem.id + ".toml";
  return {{"setup.sh", setup_sh(deb.filename().string()), true},
          {"run_autograder", run_autograder(problem_file, check_options), true},
          {problem_file, read_file(problem.file, "problem")},
          {deb.filename().string(), std::move(package)}};
}

std::string gradescope_results(const check::SubmissionResult& result) {
  using nlohmann::json;
  json tests = json::array();
  double score = 0.0;
  for (const auto& a : result.answers) {
    std::string output = a.verdict.line;
    for (const auto& f : a.verdict.feedback) output += "\n  " + f;
    if (a.answered) output = "you gave: " + a.typed + "\n" + output;
    const double s = a.verdict.correct ? 1.0 : 0.0;
    score += s;
    tests.push_back({{"name", fmt::format("({}) {}", a.part, a.name)},
                     {"score", s},
                     {"max_score", 1.0},
                     {"status", a.verdict.correct ? "passed" : "failed"},
                     {"output", output},
                     {"visibility", "visible"}});
  }
  std::string output;
  for (const auto& p : result.problems) output += p + "\n";
  json results = {{"score", score}, {"tests", tests}, {"visibility", "visible"}};
  if (!output.empty()) results["output"] = output;
  return results.dump(2) + "\n";
}

}  // namespace wobble::exports
