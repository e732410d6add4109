#include "solvers/key.hpp"

#include <cmath>

namespace wobble {

double Value::scale() const {
  double s = 0.0;
  for (double x : data) s = std::max(s, std::abs(x));
  return s;
}

}  // namespace wobble
