// A capsule's geometry: the public functions of shapes.h (its traits are inline in shapes/capsule.h).
#include <collide2d/shapes.h>

#include "shapes/capsule.h"

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

}  // namespace collide2d
