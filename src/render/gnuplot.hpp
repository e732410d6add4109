#pragma once
/// @file
/// Drawing an SVG with gnuplot, atomically: the script writes a temporary SVG in the target's
/// folder, which is renamed over the target only if gnuplot succeeded; a failed run leaves no
/// partial file and an old file intact.
#include <filesystem>
#include <functional>
#include <string>

namespace wobble {

/// `script(svg_tmp)` returns a gnuplot script whose output is svg_tmp.
/// @throws std::runtime_error naming `out` if the folder is not writable or gnuplot fails.
void draw_svg_with_gnuplot(const std::function<std::string(const std::filesystem::path&)>& script,
                           const std::filesystem::path& out);

/// Text quoted for a gnuplot double-quoted string (backslashes and quotes escaped).
std::string gnuplot_quote(const std::string& text);

}  // namespace wobble
