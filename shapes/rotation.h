// Private: a planar rotation stored as its cosine and sine, generic over the scalar so that the
// extended-precision fallbacks in narrowphase/ reuse it. The public Orientation (shapes.h) is the
// same pair kept by callers; of() is the one conversion from it.
#pragma once

#include <collide2d/shapes.h>

#include "shapes/elementary.h"

#include <cmath>
#include <type_traits>

namespace collide2d::detail {

template <class Real>
struct Rotation {
  Real c = 1;
  Real s = 0;

  static Rotation of(double angle) {
    static_assert(std::is_same_v<Real, double> || std::is_same_v<Real, DoubleDouble>);
    if constexpr (std::is_same_v<Real, double>) {
      const CosSin r = cos_sin(angle);
      return {r.c, r.s};
    } else {
      const ExtendedCosSin r = cos_sin_extended(angle);
      return {r.c, r.s};
    }
  }
  static Rotation of(const Orientation& o) { return {static_cast<Real>(o.c), static_cast<Real>(o.s)}; }
  // Rotates (x, y) by this rotation.
  template <class V>
  V apply(const V& v) const {
    return V(c * v[0] - s * v[1], s * v[0] + c * v[1]);
  }
  // Rotates (x, y) by the inverse rotation: the coordinates of a world vector in this frame.
  template <class V>
  V apply_inverse(const V& v) const {
    return V(c * v[0] + s * v[1], -s * v[0] + c * v[1]);
  }
  // This rotation seen from `frame`: frame^-1 * this. Composed from the two cosines and sines
  // rather than from the angle difference, which loses digits when the angles are large.
  Rotation relative_to(const Rotation& frame) const { return {frame.c * c + frame.s * s, frame.c * s - frame.s * c}; }
};

}  // namespace collide2d::detail
