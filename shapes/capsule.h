// A capsule's traits for the generic code (shapes/internal.h says what each is), inline: the World
// boxes every shape at every step and the time of impact takes supports at every step.
#pragma once

#include "shapes/internal.h"

#include <array>
#include <cmath>

namespace collide2d::detail {

inline Aabb oriented_box(const Capsule& c, const Orientation& o) {
  return around(c.center, Vec2(c.half_length * std::abs(o.c) + c.radius, c.half_length * std::abs(o.s) + c.radius));
}

inline Vec2 support(const Capsule& c, const Rotation<double>& rot, const Vec2& d) {
  const Vec2 axis(rot.c, rot.s);
  const double n = d.norm();
  const Vec2 end = c.center + (d.dot(axis) >= 0.0 ? c.half_length : -c.half_length) * axis;
  return n > 0.0 ? Vec2(end + (c.radius / n) * d) : end;
}

inline double reach(const Capsule& c) { return c.half_length + c.radius; }
inline double turning_reach(const Capsule& c) { return c.half_length; }
inline double support_along(const Capsule& c, const Vec2& local) {
  return c.half_length * std::abs(local.x()) + c.radius;
}
inline std::array<Vec2, 2> core_points(const Capsule& c) { return {Vec2(-c.half_length, 0), Vec2(c.half_length, 0)}; }

}  // namespace collide2d::detail
