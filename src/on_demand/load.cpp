// The program's side: finds the module, loads it once, checks that it was built with this program.
#include <dlfcn.h>
#include <fmt/format.h>

#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "on_demand/on_demand.hpp"

namespace wobble::on_demand {
namespace {
namespace fs = std::filesystem;

// Next to the program (the build tree), then the install's place relative to bin/.
std::vector<fs::path> candidates() {
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {kModuleFile};  // a bare name: dlopen's own search (LD_LIBRARY_PATH, ...)
  const fs::path dir = self.parent_path();
  return {dir / kModuleFile, (dir / WOBBLE_MODULE_FROM_BIN / kModuleFile).lexically_normal()};
}

const Entry& load_once() {
  const auto paths = candidates();
  std::string tried;
  for (const auto& path : paths) {
    std::error_code ec;
    if (path.is_absolute() && !fs::exists(path, ec)) {
      tried += (tried.empty() ? "" : ", ") + path.string();
      continue;
    }
    // RTLD_NOW: a symbol the module needs and the program lacks fails here, naming it, not
    // midway through a command.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      throw std::runtime_error(fmt::format("cannot load {}: {}", path.string(), dlerror()));
    }
    using EntryFunction = const Entry* (*)();
    const auto entry = reinterpret_cast<EntryFunction>(dlsym(handle, kEntrySymbol));
    if (entry == nullptr) {
      throw std::runtime_error(
          fmt::format("{} is not wobble's module: {}", path.string(), dlerror()));
    }
    const Entry* e = entry();
    if (std::strcmp(e->version, WOBBLE_VERSION) != 0) {
      throw std::runtime_error(fmt::format("{} belongs to wobble {}, this is wobble {}",
                                           path.string(), e->version, WOBBLE_VERSION));
    }
    return *e;  // the module stays loaded until the program exits
  }
  throw std::runtime_error(fmt::format("the module {} is missing (looked for {})",
                                       kModuleFile, tried));
}
}  // namespace

const Entry& load() {
  static const Entry& entry = load_once();  // thread-safe, once; a failure is retried
  return entry;
}

}  // namespace wobble::on_demand
