#pragma once
// Boost.Odeint, included with two of GCC 12's flow warnings off: its steppers copy their own
// default-constructed scratch arrays (std::array members never read before written), which GCC
// 12 at -O3 reports as -Wuninitialized / -Wmaybe-uninitialized inside Boost's headers. The
// pragma covers those headers only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop
