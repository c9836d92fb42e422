// A rectangle's geometry: the public functions of shapes.h (its traits are inline in shapes/rect.h).
#include <collide2d/shapes.h>

#include "shapes/rect.h"

#include <cmath>

namespace collide2d {

using Rot = detail::Rotation<double>;

void validate(const Rect& r) {
  detail::require_coordinate("rect", "cx", r.center.x());
  detail::require_coordinate("rect", "cy", r.center.y());
  detail::require_size("rect", "hx", r.half_extents.x());
  detail::require_size("rect", "hy", r.half_extents.y());
  detail::require_finite("rect", "angle", r.angle);
}

Aabb aabb(const Rect& r) { return detail::oriented_box(r, Orientation::of(r.angle)); }

Vec2 support(const Rect& r, const Vec2& d) { return detail::support(r, Rot::of(r.angle), d); }

bool contains(const Rect& r, const Vec2& p) {
  const Vec2 q = Rot::of(r.angle).apply_inverse(Vec2(p - r.center));
  return std::abs(q.x()) <= r.half_extents.x() && std::abs(q.y()) <= r.half_extents.y();
}

}  // namespace collide2d
