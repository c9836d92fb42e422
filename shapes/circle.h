// A circle's traits for the generic code (shapes/internal.h says what each is), inline: the World
// boxes every shape at every step and the time of impact takes supports at every step.
#pragma once

#include "shapes/internal.h"

namespace collide2d::detail {

inline Aabb oriented_box(const Circle& c, const Orientation&) { return around(c.center, Vec2::Constant(c.radius)); }
inline Vec2 support(const Circle& c, const Rotation<double>&, const Vec2& d) {
  const double n = d.norm();
  return n > 0.0 ? Vec2(c.center + (c.radius / n) * d) : c.center;
}
inline double reach(const Circle& c) { return c.radius; }
inline double turning_reach(const Circle&) { return 0.0; }
inline double support_along(const Circle& c, const Vec2&) { return c.radius; }

}  // namespace collide2d::detail
