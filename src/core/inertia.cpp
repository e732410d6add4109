#include "core/inertia.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace wobble {

namespace {
void require_finite_mass(double mass_kg, std::size_t index) {
  if (!std::isfinite(mass_kg) || mass_kg < 0.0) {
    throw std::invalid_argument("point mass " + std::to_string(index) +
                                ": mass must be finite and >= 0, got " + std::to_string(mass_kg));
  }
}
}  // namespace

Mat3 parallel_axis_term(double mass_kg, const Vec3& d_m) {
  return mass_kg * (d_m.squaredNorm() * Mat3::Identity() - d_m * d_m.transpose());
}

Mat3 inertia_of_point_masses(const std::vector<PointMass>& masses) {
  Mat3 I_O = Mat3::Zero();
  for (std::size_t i = 0; i < masses.size(); ++i) {
    require_finite_mass(masses[i].mass_kg, i);
    if (!masses[i].r_O_m.allFinite()) {
      throw std::invalid_argument("point mass " + std::to_string(i) + ": position not finite");
    }
    I_O += parallel_axis_term(masses[i].mass_kg, masses[i].r_O_m);
  }
  return I_O;
}

MassProperties mass_properties(const std::vector<PointMass>& masses) {
  MassProperties props;
  props.I_O = inertia_of_point_masses(masses);
  Vec3 first_moment = Vec3::Zero();
  for (const auto& p : masses) {
    props.mass_kg += p.mass_kg;
    first_moment += p.mass_kg * p.r_O_m;
  }
  if (!(props.mass_kg > 0.0)) throw std::invalid_argument("total mass must be > 0");
  props.r_cm_m = first_moment / props.mass_kg;
  return props;
}

Mat3 shift_from_cm(const Mat3& I_cm, double mass_kg, const Vec3& r_P_from_cm) {
  return I_cm + parallel_axis_term(mass_kg, r_P_from_cm);
}

Mat3 shift_to_cm(const Mat3& I_P, double mass_kg, const Vec3& r_P_from_cm) {
  return I_P - parallel_axis_term(mass_kg, r_P_from_cm);
}

MassProperties combine(const std::vector<MassProperties>& parts) {
  MassProperties total;
  Vec3 first_moment = Vec3::Zero();
  for (const auto& p : parts) {
    total.mass_kg += p.mass_kg;
    first_moment += p.mass_kg * p.r_cm_m;
    total.I_O += p.I_O;
  }
  if (!(total.mass_kg > 0.0)) throw std::invalid_argument("total mass must be > 0");
  total.r_cm_m = first_moment / total.mass_kg;
  return total;
}

}  // namespace wobble
