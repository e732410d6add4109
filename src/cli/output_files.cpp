#include <filesystem>

#include "cli/commands.hpp"
#include "core/input_error.hpp"

namespace wobble::cli {

void refuse_to_replace(const std::string& option, const std::filesystem::path& file, bool force) {
  std::error_code ec;  // an unreadable folder is found where the file is written
  if (!file.empty() && !force && std::filesystem::exists(file, ec)) {
    throw InputError(option + ": " + file.string() + " exists; use --force to overwrite it");
  }
}

}  // namespace wobble::cli
