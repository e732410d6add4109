#pragma once
/// @file
/// A problem's body, built twice from its file: exactly (GiNaC) and numerically (core), so the
/// solver can answer from the exact form and check it against an independent computation.
#include <string>
#include <vector>

#include "core/inertia.hpp"
#include "problem/problem.hpp"
#include "solvers/exact_answer.hpp"
#include "solvers/key.hpp"
#include "symbolic/inertia_sym.hpp"

namespace wobble {

struct InertiaBody {
  bool has_mass = true;          ///< false for a tensor given directly (no mass, no centre)
  sym::SymMassProperties exact;  ///< entries exact in the parameters
  MassProperties numeric;        ///< from the evaluated inputs through core/
  std::vector<Step> steps;       ///< how the tensor about O is assembled
};

/// @throws InputError naming the field: a malformed expression or undefined symbol; a mass or
///   size that is not > 0 at the values; coinciding point masses; an unknown shape; a tensor
///   that is not symmetric or violates positivity or the triangle inequality.
InertiaBody build_inertia_body(const Problem& problem, const sym::SymbolTable& table,
                               const sym::Values& values);

/// A top needs a moment > 0 about every axis: a rod (all mass on a line) has none about its
/// line, a point none at all, and the equations of motion divide by each moment.
/// `moments` are the principal moments (kg m^2) at the values; `who` says who needs them
/// ("the heavy_top solver", "a scene").
/// @throws InputError naming the file and saying which body it is.
void require_rotating_body(const std::string& file, const Vec3& moments_kgm2,
                           const std::string& who);

/// What a body solver starts from: the problem's symbols, the values as an exact substitution,
/// and the body built both ways. Built in place and never copied: `exact` refers to `table`.
/// @throws as build_inertia_body.
struct BodyContext {
  BodyContext(const Problem& p, const sym::Values& values)
      : problem(p),
        table(p.symbol_table()),
        exact{table, sym::substitution(table, values)},
        body(build_inertia_body(p, table, values)) {}
  BodyContext(const BodyContext&) = delete;
  BodyContext& operator=(const BodyContext&) = delete;

  const Problem& problem;
  sym::SymbolTable table;
  ExactContext exact;
  InertiaBody body;
};

}  // namespace wobble
