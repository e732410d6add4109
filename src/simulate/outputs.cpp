#include "simulate/outputs.hpp"

#include "core/euler_angles.hpp"

namespace wobble {

Columns output_columns(const SceneSetup& s, const std::vector<ConservedQuantity>& conserved) {
  Columns c;
  c.names.push_back("t");
  c.units.push_back("s");
  const auto add3 = [&c](const std::string& name, const std::string& unit,
                         const std::array<const char*, 3>& suffixes = {"x", "y", "z"}) {
    for (const char* suffix : suffixes) {
      c.names.push_back(name + "_" + suffix);
      c.units.push_back(unit);
    }
  };
  for (const auto& o : s.outputs) {
    if (o == "omega_body" || o == "omega_space") {
      add3(o, "rad/s");
    } else if (o == "L_body" || o == "L_space") {
      add3(o, "kg m^2/s");
    } else if (o == "e1_space" || o == "e2_space" || o == "e3_space") {
      add3(o, "1");
    } else if (o == "euler_zyz" || o == "euler_zxz") {
      add3(o, "rad", {"phi", "theta", "psi"});
    } else if (o == "com_position") {
      add3(o, "m");
    } else if (o == "invariant_errors") {
      for (const auto& q : conserved) {
        c.names.push_back("err_" + q.name);
        c.units.push_back(q.unit);
      }
    } else {  // kinetic_energy, total_energy
      c.names.push_back(o);
      c.units.push_back("J");
    }
  }
  return c;
}

std::vector<double> output_row(const SceneSetup& s, const SimState& st, double t,
                               const std::vector<double>& errors) {
  const RigidBodyModel& model = s.model;
  const Mat3& A = s.axes_B;  // P -> B
  const Mat3 R_PtoS = st.q_PtoS.toRotationMatrix();
  const Vec3 w_P = model.omega_P(st.m_P);
  // Free flight in closed form: no torque about the centre of mass, so no coupling.
  const Vec3 x_S = s.x0_S + s.v0_S * t + 0.5 * s.g_S * t * t, v_S = s.v0_S + s.g_S * t;
  std::vector<double> row{t};
  const auto put = [&row](const Vec3& v) { row.insert(row.end(), {v.x(), v.y(), v.z()}); };
  for (const auto& o : s.outputs) {
    if (o == "omega_body") {
      put(A * w_P);
    } else if (o == "omega_space") {
      put(R_PtoS * w_P);
    } else if (o == "L_body") {
      put(A * st.m_P);
    } else if (o == "L_space") {
      put(R_PtoS * st.m_P);
    } else if (o == "e1_space" || o == "e2_space" || o == "e3_space") {
      put(R_PtoS.col(o[1] - '1'));
    } else if (o == "euler_zyz" || o == "euler_zxz") {
      put(euler_from_rotation(R_PtoS * A.transpose(),
                              o == "euler_zyz" ? EulerConvention::zyz : EulerConvention::zxz));
    } else if (o == "kinetic_energy" || o == "total_energy") {
      double e = model.kinetic(st.m_P);
      if (s.free_flight) e += 0.5 * s.mass_kg * v_S.squaredNorm();
      if (o == "total_energy") {
        e += model.potential(st.q_PtoS);
        if (s.free_flight) e -= s.mass_kg * s.g_S.dot(x_S);
      }
      row.push_back(e);
    } else if (o == "com_position") {
      put(s.free_flight ? x_S : model.gravity ? Vec3(R_PtoS * model.d_P_m) : Vec3::Zero());
    } else if (o == "invariant_errors") {
      row.insert(row.end(), errors.begin(), errors.end());
    }
  }
  return row;
}

}  // namespace wobble
