// A convex polygon's traits for the generic code (shapes/internal.h says what each is), inline: the
// World boxes every shape at every step and the time of impact takes supports at every step.
#pragma once

#include "shapes/internal.h"

#include <algorithm>
#include <limits>
#include <span>

namespace collide2d::detail {

inline Aabb oriented_box(const ConvexPolygon& p, const Orientation& o) {
  const Rotation<double> rot = Rotation<double>::of(o);
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec2& v : p.vertices()) {
    const Vec2 w = rot.apply(v);
    lo = lo.cwiseMin(w), hi = hi.cwiseMax(w);
  }
  const Vec2 reach = lo.cwiseAbs().cwiseMax(hi.cwiseAbs()).array() + p.radius();
  return around(p.center, p.radius() - lo.array(), hi.array() + p.radius(), reach);
}

inline Vec2 support(const ConvexPolygon& p, const Rotation<double>& rot, const Vec2& d) {
  const Vec2 local = rot.apply_inverse(d);
  const std::span<const Vec2> v = p.vertices();
  const Vec2* best = &v[0];
  double top = best->dot(local);
  for (const Vec2& w : v.subspan(1)) {
    const double along = w.dot(local);
    if (along > top) top = along, best = &w;
  }
  const Vec2 vertex = p.center + rot.apply(*best);
  const double n = d.norm();
  return n > 0.0 && p.radius() > 0.0 ? Vec2(vertex + (p.radius() / n) * d) : vertex;
}

inline double reach(const ConvexPolygon& p) { return p.outline->reach; }
inline double turning_reach(const ConvexPolygon& p) { return p.outline->reach - p.radius(); }

inline double support_along(const ConvexPolygon& p, const Vec2& local) {
  double top = -std::numeric_limits<double>::infinity();
  for (const Vec2& v : p.vertices()) top = std::max(top, local.dot(v));
  return top + p.radius();
}

inline std::span<const Vec2> core_points(const ConvexPolygon& p) { return p.vertices(); }

}  // namespace collide2d::detail
