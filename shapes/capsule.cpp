// A capsule's geometry: the public functions of shapes.h and the traits of shapes/internal.h.
#include <collide2d/shapes.h>

#include "shapes/internal.h"

#include <algorithm>
#include <cmath>

namespace collide2d {

using Rot = detail::Rotation<double>;

void validate(const Capsule& c) {
  detail::require_coordinate("capsule", "cx", c.center.x());
  detail::require_coordinate("capsule", "cy", c.center.y());
  if (c.half_length == 0.0)
    detail::reject("capsule", "half_length", c.half_length,
                   "must be positive (a capsule of no length is a circle: use circle)");
  detail::require_size("capsule", "half_length", c.half_length);
  detail::require_size("capsule", "radius", c.radius);
  detail::require_finite("capsule", "angle", c.angle);
}

Aabb aabb(const Capsule& c) { return detail::oriented_box(c, Orientation::of(c.angle)); }

Vec2 support(const Capsule& c, const Vec2& d) { return detail::support(c, Rot::of(c.angle), d); }

bool contains(const Capsule& c, const Vec2& p) {
  const Vec2 q = Rot::of(c.angle).apply_inverse(Vec2(p - c.center));
  const double along = q.x() - std::clamp(q.x(), -c.half_length, c.half_length);
  return along * along + q.y() * q.y() <= c.radius * c.radius;
}

namespace detail {

Aabb oriented_box(const Capsule& c, const Orientation& o) {
  return around(c.center, Vec2(c.half_length * std::abs(o.c) + c.radius, c.half_length * std::abs(o.s) + c.radius));
}

Vec2 support(const Capsule& c, const Rot& rot, const Vec2& d) {
  const Vec2 axis(rot.c, rot.s);
  const double n = d.norm();
  const Vec2 end = c.center + (d.dot(axis) >= 0.0 ? c.half_length : -c.half_length) * axis;
  return n > 0.0 ? Vec2(end + (c.radius / n) * d) : end;
}

double reach(const Capsule& c) { return c.half_length + c.radius; }
double turning_reach(const Capsule& c) { return c.half_length; }
double support_along(const Capsule& c, const Vec2& local) { return c.half_length * std::abs(local.x()) + c.radius; }
std::array<Vec2, 2> core_points(const Capsule& c) { return {Vec2(-c.half_length, 0), Vec2(c.half_length, 0)}; }

}  // namespace detail
}  // namespace collide2d
