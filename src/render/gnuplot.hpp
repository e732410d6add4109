#pragma once
/// @file
/// Drawing a figure with gnuplot, atomically: the script writes a temporary file in the
/// target's folder (created exclusively, so a planted link is never written through), which is
/// renamed over the target only if gnuplot succeeded; a failed run leaves no partial file and an
/// old file intact.
#include <filesystem>
#include <functional>
#include <string>

namespace wobble {

/// `script(tmp)` returns a gnuplot script whose output is tmp (same extension as `out`).
/// @throws std::runtime_error naming `out` if the folder is not writable or gnuplot fails.
void draw_with_gnuplot(const std::function<std::string(const std::filesystem::path&)>& script,
                       const std::filesystem::path& out);

/// The gnuplot terminal line for a figure file by its extension: .svg (svg), .png (pngcairo),
/// .pdf (pdfcairo), at about `width` x `height` pixels.
/// @throws std::invalid_argument for another extension.
std::string gnuplot_terminal(const std::filesystem::path& file, int width, int height);

/// Text quoted for a gnuplot double-quoted string (backslashes and quotes escaped).
std::string gnuplot_quote(const std::string& text);

}  // namespace wobble
