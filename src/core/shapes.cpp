#include "core/shapes.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

#include "core/characters.hpp"

namespace wobble {

namespace {
// The principal moments about the centre of mass per unit mass (m^2), from the sizes in order.
using MomentsPerMass = Vec3 (*)(const std::vector<double>& s);

double sq(double x) { return x * x; }

struct ShapeInfo {
  ShapeKind kind;
  std::string_view name;
  std::vector<std::string> sizes;
  MomentsPerMass moments;  ///< the closed form (symbolic/shape_integrals integrates it apart)
};

// One entry per shape: its name, its sizes and its tensor about the centre of mass.
const std::array<ShapeInfo, 9>& shape_table() {
  static const std::array<ShapeInfo, 9> table{{
      {ShapeKind::box, "box", {"a", "b", "c"},
       [](const std::vector<double>& s) -> Vec3 {
         return Vec3{sq(s[1]) + sq(s[2]), sq(s[0]) + sq(s[2]), sq(s[0]) + sq(s[1])} / 12.0;
       }},
      {ShapeKind::plate, "plate", {"a", "b"},
       [](const std::vector<double>& s) -> Vec3 {
         return Vec3{sq(s[1]), sq(s[0]), sq(s[0]) + sq(s[1])} / 12.0;
       }},
      {ShapeKind::disc, "disc", {"R"},
       [](const std::vector<double>& s) -> Vec3 {
         return {sq(s[0]) / 4.0, sq(s[0]) / 4.0, sq(s[0]) / 2.0};
       }},
      {ShapeKind::cylinder, "cylinder", {"R", "h"},
       [](const std::vector<double>& s) -> Vec3 {
         const double side = sq(s[0]) / 4.0 + sq(s[1]) / 12.0;
         return {side, side, sq(s[0]) / 2.0};
       }},
      {ShapeKind::sphere, "sphere", {"R"},
       [](const std::vector<double>& s) -> Vec3 { return Vec3::Constant(0.4 * sq(s[0])); }},
      {ShapeKind::rod, "rod", {"L"},
       [](const std::vector<double>& s) -> Vec3 { return {sq(s[0]) / 12.0, sq(s[0]) / 12.0, 0.0}; }},
      {ShapeKind::cone, "cone", {"R", "h"},
       [](const std::vector<double>& s) -> Vec3 {
         const double side = 3.0 / 20.0 * sq(s[0]) + 3.0 / 80.0 * sq(s[1]);
         return {side, side, 3.0 / 10.0 * sq(s[0])};
       }},
      {ShapeKind::ring, "ring", {"R"},
       [](const std::vector<double>& s) -> Vec3 {
         return {sq(s[0]) / 2.0, sq(s[0]) / 2.0, sq(s[0])};
       }},
      {ShapeKind::shell, "shell", {"R"},
       [](const std::vector<double>& s) -> Vec3 { return Vec3::Constant(2.0 / 3.0 * sq(s[0])); }},
  }};
  return table;
}

const ShapeInfo& info(ShapeKind kind) {
  for (const auto& s : shape_table()) {
    if (s.kind == kind) return s;
  }
  throw std::logic_error("shape kind missing from the shape table");
}
}  // namespace

ShapeKind shape_kind_from_name(std::string_view name) {
  std::string known;
  const std::string lower = ascii_lower(std::string(name));
  std::string meant;
  for (const auto& s : shape_table()) {
    if (s.name == name) return s.kind;
    known += (known.empty() ? "" : ", ") + std::string(s.name);
    if (s.name == lower) meant = "; write " + std::string(s.name);  // "Box"
  }
  // The names people use for shapes the table has by another.
  if (lower == "disk") meant = "; write disc";
  if (lower == "cube") meant = "; a cube is a box of three equal sizes";
  if (lower == "cuboid" || lower == "brick" || lower == "block") meant = "; write box";
  if (lower == "ball") meant = "; a solid ball is a sphere, a hollow one a shell";
  if (lower == "hoop") meant = "; write ring";
  throw std::invalid_argument("unknown shape '" + std::string(name) + "' (known: " + known + ")" +
                              meant);
}

std::vector<ShapeKind> shape_kinds() {
  std::vector<ShapeKind> out;
  for (const auto& s : shape_table()) out.push_back(s.kind);
  return out;
}

std::string_view shape_kind_name(ShapeKind kind) {
  return info(kind).name;
}

const std::vector<std::string>& shape_size_names(ShapeKind kind) {
  return info(kind).sizes;
}

Mat3 shape_inertia_about_cm(ShapeKind kind, double mass_kg, const std::vector<double>& sizes_m) {
  const auto& names = shape_size_names(kind);
  if (sizes_m.size() != names.size()) {
    throw std::invalid_argument(std::string(shape_kind_name(kind)) + " takes " +
                                std::to_string(names.size()) + " sizes");
  }
  if (!std::isfinite(mass_kg) || !(mass_kg > 0.0)) {
    throw std::invalid_argument("shape mass must be finite and > 0");
  }
  for (std::size_t i = 0; i < sizes_m.size(); ++i) {
    if (!std::isfinite(sizes_m[i]) || !(sizes_m[i] > 0.0)) {
      throw std::invalid_argument(std::string(shape_kind_name(kind)) + " size " + names[i] +
                                  " must be finite and > 0");
    }
  }
  const Vec3 diag = info(kind).moments(sizes_m);
  return mass_kg * diag.asDiagonal().toDenseMatrix();
}

}  // namespace wobble
