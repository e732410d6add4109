#pragma once
/// @file
/// Reading problem files (TOML; schema in README, "Problem files").
///
/// Every error is an InputError whose message starts "FILE:LINE: FIELD:" (or "FILE: FIELD:"
/// where no line is known) and says what was expected and what was found: a malformed file, a
/// missing or mistyped field, an unknown key (a typo must not be ignored silently), a bad range.
/// The solver, its `[motion]` keys and each answer's quantity are checked against `schemas`
/// (problem/solver_schema.hpp; solvers/registry.hpp has the program's). Expressions are checked
/// later, by the solver, against the parameters.
#include <filesystem>
#include <string>
#include <vector>

#include "problem/problem.hpp"
#include "problem/solver_schema.hpp"

namespace wobble {

/// @throws InputError as described above, or if the file cannot be read.
Problem load_problem(const std::filesystem::path& file, const SolverSchemas& schemas);
/// The same from text already read (`name` stands for the file in messages): for the fuzzers.
Problem load_problem_text(const std::string& text, const std::filesystem::path& name,
                          const SolverSchemas& schemas);

/// The folder of the problem catalog (io/data_dir.hpp says where).
std::filesystem::path problems_dir();

/// Resolves "ID" (a file ID.toml in problems_dir()) or a path to a .toml file, and loads it.
/// @throws InputError for an unknown id (listing the known ones) or an unreadable file.
Problem find_problem(const std::string& id_or_file, const SolverSchemas& schemas);

/// Every problem of the catalog, sorted by id; each file's id must equal its file name.
/// @throws InputError for the first bad file.
std::vector<Problem> load_catalog(const SolverSchemas& schemas);

}  // namespace wobble
