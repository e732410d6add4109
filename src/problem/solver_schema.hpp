#pragma once
/// @file
/// What the problem loader needs to know of the solvers to check a file when it loads: each
/// solver's name, the `[motion]` keys it requires (all of them; none means it takes no
/// `[motion]` table) and the quantities it computes. The solvers own this (solvers/registry.hpp
/// builds it from their registry); the problem layer only reads it, so a file that names an
/// unknown solver, motion key or quantity is refused at load, with its line, before any solving.
#include <string>
#include <vector>

namespace wobble {

struct SolverSchema {
  std::string name;
  std::vector<std::string> motion_keys;
  std::vector<std::string> quantities;
};

using SolverSchemas = std::vector<SolverSchema>;

}  // namespace wobble
