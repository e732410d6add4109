#include "render/gnuplot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <cstdlib>
#include <stdexcept>

#include <fmt/format.h>

#include "io/atomic_write.hpp"

extern char** environ;

namespace wobble {

namespace {
// A new file in `dir` named ".NAME.XXXXXX<suffix>", created exclusively (O_EXCL, mode 0600):
// a planted file or link of that name is never written through.
// `content` is written through the descriptor mkstemps returned, never by reopening the name.
std::filesystem::path exclusive_temp(const std::filesystem::path& dir, const std::string& name,
                                     const std::string& suffix, const std::string& content = "") {
  std::string tmpl = (dir / ("." + name + ".XXXXXX" + suffix)).string();
  const int fd = ::mkstemps(tmpl.data(), static_cast<int>(suffix.size()));
  if (fd < 0) {
    throw std::runtime_error(dir.string() + ": cannot create a temporary file: " +
                             std::strerror(errno));
  }
  if (!write_fully(fd, content)) {
    const std::string why = std::strerror(errno);
    ::close(fd);
    ::unlink(tmpl.c_str());
    throw std::runtime_error(dir.string() + ": cannot write a temporary file: " + why);
  }
  ::close(fd);
  return tmpl;
}
}  // namespace

void draw_with_gnuplot(const std::function<std::string(const std::filesystem::path&)>& script,
                       const std::filesystem::path& out) {
  require_regular_or_absent(out);
  const std::filesystem::path dir = out.has_parent_path() ? out.parent_path() : ".";
  const std::string name = out.filename().string();
  const auto figure_tmp = exclusive_temp(dir, name, out.extension().string());
  std::filesystem::path script_file;
  try {
    script_file = exclusive_temp(dir, name, ".gp", script(figure_tmp));
  } catch (...) {
    std::error_code ec;
    std::filesystem::remove(figure_tmp, ec);
    throw;
  }
  auto cleanup = [&] {
    std::error_code ec;
    std::filesystem::remove(figure_tmp, ec);
    std::filesystem::remove(script_file, ec);
  };
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
  if (status != 0 || !std::filesystem::exists(figure_tmp, ec) ||
      std::filesystem::file_size(figure_tmp, ec) == 0) {
    cleanup();
    throw std::runtime_error(
        out.string() +
        ": gnuplot failed to draw the figure (is gnuplot installed? scripts/setup "
        "installs it)");
  }
  // Readable as any other output (the temporary was created 0600).
  std::filesystem::permissions(figure_tmp, std::filesystem::perms(0644), ec);
  std::filesystem::rename(figure_tmp, out, ec);
  if (ec) {
    cleanup();
    throw std::runtime_error(out.string() + ": cannot replace: " + ec.message());
  }
  cleanup();
}

std::string gnuplot_terminal(const std::filesystem::path& file, int width, int height) {
  const std::string ext = file.extension().string();
  if (ext == ".svg") {
    return fmt::format("set terminal svg size {},{} dynamic font \"Helvetica,15\" background "
                       "rgb \"white\"\n",
                       width, height);
  }
  if (ext == ".png") {
    return fmt::format("set terminal pngcairo size {},{} font \"Helvetica,13\" background rgb "
                       "\"white\"\n",
                       width, height);
  }
  if (ext == ".pdf") {
    // pdfcairo sizes in inches: 180 pixels to the inch makes a 760-pixel figure about 4.2 in,
    // the width a LaTeX key includes it at, so its 8 pt text prints at 8 pt.
    return fmt::format("set terminal pdfcairo size {:.2f}in,{:.2f}in font \"Helvetica,8\"\n",
                       width / 180.0, height / 180.0);
  }
  throw std::invalid_argument(file.string() + ": a figure is .svg, .png or .pdf");
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
