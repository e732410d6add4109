#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/commands.hpp"
#include "core/input_error.hpp"

namespace wobble::cli {

namespace {
// Text a user hands in (answers, a submission) is small; a larger file is a wrong path.
constexpr std::uintmax_t kMaxTextBytes = 1 << 20;
}  // namespace

std::string read_text_file(const std::string& path, const std::string& option) {
  // "-" is standard input ("xclip -o | wobble check P --answers -"); a pipe or a terminal by its
  // path too ("--answers <(..)" is /dev/fd/63): read as a file is, to the same limit.
  const bool standard_input = path == "-";
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  const bool stream = standard_input || std::filesystem::is_fifo(status) ||
                      std::filesystem::is_character_file(status);
  if (!stream && !std::filesystem::is_regular_file(status)) {
    throw InputError(fmt::format("{}: '{}' is not a file", option, path));
  }
  const std::string named = standard_input ? "standard input" : "'" + path + "'";
  std::ifstream file;
  if (!standard_input) file.open(path, std::ios::binary);
  std::istream& in = standard_input ? std::cin : file;
  if (!in) throw InputError(fmt::format("{}: cannot read {}", option, named));
  // At most one byte past the limit, for a file as for a stream (whose size is known only by
  // reading it).
  std::string text(kMaxTextBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw InputError(fmt::format("{}: cannot read {}", option, named));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxTextBytes) {
    throw InputError(fmt::format("{}: {} is larger than {} bytes", option, named, kMaxTextBytes));
  }
  return text;
}

}  // namespace wobble::cli
