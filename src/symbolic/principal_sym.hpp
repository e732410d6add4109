#pragma once
/// @file
/// Principal moments and axes in closed form, where the structure allows it.
///
/// Three routes, tried in order:
/// - diagonal: every product of inertia is identically zero; the moments are the diagonal;
/// - block: exactly one product of inertia I_pq is nonzero; I_kk is a moment, and the p-q block
///   gives lambda = (I_pp + I_qq)/2 +- sqrt(((I_pp - I_qq)/2)^2 + I_pq^2), with axes rotated by
///   theta = atan2(2 I_pq, I_pp - I_qq)/2 about e_k (a planar body, such as a molecule, is one);
/// - factored: the characteristic polynomial det(lambda 1 - I) factors over the rationals into
///   linear and quadratic factors; each is solved, and each simple root's axis is the normalised
///   cross product of two rows of I - lambda 1.
/// Otherwise there is no closed form here and the moments are numeric only (`Method::numeric`).
/// The moments come unordered: their order depends on the parameter values (the caller sorts).
#include <ginac/ginac.h>

#include <optional>
#include <string>
#include <vector>

#include "symbolic/inertia_sym.hpp"

namespace wobble::sym {

struct SymPrincipal {
  enum class Method { diagonal, block, factored, numeric };
  Method method = Method::numeric;
  /// The tensor's entries were too large for the closed-form routes within the time budget
  /// (kMaxClosedFormNodes): the characteristic polynomial was not formed.
  bool too_large = false;
  int tensor_nodes = 0;  ///< the size measured
  /// det(lambda 1 - I), factored where GiNaC could (for the steps).
  GiNaC::ex characteristic;
  /// Three closed-form moments (unordered, repeated roots repeated) unless method is numeric.
  std::vector<GiNaC::ex> moments;
  /// Block route: the decoupled index k, the coupled pair (p, q) and the angle theta.
  int block_k = -1, block_p = -1, block_q = -1;
  GiNaC::ex block_angle;
};

/// The symbolic budget: a tensor whose six entries have more expression nodes than this goes the
/// numeric route at once. Expanding and factoring det(lambda 1 - I) grows fast with the entries
/// (a file of 40 masses at sqrt(k) coordinates took minutes); the catalog's largest tensor has
/// 155 nodes (a test keeps it under half the budget); 20 masses at sqrt(k) factor in 0.7 s.
inline constexpr int kMaxClosedFormNodes = 400;

/// Expression nodes in the six independent entries of I, counted up to kMaxClosedFormNodes + 1.
int tensor_nodes(const GiNaC::matrix& I);

/// @param lambda the symbol to write the characteristic polynomial in
SymPrincipal principal_closed_form(const GiNaC::matrix& I, const GiNaC::symbol& lambda);

/// The unit axis of the moment moments[index] of a closed form, if one can be written: for a
/// root repeated in the closed form there is none (a degenerate pair has no single axis).
/// `at` (parameter values) chooses, for the factored route, the pair of rows whose cross product
/// is largest there, so the expression is well conditioned at those values.
std::optional<SymVec3> principal_axis_closed_form(const GiNaC::matrix& I, const SymPrincipal& p,
                                                  std::size_t index, const GiNaC::lst& at);

}  // namespace wobble::sym
