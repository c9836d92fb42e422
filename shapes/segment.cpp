// A segment's geometry: the public functions of shapes.h (its traits are inline in shapes/segment.h).
#include <collide2d/shapes.h>

#include "shapes/segment.h"

#include <algorithm>

namespace collide2d {

using Rot = detail::Rotation<double>;

void validate(const Segment& s) {
  detail::require_coordinate("segment", "x1", s.center.x());
  detail::require_coordinate("segment", "y1", s.center.y());
  detail::require_coordinate("segment", "end x", s.end.x());
  detail::require_coordinate("segment", "end y", s.end.y());
  detail::require_finite("segment", "angle", s.angle);
  const double length = s.end.norm();
  if (length == 0.0) detail::reject("segment", "length", length, "must be positive (its two points are one)");
  if (length < kMinSize || length > kMaxMagnitude)
    detail::reject("segment", "length", length, "is outside the supported range 1e-50 to 1e50");
}

Vec2 Segment::point2() const { return center + Rot::of(angle).apply(end); }

Aabb aabb(const Segment& s) { return detail::oriented_box(s, Orientation::of(s.angle)); }

Vec2 support(const Segment& s, const Vec2& d) { return detail::support(s, Rot::of(s.angle), d); }

// On the segment: on its line (the orientation test's sign exactly 0) and between its points.
bool contains(const Segment& s, const Vec2& p) {
  const Vec2 q = Rot::of(s.angle).apply_inverse(Vec2(p - s.center));
  const double along = q.dot(s.end);
  return q.x() * s.end.y() == q.y() * s.end.x() && along >= 0.0 && along <= s.end.squaredNorm();
}

}  // namespace collide2d
