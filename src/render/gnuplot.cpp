#include "render/gnuplot.hpp"

#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace wobble {

void draw_svg_with_gnuplot(const std::function<std::string(const std::filesystem::path&)>& script,
                           const std::filesystem::path& out) {
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
  const std::string command = "gnuplot '" + script_file.string() + "' 2>/dev/null";
  const int status = std::system(command.c_str());
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
