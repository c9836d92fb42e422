// Private: the overlap of two sharp convex polygons (rectangles included) by clipping one to the
// other (Sutherland and Hodgman, "Reentrant polygon clipping", 1974), generic over the scalar: in
// double, and in double-double where a sliver or a near-identical pair needs more digits than a
// double clip keeps.
#pragma once

#include <collide2d/shapes.h>

#include "narrowphase/area/boundary.h"
#include "shapes/internal.h"

#include <array>
#include <type_traits>

namespace collide2d::detail::areas {

template <class Real>
V2<Real> widened(const Vec2& v) {
  return {Real(v.x()), Real(v.y())};
}

// A point's offset from the origin: exact in double-double (one two_sum per coordinate), and
// rounded once in double.
template <class Real>
V2<Real> offset(const Vec2& p, const Vec2& origin) {
  if constexpr (std::is_same_v<Real, double>)
    return p - origin;
  else
    return {two_sum(p.x(), -origin.x()), two_sum(p.y(), -origin.y())};
}

// A convex polygon, counter-clockwise: one clipped by another has at most the two counts together.
template <class Real>
struct Corners {
  std::array<V2<Real>, kMaxPieces> v{};
  int count = 0;
};

// The corners of a rectangle or a polygon's core relative to `origin`, rotated by the exact angle to
// the precision of Real; a Shape's must be one of the two.
template <class Real>
Corners<Real> corners_of(const Rect& r, const Vec2& origin);
template <class Real>
Corners<Real> corners_of(const ConvexPolygon& p, const Vec2& origin);
template <class Real>
Corners<Real> corners_of(const Shape& s, const Vec2& origin);

// The part of `subject` on the inner side of every edge of `clipper`.
template <class Real>
Corners<Real> clipped(const Corners<Real>& subject, const Corners<Real>& clipper);

// Green's theorem over straight chords: the triangles (0, p, q) summed, as twice their area and
// six times their first moment about 0.
template <class Real>
struct Fan {
  Real twice_area = 0;
  V2<Real> moment6 = V2<Real>::Zero();

  void add(const V2<Real>& p, const V2<Real>& q) {
    const Real twice = cross(p, q);
    twice_area += twice;
    moment6 += twice * (p + q);
  }
};

// A region's area and first moment about the origin its corners are given relative to.
template <class Real>
struct Moments {
  Real area = 0;
  V2<Real> moment = V2<Real>::Zero();
};

// The moments of a polygon, fanned from its first corner, where the triangles are smallest (an
// empty one has none).
template <class Real>
Moments<Real> moments_of(const Corners<Real>& p);

}  // namespace collide2d::detail::areas
