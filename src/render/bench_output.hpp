#pragma once
/// @file
/// The bench's results: tables (text, Markdown), JSON, CSV, and the work-precision diagram.
#include <filesystem>
#include <string>
#include <vector>

#include "bench/report.hpp"

namespace wobble {

using BenchReport = bench::Report;

/// format: text, markdown, json or csv.
std::string render_bench(const BenchReport& report, const std::string& format);

/// Error against time, log-log, one panel per problem, one curve per method (peers dashed).
/// @throws std::runtime_error naming the file if gnuplot fails.
void write_bench_plot(const BenchReport& report, const std::filesystem::path& out);

}  // namespace wobble
