// Private: the cosine and sine of an angle of moderate size, faster than the C library's.
#pragma once

#include <collide2d/shapes.h>

#include <cmath>
#include <optional>

namespace collide2d::detail {

// Orientation::of(angle) to within an ulp or two, for |angle| <= 8e5 (else nullopt), in a fraction
// of the instructions of the C library's sincos, which a turning time of impact calls every step:
// the angle less the nearest multiple k of pi/2 (in two parts, the first of 33 bits, so that
// k times it is exact for |k| < 2^19: Cody and Waite's reduction), then the Taylor polynomials of
// the cosine and sine to x^18 and x^17, whose remainders are below 1e-19 on [-pi/4, pi/4]. Not a
// replacement for Orientation::of, whose kept orientations must match the plain queries bit for
// bit; a time of impact's steps tolerate far more.
inline std::optional<Orientation> quick_orientation(double angle) {
  if (!(std::abs(angle) <= 8e5)) return std::nullopt;
  constexpr double kPio2Hi = 0x1.921fb544p+0, kPio2Lo = 0x1.0b4611a626331p-34, kTwoOverPi = 0x1.45f306dc9c883p-1;
  constexpr double kRound = 0x1.8p52;  // adding and subtracting it rounds to an integer
  const double k = (angle * kTwoOverPi + kRound) - kRound;
  const double r = (angle - k * kPio2Hi) - k * kPio2Lo;
  const double z = r * r;
  double sine = 1.0 / 355687428096000.0, cosine = 1.0 / 6402373705728000.0;  // 1/17!, 1/18!
  for (const double c : {-1.0 / 1307674368000.0, 1.0 / 6227020800.0, -1.0 / 39916800.0, 1.0 / 362880.0, -1.0 / 5040.0,
                         1.0 / 120.0, -1.0 / 6.0}) {  // -1/15!, 1/13!, ... -1/3!
    sine = sine * z + c;
  }
  for (const double c : {-1.0 / 20922789888000.0, 1.0 / 87178291200.0, -1.0 / 479001600.0, 1.0 / 3628800.0,
                         -1.0 / 40320.0, 1.0 / 720.0, -1.0 / 24.0, 0.5}) {  // -1/16!, 1/14!, ... 1/2!
    cosine = cosine * z + c;
  }
  sine = r + r * z * sine;
  cosine = 1.0 - z * cosine;
  switch (static_cast<long long>(k) & 3) {  // the quarter turns
    case 0:
      return Orientation{cosine, sine};
    case 1:
      return Orientation{-sine, cosine};
    case 2:
      return Orientation{-cosine, -sine};
    default:
      return Orientation{sine, -cosine};
  }
}

}  // namespace collide2d::detail
