#pragma once
// A per-process scratch folder for files the tests write (no randomness: named by pid), removed
// when the process exits (ctest starts one process per test case: hundreds of them).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace wobble::test {

inline std::filesystem::path scratch_dir() {
  static const std::filesystem::path dir = [] {
    auto d =
        std::filesystem::temp_directory_path() / ("wobble-tests-" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  static const struct Remover {
    std::filesystem::path path;
    ~Remover() {
      std::error_code ignored;  // a file still open elsewhere: leave it, never throw at exit
      std::filesystem::remove_all(path, ignored);
    }
  } remover{dir};
  return dir;
}

inline std::filesystem::path write_file(const std::string& name, const std::string& content) {
  const auto path = scratch_dir() / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

/// A file's whole content ("" if it cannot be read).
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace wobble::test
