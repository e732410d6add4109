#include "core/heavy_top.hpp"

#include <cmath>
#include <stdexcept>

namespace wobble {

double sleeping_top_discriminant(double p, double M, double g, double l, double I1) {
  for (const double x : {M, g, l, I1}) {
    if (!std::isfinite(x) || !(x > 0.0))
      throw std::invalid_argument("heavy top: M, g, l and I1 must be finite and > 0");
  }
  if (!std::isfinite(p)) throw std::invalid_argument("heavy top: p_psi must be finite");
  // sqrt of a product of four rounded factors: relative error a few eps, against which the
  // factor (|p| - c) is exact when |p| and c are within a factor 2 (Sterbenz).
  const double c = 2.0 * std::sqrt(M * g * l * I1);
  return (std::abs(p) - c) * (std::abs(p) + c);
}

bool sleeping_top_is_stable(double p, double M, double g, double l, double I1) {
  return sleeping_top_discriminant(p, M, g, l, I1) >= 0.0;
}

}  // namespace wobble
