#include "simulate/invariants.hpp"

#include <algorithm>
#include <cmath>

namespace wobble {

double momentum_scale(const SceneSetup& s) {
  double scale = s.m0_P.norm();
  const RigidBodyModel& m = s.model;
  if (m.gravity) {
    scale = std::max(scale, m.I_P.maxCoeff() * std::sqrt(m.mass_kg * m.g_S.norm() * m.d_P_m.norm() /
                                                         m.I_P.minCoeff()));
  }
  if (m.torque) scale = std::max(scale, std::sqrt(m.torque_Nm.norm() * m.I_P.maxCoeff()));
  return scale > 0.0 ? scale : 1.0;
}

namespace {
// The symmetry axis (index in P) when the body is symmetric about the line pivot -> centre of
// mass, so that p_psi is conserved; -1 otherwise.
int symmetry_axis(const SceneSetup& s) {
  if (!s.symmetric) return -1;
  const Vec3& I = s.model.I_P;
  const int j = I[0] == I[1] ? 2 : (I[1] == I[2] ? 0 : -1);
  if (j < 0) return -1;
  const Vec3 d = s.model.d_P_m;
  const double off = std::hypot(d[(j + 1) % 3], d[(j + 2) % 3]);
  // On the axis up to the rounding of the offset (a few eps of its length).
  constexpr double kOnAxis = 1e-12;
  return off <= kOnAxis * std::max(d.norm(), 1e-300) ? j : -1;
}
}  // namespace

std::vector<ConservedQuantity> conserved_quantities(const SceneSetup& s) {
  const RigidBodyModel& model = s.model;
  const double L = momentum_scale(s);
  const auto energy = [&model](const SimState& st, double) {
    return Vec3(model.kinetic(st.m_P) + model.potential(st.q_PtoS), 0, 0);
  };
  const double E0 = energy({s.m0_P, s.q0_PtoS}, 0)[0];
  std::vector<ConservedQuantity> out;
  if (model.torque_free()) {
    out.push_back({"rotational_energy", "J", energy, std::abs(E0)});
    out.push_back({"L_norm", "kg m^2/s",
                   [](const SimState& st, double) { return Vec3(st.m_P.norm(), 0, 0); }, L});
    out.push_back({"L_space", "kg m^2/s",
                   [](const SimState& st, double) { return Vec3(st.q_PtoS * st.m_P); }, L});
  } else if (model.gravity && !model.torque) {
    const double scale = std::max({std::abs(E0), model.kinetic(s.m0_P),
                                   model.mass_kg * model.g_S.norm() * model.d_P_m.norm()});
    out.push_back({"total_energy", "J", energy, scale});
    out.push_back(
        {"p_phi", "kg m^2/s",
         [](const SimState& st, double) { return Vec3(Vec3(st.q_PtoS * st.m_P).z(), 0, 0); }, L});
    if (const int j = symmetry_axis(s); j >= 0) {
      out.push_back({"p_psi", "kg m^2/s",
                     [j](const SimState& st, double) { return Vec3(st.m_P[j], 0, 0); }, L});
    }
  } else if (model.torque && model.torque_in_space && !model.gravity) {
    const Vec3 tau = model.torque_Nm;
    out.push_back(
        {"L_space_minus_tau_t", "kg m^2/s",
         [tau](const SimState& st, double t) { return Vec3(st.q_PtoS * st.m_P - tau * t); }, L});
  }
  return out;
}

}  // namespace wobble
