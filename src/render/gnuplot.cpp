#include "render/gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "render/atomic_write.hpp"

extern char** environ;

namespace wobble {

void draw_svg_with_gnuplot(const std::function<std::string(const std::filesystem::path&)>& script,
                           const std::filesystem::path& out) {
  require_regular_or_absent(out);
  const std::filesystem::path dir = out.has_parent_path() ? out.parent_path() : ".";
  const std::string stem = "." + out.filename().string() + "." + std::to_string(::getpid());
  const auto svg_tmp = dir / (stem + ".svg.tmp"), script_file = dir / (stem + ".gp");
  auto cleanup = [&] {
    std::error_code ec;
    std::filesystem::remove(svg_tmp, ec);
    std::filesystem::remove(script_file, ec);
  };
  {
    std::ofstream f(script_file);
    f << script(svg_tmp);
    if (!f) {
      cleanup();
      throw std::runtime_error(out.string() + ": cannot write in " + dir.string());
    }
  }
  // gnuplot SCRIPT, started without a shell: a file name is an argument, never a command line
  // (a quote in it cannot break out), and gnuplot's stderr goes to /dev/null.
  int status = -1;
  {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    std::string program = "gnuplot", script_arg = script_file.string();
    char* argv[] = {program.data(), script_arg.data(), nullptr};
    pid_t pid = 0;
    if (posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ) == 0) {
      int wstatus = 0;
      while (::waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) {
      }
      status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1;
    }
    posix_spawn_file_actions_destroy(&actions);
  }
  std::error_code ec;
  if (status != 0 || !std::filesystem::exists(svg_tmp, ec) ||
      std::filesystem::file_size(svg_tmp, ec) == 0) {
    cleanup();
    throw std::runtime_error(
        out.string() +
        ": gnuplot failed to draw the figure (is gnuplot installed? scripts/setup "
        "installs it)");
  }
  std::filesystem::rename(svg_tmp, out, ec);
  if (ec) {
    cleanup();
    throw std::runtime_error(out.string() + ": cannot replace: " + ec.message());
  }
  cleanup();
}

std::string gnuplot_quote(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\\' || c == '"') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace wobble
