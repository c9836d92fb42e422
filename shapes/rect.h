// A rectangle's traits for the generic code (shapes/internal.h says what each is), inline: the World
// boxes every shape at every step and the time of impact takes supports at every step.
#pragma once

#include "shapes/internal.h"

#include <cmath>

namespace collide2d::detail {

inline Aabb oriented_box(const Rect& r, const Orientation& o) {
  const double c = std::abs(o.c), s = std::abs(o.s);
  const Vec2& h = r.half_extents;
  return around(r.center, Vec2(h.x() * c + h.y() * s, h.x() * s + h.y() * c));
}

inline Vec2 support(const Rect& r, const Rotation<double>& rot, const Vec2& d) {
  const Vec2 w = rot.apply_inverse(d);
  const Vec2 corner(w.x() >= 0.0 ? r.half_extents.x() : -r.half_extents.x(),
                    w.y() >= 0.0 ? r.half_extents.y() : -r.half_extents.y());
  return r.center + rot.apply(corner);
}

inline double reach(const Rect& r) { return r.half_extents.norm(); }

// A corner (hx, hy) supports the directions between its two faces' normals, where |hx n_y - hy n_x|
// is largest at a face normal: the longer half side.
inline double turning_reach(const Rect& r) { return r.half_extents.maxCoeff(); }

inline double support_along(const Rect& r, const Vec2& local) { return local.cwiseAbs().dot(r.half_extents); }

}  // namespace collide2d::detail
