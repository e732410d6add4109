#include "export/gradescope.hpp"

#include <fmt/format.h>
#include <zip.h>

#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

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

struct ZipSourceDeleter {
  void operator()(zip_source_t* s) const { zip_source_free(s); }
};

[[noreturn]] void zip_failed(const std::string& what, zip_error_t* error) {
  const std::string message = fmt::format("zip: {}: {}", what, zip_error_strerror(error));
  zip_error_fini(error);
  throw std::runtime_error(message);
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

std::string zip_archive(const std::vector<OutputFile>& files) {
  zip_error_t error;
  zip_error_init(&error);
  std::unique_ptr<zip_source_t, ZipSourceDeleter> buffer(
      zip_source_buffer_create(nullptr, 0, 0, &error));
  if (!buffer) zip_failed("cannot make a buffer", &error);
  zip_source_keep(buffer.get());  // the archive's close frees it once; we read it after
  zip_t* archive = zip_open_from_source(buffer.get(), ZIP_TRUNCATE, &error);
  if (archive == nullptr) zip_failed("cannot open the archive", &error);
  for (const auto& f : files) {
    zip_source_t* data = zip_source_buffer(archive, f.content.data(), f.content.size(), 0);
    const zip_int64_t index =
        data ? zip_file_add(archive, f.path.c_str(), data, ZIP_FL_ENC_UTF_8) : -1;
    if (index < 0) {
      if (data) zip_source_free(data);
      const std::string message = zip_strerror(archive);
      zip_discard(archive);
      throw std::runtime_error("zip: cannot add " + f.path + ": " + message);
    }
    const auto i = static_cast<zip_uint64_t>(index);
    // A .deb is compressed already: stored, not deflated again.
    if (f.path.size() > 4 && f.path.compare(f.path.size() - 4, 4, ".deb") == 0) {
      zip_set_file_compression(archive, i, ZIP_CM_STORE, 0);
    }
    const zip_uint32_t mode = f.executable ? 0100755 : 0100644;
    zip_file_set_external_attributes(archive, i, 0, ZIP_OPSYS_UNIX, mode << 16);
  }
  if (zip_close(archive) < 0) {
    const std::string message = zip_strerror(archive);
    zip_discard(archive);
    throw std::runtime_error("zip: cannot write the archive: " + message);
  }
  zip_source_t* src = buffer.get();
  zip_stat_t stat;
  if (zip_source_stat(src, &stat) < 0 || zip_source_open(src) < 0) {
    throw std::runtime_error("zip: cannot read the archive back");
  }
  std::string out(static_cast<std::size_t>(stat.size), '\0');
  const zip_int64_t got = zip_source_read(src, out.data(), stat.size);
  zip_source_close(src);
  if (got < 0 || static_cast<zip_uint64_t>(got) != stat.size) {
    throw std::runtime_error("zip: cannot read the archive back");
  }
  zip_error_fini(&error);
  return out;
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
