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
// The exact flow of T_i = m_i^2 / (2 I_i) for time h: m turns about e_i by -theta and the
// body by +theta. Written as a plane rotation of the two other components of m and a product
// with the quaternion (cos(theta/2), sin(theta/2) e_i), not through a 3x3 rotation matrix: fewer
// roundings per sub-flow, so |m| drifts less over millions of them, and it is faster.
void subflow(const FreeBody& body, FreeBodyState& s, int i, double h) {
  const double theta = s.m_B[i] / body.I_kgm2[i] * h;  // m_i is constant along this flow
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  const double c = std::cos(theta), sn = std::sin(theta);
  const double mj = s.m_B[j], mk = s.m_B[k];
  s.m_B[j] = std::fma(c, mj, sn * mk);  // rotation by -theta about e_i (one rounding fewer)
  s.m_B[k] = std::fma(c, mk, -sn * mj);
  const double ch = std::cos(0.5 * theta), sh = std::sin(0.5 * theta);
  Quat turn(ch, 0.0, 0.0, 0.0);
  turn.vec()[i] = sh;
  s.q_BtoS = s.q_BtoS * turn;
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
