#pragma once
/// @file
/// A vector written as a sum along unit vectors, as a student types one (inside the check layer
/// only: answer_reading.cpp): "0.5 i + j - 1.5 k", "(0.5 x̂ + 1.5 ẑ) m", "2.59 î rad/s + 19.3 k̂
/// rad/s", along the body's "ê₁" or the primed "ê₁′" (as basis_vectors_spelled writes them), or
/// along bare x, y, z where the problem has no such symbols. i, j, k (and x, y, z) are unit
/// vectors only where the problem has no symbol of that name; a sum may not mix bases.
#include <cstddef>
#include <string>

#include "symbolic/expression.hpp"

namespace wobble::check::detail {

/// The unit vectors `typed` writes components along, for a message ("0.5 i + j + 1.5 k", "x̂ +
/// 2ŷ" -> "i, k", "x̂, ŷ"), in the order they first stand: a letter i, j, k, x, y or z with a hat
/// (precomposed or combining), the body's and primed ones, and i, j, k alone where the problem
/// has no such symbol. "" if none.
std::string unit_vectors_named(const std::string& typed, const sym::SymbolTable& table);

/// How many bases the unit vectors of unit_vectors_named's list are of (space x̂ ŷ ẑ, body ê₁,
/// primed ê₁′): a sum over more than one is no vector's components in one basis.
std::size_t bases_named(const std::string& vectors);

/// `typed` with each unit vector as a marker "@0", "@1" or "@2" (x, y, z; 3 to 8 the body's and
/// primed axes), spaced apart; bare x, y and z too with `xyz`.
std::string unit_vectors_marked(const std::string& typed, const sym::SymbolTable& table,
                                bool xyz = false);

/// The sum as a vector, "[0.5, 1, -1.5]" with the unit after, or "" if `typed` is no such sum
/// (a unit vector inside a bracket or function, two in one term, one divided by; a unit after
/// some terms but not all, or on a component told twice). A unit after the last term only is
/// the whole sum's; after every term (or before each unit vector), each component's. Bare x, y,
/// z as unit vectors with `xyz`.
std::string unit_vector_sum(const std::string& typed, const sym::SymbolTable& table,
                            bool xyz = false);

}  // namespace wobble::check::detail
