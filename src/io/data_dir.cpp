#include "io/data_dir.hpp"

#include <cstdlib>
#include <optional>

#include "core/input_error.hpp"

namespace wobble {

namespace {
std::optional<std::filesystem::path>& chosen() {
  static std::optional<std::filesystem::path> dir;
  return dir;
}

std::optional<std::filesystem::path> from_environment(const char* name) {
  const char* value = std::getenv(name);
  if (value == nullptr || *value == '\0') return std::nullopt;
  return std::filesystem::path(value);
}

// BIN/../share/wobble of the running program, if that folder exists.
std::optional<std::filesystem::path> installed() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return std::nullopt;
  const auto share = exe.parent_path().parent_path() / "share" / "wobble";
  if (std::filesystem::is_directory(share / "problems", ec)) return share;
  return std::nullopt;
}
}  // namespace

void set_data_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError("--data-dir: " + dir.string() +
                     " is not a folder (it should hold problems/, scenes/ and solutions/)");
  }
  chosen() = dir;
}

std::filesystem::path data_folder(const std::string& name) {
  if (chosen()) return *chosen() / name;
  const std::string variable = "WOBBLE_" + [&] {
    std::string upper = name;
    for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return upper;
  }();
  if (auto own = from_environment(variable.c_str())) return *own;
  if (auto all = from_environment("WOBBLE_DATA_DIR")) return *all / name;
  if (auto share = installed()) return *share / name;
  return std::filesystem::path(WOBBLE_SOURCE_DIR) / name;
}

}  // namespace wobble
