// An ellipse's geometry: the public functions of shapes.h (its traits are inline in shapes/ellipse.h).
#include <collide2d/shapes.h>

#include "shapes/ellipse.h"

#include <algorithm>
#include <cmath>

namespace collide2d {

using Rot = detail::Rotation<double>;

void validate(const Ellipse& e) {
  detail::require_coordinate("ellipse", "cx", e.center.x());
  detail::require_coordinate("ellipse", "cy", e.center.y());
  detail::require_size("ellipse", "a", e.a);
  detail::require_size("ellipse", "b", e.b);
  detail::require_finite("ellipse", "angle", e.angle);
}

Aabb aabb(const Ellipse& e) { return detail::oriented_box(e, Orientation::of(e.angle)); }

Vec2 support(const Ellipse& e, const Vec2& d) { return detail::support(e, Rot::of(e.angle), d); }

bool contains(const Ellipse& e, const Vec2& p) {
  const Vec2 q = Rot::of(e.angle).apply_inverse(Vec2(p - e.center));
  const double u = q.x() / e.a;
  const double v = q.y() / e.b;
  return u * u + v * v <= 1.0;
}

}  // namespace collide2d
