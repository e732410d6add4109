#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <thread>

#include "cli/commands.hpp"
#include "core/input_error.hpp"
#include "core/work_budget.hpp"
#include "on_demand/on_demand.hpp"
#include "problem/scene.hpp"
#include "solvers/catalog.hpp"

namespace wobble::cli {

namespace {
// Loopback addresses: only this machine reaches them.
bool loopback(const std::string& host) {
  return host == "127.0.0.1" || host == "localhost" || host == "::1";
}

std::vector<Problem> problems_of(const std::string& dir) {
  if (dir.empty()) return load_catalog();
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) {
    throw InputError(fmt::format("--problems: '{}' is not a folder", dir));
  }
  std::vector<std::filesystem::path> files;
  for (const auto& f : std::filesystem::directory_iterator(dir)) {
    if (f.path().extension() == ".toml") files.push_back(f.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<Problem> out;
  for (const auto& f : files) out.push_back(load_problem(f));
  if (out.empty()) throw InputError(fmt::format("--problems: '{}' has no .toml problem", dir));
  return out;
}
}  // namespace

void setup_serve(CLI::App& app, ServeOptions& opt) {
  app.add_option("--host", opt.host, "Address to listen on (another than 127.0.0.1: the class)")
      ->default_str("127.0.0.1");
  app.add_option("--port", opt.port, "Port (0: any free one)")->default_str("8080");
  app.add_option("--problems", opt.problems, "A folder of .toml problems instead of the catalog");
  app.add_flag("--reveal", opt.reveal, "Show the keys to everyone (self-study)");
}

int run_serve(const ServeOptions& opt) {
  if (opt.port < 0 || opt.port > 65535) {
    throw InputError(fmt::format("--port: {} is not a port (0 to 65535)", opt.port));
  }
  serve::ServeOptions so;
  so.host = opt.host;
  so.port = opt.port;
  so.problems = problems_of(opt.problems);
  so.scenes = load_scenes();
  const std::size_t count = so.problems.size();
  so.reveal = opt.reveal;
  const std::unique_ptr<on_demand::Service> server = on_demand::load().make_server(std::move(so));
  const int port = server->bind();
  const std::string url = fmt::format("http://{}:{}/", opt.host, port);
  fmt::print("wobble serve: {} ({} problems; Ctrl-C stops)\n", url, count);
  if (!loopback(opt.host)) {
    fmt::print("warning: listening on {}: anyone who can reach this machine can use it\n",
               opt.host);
  }
  if (opt.reveal) {
    fmt::print("keys: shown to everyone (--reveal)\n");
  } else {
    fmt::print("instructor: {}?token={} (the page with the keys; the token is {})\n", url,
               server->token(), server->token());
  }
  std::fflush(stdout);
  std::atomic<bool> done{false};
  // Ctrl-C sets a flag (core/work_budget.hpp); a watcher stops the server from a normal thread.
  std::thread watcher([&] {
    while (!done) {
      if (interrupt_requested()) {
        server->stop();
        return;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  server->run();
  done = true;
  watcher.join();
  if (interrupt_requested()) fmt::print("wobble serve: stopped\n");
  return kExitOk;
}

}  // namespace wobble::cli
