#pragma once
/// @file
/// The sketch of a torque-free symmetric top at t = 0 (parts c and d), drawn by gnuplot as SVG:
/// e3, w and L as labelled arrows, the body cone (about e3, through w) and the space cone (about
/// L, through w) as wireframes, and the sense of each precession as an arrow on its cone's rim.
/// Lengths are for legibility (w 1, L 1.2, e3 1.35); directions and angles are exact.
#include <filesystem>
#include <string>

#include "solvers/sketch.hpp"

namespace wobble {

/// The gnuplot script that draws `sketch` into `svg_path`.
std::string top_sketch_script(const TopSketch& sketch, const std::filesystem::path& svg_path);

/// Runs gnuplot and puts the SVG at `out` atomically (temporary file in the same folder, then
/// rename), so a failed run leaves no partial file and an old file intact.
/// @throws std::runtime_error naming the file if gnuplot is missing or fails.
void write_top_sketch(const TopSketch& sketch, const std::filesystem::path& out);

}  // namespace wobble
