// A circle's geometry: the public functions of shapes.h (its traits are inline in shapes/circle.h).
#include <collide2d/shapes.h>

#include "shapes/circle.h"

namespace collide2d {

void validate(const Circle& c) {
  detail::require_coordinate("circle", "cx", c.center.x());
  detail::require_coordinate("circle", "cy", c.center.y());
  detail::require_size("circle", "radius", c.radius);
}

Aabb aabb(const Circle& c) { return detail::oriented_box(c, Orientation{}); }

Vec2 support(const Circle& c, const Vec2& d) { return detail::support(c, detail::Rotation<double>{}, d); }

bool contains(const Circle& c, const Vec2& p) { return (p - c.center).squaredNorm() <= c.radius * c.radius; }

}  // namespace collide2d
