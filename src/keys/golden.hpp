#pragma once
/// @file
/// Golden keys: every problem's key at its default values, stored in solutions/ as ID.json and
/// ID.md, written only by `wobble keys --update` and checked by `wobble keys --check`.
///
/// Comparison: texts (symbolic forms, LaTeX, steps, notes, units, names) must be equal; numbers
/// may differ by kKeyRelTol times the scale of their answer (its largest |entry|), so that a
/// different compiler's last-bit rounding in a numeric-only answer is not a change, while any
/// change a key prints (10 significant digits) is. The Markdown must be equal byte for byte.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "problem/problem.hpp"

namespace wobble {

inline constexpr double kKeyRelTol = 1e-12;

/// The folder of the golden keys (io/data_dir.hpp says where).
std::filesystem::path solutions_dir();

/// The differences between an expected and an actual key document, one line each, with the
/// JSON path ("parts[1].answers[0].value[2]: 7 -> 7.5").
std::vector<std::string> compare_keys(const nlohmann::ordered_json& expected,
                                      const nlohmann::ordered_json& actual);

/// Recomputes each problem's key and compares with `dir`; also reports missing files and files
/// for problems that no longer exist. Returns the differences, each prefixed with the file.
std::vector<std::string> check_keys(const std::vector<Problem>& problems,
                                    const std::filesystem::path& dir);

/// Rewrites ID.json and ID.md for each problem (atomically); returns the files that changed.
std::vector<std::string> update_keys(const std::vector<Problem>& problems,
                                     const std::filesystem::path& dir);

}  // namespace wobble
