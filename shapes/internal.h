// The shapes module's interface to the rest of the library (not installed): rotations generic over
// the scalar, a value's bits, boxes kept in float, and the form of every validation message.
#pragma once

#include <collide2d/shapes.h>

#include "shapes/bits.h"
#include "shapes/float_box.h"
#include "shapes/rotation.h"

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <span>
#include <string>
#include <vector>

namespace collide2d::detail {

template <class Real>
using V2 = Eigen::Matrix<Real, 2, 1>;

// v turned a quarter turn counter-clockwise: a counter-clockwise outline's face direction from its
// outward normal.
template <class Real>
V2<Real> perp(const V2<Real>& v) {
  return {-v[1], v[0]};
}

// The z of the cross product; any two 2-vectors of one scalar, or expressions of them.
template <class P, class Q>
auto cross(const Eigen::MatrixBase<P>& p, const Eigen::MatrixBase<Q>& q) {
  return p[0] * q[1] - p[1] * q[0];
}

// Places the shape at a centre and angle, in place (a kind with no angle, a circle, keeps none);
// inline, as it runs for every shape a World poses.
inline void place(Shape& shape, const Vec2& center, double angle) {
  std::visit(
      [&](auto& s) {
        s.center = center;
        if constexpr (requires { s.angle; }) s.angle = angle;
      },
      shape);
}
// The shape placed so.
inline Shape placed_at(Shape shape, const Vec2& center, double angle) {
  place(shape, center, angle);
  return shape;
}

// Throws InvalidShape("<what> <field> <rule> (got <value>)"), the form of every validation message
// ("ellipse a must be positive (got -1)"), for the checks of other modules to share.
[[noreturn]] void reject(const char* what, const char* field, double value, const char* rule);

// The checks every shape's validation makes of one field, with that message; inline, as array forms
// check every row, and only a refusal leaves the line.
inline void require_finite(const char* shape, const char* field, double value) {
  if (!std::isfinite(value)) reject(shape, field, value, "must be finite");
}
inline void require_coordinate(const char* shape, const char* field, double value) {
  require_finite(shape, field, value);
  if (std::abs(value) > kMaxMagnitude) reject(shape, field, value, "is beyond the supported range of +-1e50");
}
inline void require_size(const char* shape, const char* field, double value) {
  require_finite(shape, field, value);
  if (!(value > 0.0)) reject(shape, field, value, "must be positive");
  if (value < kMinSize || value > kMaxMagnitude)
    reject(shape, field, value, "is outside the supported range 1e-50 to 1e50");
}

// The box from center - below to center + above, grown by a few ulps of its coordinates (the
// centre's and `reach`, the shape's extent from it): the kernels' rounding must not put a point of
// the shape outside its box (a pair touching to rounding would otherwise never reach the narrow
// phase).
Aabb around(const Vec2& center, const Vec2& below, const Vec2& above, const Vec2& reach);
// The same, as far below as above.
inline Aabb around(const Vec2& center, const Vec2& half) { return around(center, half, half, half); }

// The shortest digits that read back as the value ("0.1", "1e+51", "nan"), for messages.
std::string shortest(double value);

// Room for n elements, an eighth more when it must grow, where push_back and resize double it: the
// lists kept for every proxy and shape would otherwise be up to half empty.
template <class T>
void reserve_room(std::vector<T>& list, std::size_t n) {
  if (n > list.capacity()) list.reserve(n + n / 8);
}

// The list resized to n, new elements `fill`, growing as reserve_room() does.
template <class T>
void resize_room(std::vector<T>& list, std::size_t n, const T& fill = T{}) {
  reserve_room(list, n);
  list.resize(n, fill);
}

}  // namespace collide2d::detail

// Each kind's geometry as the generic code takes it, defined inline in its own header
// (shapes/<word>.h, below; its public validate, aabb, support and contains are in shapes/<word>.cpp):
//   oriented_box(s, o)       its box, given its orientation, Orientation::of(its angle)
//   support(s, rotation, d)  its support point along d, given its rotation
//   reach(s)                 the distance from its centre to its farthest point (reach_of)
//   turning_reach(s)         how fast its support function changes as it turns, per radian: the
//                            largest distance of its normal lines from its centre
//   support_along(s, u)      its support function along a unit direction u of its own axes (a
//                            segment's from its first point)
// and, for a kind with a convex core, core_points(s): its core's points in its own axes.
#include "shapes/capsule.h"
#include "shapes/circle.h"
#include "shapes/ellipse.h"
#include "shapes/polygon.h"
#include "shapes/rect.h"
#include "shapes/segment.h"
