#pragma once
// A double-double result against Boost.Multiprecision at 50 digits: its exact value and its
// relative error in units of 2^-104 (a double-double's precision is about 2^-106; its
// operations' bounds are a few of these, Hida, Li and Bailey's QD library).
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "core/double_double.hpp"

namespace wobble::testing {

using mp50 = boost::multiprecision::cpp_bin_float_50;

inline mp50 exact(const DoubleDouble& x) {
  return mp50(x.hi) + mp50(x.lo);
}

inline double error_in_u(const DoubleDouble& got, const mp50& want) {
  return static_cast<double>(abs(exact(got) - want) / abs(want)) / 0x1p-104;
}

}  // namespace wobble::testing
