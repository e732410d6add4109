#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/commands.hpp"
#include "core/input_error.hpp"

namespace wobble::cli {

namespace {
// Text a user hands in (answers, a submission) is small; a larger file is a wrong path.
constexpr std::uintmax_t kMaxTextBytes = 1 << 20;
}  // namespace

std::string read_text_file(const std::string& path, const std::string& option) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw InputError(fmt::format("{}: '{}' is not a file", option, path));
  }
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxTextBytes) {
    throw InputError(fmt::format("{}: '{}' is larger than {} bytes", option, path, kMaxTextBytes));
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw InputError(fmt::format("{}: cannot read '{}'", option, path));
  return text.str();
}

}  // namespace wobble::cli
