#include "core/shapes.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

namespace wobble {

namespace {
struct ShapeInfo {
  ShapeKind kind;
  std::string_view name;
  std::vector<std::string> sizes;
};

const std::array<ShapeInfo, 6>& shape_table() {
  static const std::array<ShapeInfo, 6> table{{
      {ShapeKind::box, "box", {"a", "b", "c"}},
      {ShapeKind::plate, "plate", {"a", "b"}},
      {ShapeKind::disc, "disc", {"R"}},
      {ShapeKind::cylinder, "cylinder", {"R", "h"}},
      {ShapeKind::sphere, "sphere", {"R"}},
      {ShapeKind::rod, "rod", {"L"}},
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
  for (const auto& s : shape_table()) {
    if (s.name == name) return s.kind;
    known += (known.empty() ? "" : ", ") + std::string(s.name);
  }
  throw std::invalid_argument("unknown shape '" + std::string(name) + "' (known: " + known + ")");
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
  const auto sq = [&](std::size_t i) { return sizes_m[i] * sizes_m[i]; };
  Vec3 diag = Vec3::Zero();
  switch (kind) {
    case ShapeKind::box:
      diag = {sq(1) + sq(2), sq(0) + sq(2), sq(0) + sq(1)};
      diag /= 12.0;
      break;
    case ShapeKind::plate:
      diag = {sq(1), sq(0), sq(0) + sq(1)};
      diag /= 12.0;
      break;
    case ShapeKind::disc:
      diag = {sq(0) / 4.0, sq(0) / 4.0, sq(0) / 2.0};
      break;
    case ShapeKind::cylinder:
      diag = {sq(0) / 4.0 + sq(1) / 12.0, sq(0) / 4.0 + sq(1) / 12.0, sq(0) / 2.0};
      break;
    case ShapeKind::sphere:
      diag = Vec3::Constant(0.4 * sq(0));
      break;
    case ShapeKind::rod:
      diag = {sq(0) / 12.0, sq(0) / 12.0, 0.0};
      break;
  }
  return mass_kg * diag.asDiagonal().toDenseMatrix();
}

}  // namespace wobble
