#include "check/axes_judge.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <utility>

#include "core/principal_axes.hpp"

namespace wobble::check {

namespace {
// The key's principal directions: one axis, or the plane of a degenerate pair (two columns),
// or all space.
struct Eigenspace {
  std::vector<int> columns;
  // Sine of the angle between unit v and the space.
  double distance(const Mat3& axes, const Vec3& v) const {
    Vec3 projection = Vec3::Zero();
    for (int c : columns) projection += axes.col(c).dot(v) * axes.col(c);
    return (v - projection).norm();
  }
};

std::vector<Eigenspace> eigenspaces(const Vec3& moments) {
  std::vector<Eigenspace> out;
  for (auto& columns : eigenspace_columns(moments)) out.push_back({std::move(columns)});
  return out;
}

std::string shown(const Vec3& v) {
  return fmt::format("({:.4g}, {:.4g}, {:.4g})", v[0], v[1], v[2]);
}

double degrees(double sine) { return std::asin(std::min(1.0, sine)) * 180 / M_PI; }

// One reading of the typed matrix: its rows or its columns as the three vectors.
AxesFinding judge_vectors(const std::array<Vec3, 3>& typed, const Mat3& axes,
                          const std::vector<Eigenspace>& spaces, double tol) {
  AxesFinding out;
  std::array<Vec3, 3> unit;
  std::array<int, 3> space_of{-1, -1, -1};
  for (int i = 0; i < 3; ++i) {
    const double n = typed[static_cast<std::size_t>(i)].norm();
    if (!(n > 0.0) || !std::isfinite(n)) {
      out.problems.push_back(fmt::format("vector {} is zero: no direction, so no axis", i + 1));
      continue;
    }
    unit[static_cast<std::size_t>(i)] = typed[static_cast<std::size_t>(i)] / n;
    out.unit_lengths = out.unit_lengths && std::abs(n - 1.0) <= tol;
    double best = 2.0;
    for (std::size_t s = 0; s < spaces.size(); ++s) {
      const double d = spaces[s].distance(axes, unit[static_cast<std::size_t>(i)]);
      if (d < best) {
        best = d;
        space_of[static_cast<std::size_t>(i)] = static_cast<int>(s);
      }
    }
    if (best > tol) {
      space_of[static_cast<std::size_t>(i)] = -1;
      out.problems.push_back(fmt::format(
          "vector {} {} is not a principal axis: it is {:.3g}° from the nearest one "
          "(I v is not parallel to v)",
          i + 1, shown(typed[static_cast<std::size_t>(i)]), degrees(best)));
    }
  }
  if (!out.problems.empty()) return out;
  // Every direction there as often as its dimension; perpendicular within a space.
  for (std::size_t s = 0; s < spaces.size(); ++s) {
    std::vector<int> members;
    for (int i = 0; i < 3; ++i) {
      if (space_of[static_cast<std::size_t>(i)] == static_cast<int>(s)) members.push_back(i);
    }
    if (spaces[s].columns.size() == 1 && members.size() > 1) {
      out.problems.push_back(fmt::format(
          "vectors {} and {} are the same axis (up to sign): one principal axis is missing",
          members[0] + 1, members[1] + 1));
    }
    for (std::size_t a = 0; a < members.size(); ++a) {
      for (std::size_t b = a + 1; b < members.size(); ++b) {
        const double c = std::abs(unit[static_cast<std::size_t>(members[a])].dot(
            unit[static_cast<std::size_t>(members[b])]));
        if (spaces[s].columns.size() > 1 && c > tol) {
          out.problems.push_back(fmt::format(
              "vectors {} and {} are principal (the moments there are equal) but not "
              "perpendicular: {:.3g}° apart",
              members[a] + 1, members[b] + 1, std::acos(std::min(1.0, c)) * 180 / M_PI));
        }
      }
    }
  }
  out.correct = out.problems.empty();
  return out;
}
}  // namespace

std::vector<std::vector<int>> eigenspace_columns(const Vec3& moments) {
  const double scale = moments.cwiseAbs().maxCoeff();
  switch (degeneracy_of(moments, scale)) {
    case Degeneracy::all:
      return {{0, 1, 2}};
    case Degeneracy::pair12:
      return {{0, 1}, {2}};
    case Degeneracy::pair23:
      return {{0}, {1, 2}};
    case Degeneracy::none:
      break;
  }
  return {{0}, {1}, {2}};
}

AxesFinding judge_axes(const std::vector<double>& typed, const Mat3& key_axes,
                       const Vec3& key_moments, double angle_tolerance, AxesLayout layout) {
  std::array<Vec3, 3> columns, rows;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double x = typed.at(static_cast<std::size_t>(3 * i + j));
      rows[static_cast<std::size_t>(i)][j] = x;
      columns[static_cast<std::size_t>(j)][i] = x;
    }
  }
  const auto spaces = eigenspaces(key_moments);
  // Vectors the student listed or labelled are the axes as written: "as rows" would name the
  // reader's matrix, which the student never wrote.
  constexpr std::string_view kListed = "each of your vectors an axis";
  AxesFinding as_rows = judge_vectors(rows, key_axes, spaces, angle_tolerance);
  as_rows.how = layout == AxesLayout::rows ? kListed : "as rows";
  if (layout == AxesLayout::rows) return as_rows;
  AxesFinding as_columns = judge_vectors(columns, key_axes, spaces, angle_tolerance);
  as_columns.how = layout == AxesLayout::columns ? kListed : "as columns";
  if (layout == AxesLayout::columns || as_columns.correct) return as_columns;
  if (as_rows.correct) return as_rows;
  // Wrong either way: report the reading with fewer problems (columns, as printed, on a tie).
  if (as_rows.problems.size() < as_columns.problems.size()) {
    for (auto& p : as_rows.problems) p = "reading your rows as the axes: " + p;
    return as_rows;
  }
  return as_columns;
}

}  // namespace wobble::check
