#include "core/free_body.hpp"

#include <cmath>
#include <stdexcept>

namespace wobble {

void FreeBody::validate() const {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(I_kgm2[i]) || !(I_kgm2[i] > 0.0)) {
      throw std::invalid_argument("free body: moments must be finite and > 0");
    }
  }
}

namespace {
// The exact flow of T_i = m_i^2 / (2 I_i) for time h.
void subflow(const FreeBody& body, FreeBodyState& s, int i, double h) {
  const double theta = s.m_B[i] / body.I_kgm2[i] * h;  // m_i is constant along this flow
  const Eigen::AngleAxisd turn(theta, Vec3::Unit(i));
  s.m_B = turn.inverse() * s.m_B;    // dm/dt = m x (w_i e_i)
  s.q_BtoS = s.q_BtoS * Quat(turn);  // the body turns by +theta about e_i
}

void strang(const FreeBody& body, FreeBodyState& s, double h, std::int64_t& count) {
  subflow(body, s, 0, h / 2);
  subflow(body, s, 1, h / 2);
  subflow(body, s, 2, h);
  subflow(body, s, 1, h / 2);
  subflow(body, s, 0, h / 2);
  count += 5;
}
}  // namespace

void split_free_body(const FreeBody& body, FreeBodyState& s, double h_s, std::int64_t steps,
                     SplittingOrder order, std::int64_t* subflows) {
  body.validate();
  if (!std::isfinite(h_s) || !(h_s > 0.0))
    throw std::invalid_argument("split_free_body: h must be > 0");
  std::int64_t count = 0;
  const double c1 = 1.0 / (2.0 - std::cbrt(2.0)), c0 = 1.0 - 2.0 * c1;
  for (std::int64_t k = 0; k < steps; ++k) {
    if (order == SplittingOrder::strang2) {
      strang(body, s, h_s, count);
    } else {
      strang(body, s, c1 * h_s, count);
      strang(body, s, c0 * h_s, count);
      strang(body, s, c1 * h_s, count);
    }
    // Keep the quaternion's norm from drifting by round-off (each sub-flow is exactly unit).
    s.q_BtoS.normalize();
  }
  if (subflows != nullptr) *subflows += count;
}

}  // namespace wobble
