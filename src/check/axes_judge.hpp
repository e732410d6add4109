#pragma once
/// @file
/// Judging principal axes by what they mean, not by their entries.
///
/// A student lists three axis vectors: as the rows or the columns of a matrix, in any order,
/// each up to sign and length. They are right when each is an eigenvector of the key's tensor
/// (its direction within `angle_tolerance`, the sine of the angle, of the key's axis or, for a
/// degenerate pair, of the pair's plane), every principal direction is there once, and the three
/// are perpendicular (|cos| within the same tolerance). Degeneracy is decided by core's rule
/// (principal_axes.hpp, degeneracy_of) on the key's moments: the key's own decision. What is
/// wrong is said in words: which vector is no axis, which axis is missing, which two are not
/// perpendicular.
#include <string>
#include <vector>

#include "core/inertia.hpp"

namespace wobble::check {

struct AxesFinding {
  bool correct = false;
  std::string how;  ///< "as columns", "as rows" or "each of your vectors an axis", when correct
  bool unit_lengths = true;           ///< each vector of unit length, within the tolerance
  std::vector<std::string> problems;  ///< one line each, when wrong
};

/// The key's principal directions as groups of its axis columns (0-based): one column for a
/// single axis, two for a degenerate pair's plane, three when all moments are equal. Decided by
/// core's rule on the ascending moments.
std::vector<std::vector<int>> eigenspace_columns(const Vec3& key_moments);

/// Which of the student's matrix holds the axes: a matrix as the key prints one may be read
/// either way; vectors listed one by one ("(1, 0, 1)/√2, (1, 0, −1)/√2, (0, 1, 0)") are its rows,
/// and vectors labelled e1 = (..), .. its columns. A listed vector is never read across: the
/// columns of wrong rows can be right axes.
enum class AxesLayout { rows_or_columns, rows, columns };

/// `typed` is the student's 3x3 matrix, row-major; `key_axes` has the key's axes as columns,
/// `key_moments` ascending.
AxesFinding judge_axes(const std::vector<double>& typed, const Mat3& key_axes,
                       const Vec3& key_moments, double angle_tolerance,
                       AxesLayout layout = AxesLayout::rows_or_columns);

}  // namespace wobble::check
