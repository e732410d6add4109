#pragma once
/// @file
/// Problem files read and checked against the program's solvers (solvers/registry.hpp): the
/// loader of problem/load.hpp with solver_schemas(), so an unknown solver, motion key or
/// quantity is refused when the file loads, with its line.
#include <filesystem>
#include <string>
#include <vector>

#include "problem/load.hpp"
#include "solvers/registry.hpp"

namespace wobble {

inline Problem load_problem(const std::filesystem::path& file) {
  return load_problem(file, solver_schemas());
}
inline Problem load_problem_text(const std::string& text, const std::filesystem::path& name) {
  return load_problem_text(text, name, solver_schemas());
}
inline Problem find_problem(const std::string& id_or_file) {
  return find_problem(id_or_file, solver_schemas());
}
inline std::vector<Problem> load_catalog() { return load_catalog(solver_schemas()); }

}  // namespace wobble
