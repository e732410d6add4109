#pragma once
/// @file
/// An answer's shape against the key's (inside the check layer only: judge.cpp): a number, a
/// vector or a matrix of the key's size. Two forms a student writes are taken as the key's
/// (a planar body's (x, y), a diagonal tensor for its moments); any other shape is refused
/// with what was likely meant.
#include <string>

#include "check/answer_reading.hpp"
#include "check/judge.hpp"
#include "symbolic/value_text.hpp"

namespace wobble::check::detail {

/// "(0.0131, 0.1529) m" for the planar molecule's centre of mass: where a 3-vector's last entry
/// is zero in the key's exact form (a body in the plane z = 0) and `v` is a 2-vector, `v` becomes
/// (x, y, 0); whether it did. Not where another entry is the zero one ("(0, -0.225)" for the
/// cone's centre on its axis reads two ways), nor for entries the question names.
bool in_plane_of_two(const Answer& a, sym::ValueText& v);

/// Where the principal moments are asked for and `v` is a 3x3 matrix with nothing off its
/// diagonal (the tensor in its principal axes, "diag(..)"), `v` becomes its diagonal; whether it
/// did.
bool moments_on_diagonal(const Answer& a, sym::ValueText& v);

/// @throws InputError where `p`, read from `typed`, is not of `a`'s shape: "I wants a 3x3
/// matrix [[..], ..], not a 3-vector [..]", with what was likely meant (decimal commas that split
/// entries, a tensor's diagonal for its moments, or three entries for a diagonal tensor).
void check_shape(const Answer& a, const ReadAnswer& p, const std::string& typed);

}  // namespace wobble::check::detail
