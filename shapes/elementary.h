// Private: the elementary functions the library calls, its own so that every platform computes the
// same bits (the C libraries' sin, cos, atan2 and hypot differ in their last bits). Plain double
// operations with double-double intermediates: each result is within one ulp of the exact value
// (one of the two doubles around it), for every double argument. docs/determinism.md gives the
// conditions; tests/unit/test_elementary.cpp measures the error against 50-digit values.
#pragma once

#include "shapes/double_double.h"

#include <array>
#include <cstddef>

namespace collide2d::detail {

struct CosSin {
  double c = 1;
  double s = 0;
};

struct ExtendedCosSin {
  DoubleDouble c = 1;
  DoubleDouble s = 0;
};

// cos(angle) and sin(angle), reduced by the exact multiple of pi/2 (Payne and Hanek, "Radian
// reduction for trigonometric functions", 1983), so that a large angle loses no digits. NaN for an
// infinite or NaN angle.
CosSin cos_sin(double angle);

// cos(angle) and sin(angle) as double-doubles, each within 2^-102 of the exact value: the rotations
// of the extended-precision fallbacks.
ExtendedCosSin cos_sin_extended(double angle);

// The angle of (x, y) in [-pi, pi], with the signs of zero and the infinities as C's atan2.
double arc_tangent(double y, double x);

// The Taylor series of sin (first 3) and cos (first 4) as double-doubles, (-1)^(n/2) / n! for n =
// first, first + 2, ..., `count` of them, each coefficient divided from the one before (relative
// error within 2^-100).
template <std::size_t count>
constexpr std::array<DoubleDouble, count> extended_series(int first) {
  std::array<DoubleDouble, count> c{};
  DoubleDouble term = 1;
  for (int n = 2; n < first; ++n) term = term / DoubleDouble(n);
  for (std::size_t k = 0; k < count; ++k) {
    const int n = first + 2 * static_cast<int>(k);
    term = term / DoubleDouble(n);
    c[k] = (n / 2) % 2 == 0 ? term : -term;
    term = term / DoubleDouble(n + 1);
  }
  return c;
}

// pi as a double-double.
inline constexpr DoubleDouble kExtendedPi{0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53};

// The angle of (x, y) as a double-double, for finite x and y not both zero: within 2^-102 of the
// exact angle, and of it relatively where it is small.
DoubleDouble arc_tangent_extended(const DoubleDouble& y, const DoubleDouble& x);

// sqrt(x^2 + y^2) without overflow or underflow in between; +inf when either is infinite.
double hypotenuse(double x, double y);

}  // namespace collide2d::detail
