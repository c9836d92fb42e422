// A circle's geometry: the public functions of shapes.h and the traits of shapes/internal.h.
#include <collide2d/shapes.h>

#include "shapes/internal.h"

namespace collide2d {

void validate(const Circle& c) {
  detail::require_coordinate("circle", "cx", c.center.x());
  detail::require_coordinate("circle", "cy", c.center.y());
  detail::require_size("circle", "radius", c.radius);
}

Aabb aabb(const Circle& c) { return detail::around(c.center, Vec2::Constant(c.radius)); }

Vec2 support(const Circle& c, const Vec2& d) {
  const double n = d.norm();
  return n > 0.0 ? Vec2(c.center + (c.radius / n) * d) : c.center;
}

bool contains(const Circle& c, const Vec2& p) { return (p - c.center).squaredNorm() <= c.radius * c.radius; }

namespace detail {

Aabb oriented_box(const Circle& c, const Orientation&) { return aabb(c); }
Vec2 support(const Circle& c, const Rotation<double>&, const Vec2& d) { return collide2d::support(c, d); }
double reach(const Circle& c) { return c.radius; }
double turning_reach(const Circle&) { return 0.0; }
double support_along(const Circle& c, const Vec2&) { return c.radius; }

}  // namespace detail
}  // namespace collide2d
