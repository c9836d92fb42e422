// A rectangle's geometry: the public functions of shapes.h and the traits of shapes/internal.h.
#include <collide2d/shapes.h>

#include "shapes/internal.h"

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

namespace detail {

Aabb oriented_box(const Rect& r, const Orientation& o) {
  const double c = std::abs(o.c), s = std::abs(o.s);
  const Vec2& h = r.half_extents;
  return around(r.center, Vec2(h.x() * c + h.y() * s, h.x() * s + h.y() * c));
}

Vec2 support(const Rect& r, const Rot& rot, const Vec2& d) {
  const Vec2 w = rot.apply_inverse(d);
  const Vec2 corner(w.x() >= 0.0 ? r.half_extents.x() : -r.half_extents.x(),
                    w.y() >= 0.0 ? r.half_extents.y() : -r.half_extents.y());
  return r.center + rot.apply(corner);
}

double reach(const Rect& r) { return r.half_extents.norm(); }

// A corner (hx, hy) supports the directions between its two faces' normals, where |hx n_y - hy n_x|
// is largest at a face normal: the longer half side.
double turning_reach(const Rect& r) { return r.half_extents.maxCoeff(); }

double support_along(const Rect& r, const Vec2& local) { return local.cwiseAbs().dot(r.half_extents); }

}  // namespace detail
}  // namespace collide2d
