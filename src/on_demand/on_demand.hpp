#pragma once
/// @file
/// The parts loaded only when a command needs them: the HTTP server (cpp-httplib) and the zip
/// writer (libzip). Both libraries bring OpenSSL's libcrypto, and the dynamic loader binding its
/// 21000 relocations was a third of every command's start-up; built into a module of their own
/// (wobble-on-demand.so), they cost only `serve` and `export gradescope`.
///
/// The module is built with the program and must match it: it finds the rest of wobble in the
/// program itself (exported symbols), and hands the program an Entry of function pointers, the
/// one symbol the program looks up. Where the program looks: next to itself (the build tree),
/// then in the install's library folder (lib/wobble/, relative to bin/).
#include <memory>
#include <string>
#include <vector>

#include "export/output_file.hpp"
#include "serve/server.hpp"

namespace wobble::on_demand {

/// serve::Server as the program uses it: through virtual calls, which need no symbol of the
/// module's to be linked into the program.
class Service {
 public:
  virtual ~Service() = default;
  virtual int bind() = 0;  ///< @return the port; @throws InputError naming host and port
  virtual void run() = 0;
  virtual void stop() = 0;
  virtual const std::string& token() const = 0;
};

struct Entry {
  const char* version;  ///< the program's version the module was built with
  std::unique_ptr<Service> (*make_server)(serve::ServeOptions options);
  std::string (*zip_archive)(const std::vector<exports::OutputFile>& files);
};

/// The name of the module's one exported function, `const Entry* wobble_on_demand_entry()`.
inline constexpr const char* kEntrySymbol = "wobble_on_demand_entry";
/// The module's file name.
inline constexpr const char* kModuleFile = "wobble-on-demand.so";

/// The module's entry, loaded on first use. @throws std::runtime_error naming the file looked
/// for and why it could not be loaded (missing, or built for another version).
const Entry& load();

}  // namespace wobble::on_demand
