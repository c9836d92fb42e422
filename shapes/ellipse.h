// An ellipse's traits for the generic code (shapes/internal.h says what each is), inline: the World
// boxes every shape at every step and the time of impact takes supports at every step.
#pragma once

#include "shapes/internal.h"

#include <algorithm>
#include <cmath>

namespace collide2d::detail {

// The extreme x of the rotated ellipse is the support half-width sqrt((a c)^2 + (b s)^2).
inline Aabb oriented_box(const Ellipse& e, const Orientation& o) {
  return around(e.center, Vec2(hypotenuse(e.a * o.c, e.b * o.s), hypotenuse(e.a * o.s, e.b * o.c)));
}

// Support of {K + V diag(a,b) u : |u| <= 1} in direction d is K + V diag(a,b)^2 w / |diag(a,b) w|
// with w = V^T d; d is scaled by its largest component first so that squares cannot overflow.
inline Vec2 support(const Ellipse& e, const Rotation<double>& r, const Vec2& d) {
  const double m = d.cwiseAbs().maxCoeff();
  if (!(m > 0.0)) return e.center;
  const Vec2 w = r.apply_inverse(Vec2(d / m));
  const Vec2 scaled(e.a * w.x(), e.b * w.y());
  const Vec2 local(e.a * scaled.x(), e.b * scaled.y());
  return e.center + r.apply(Vec2(local / scaled.norm()));
}

inline double reach(const Ellipse& e) { return std::max(e.a, e.b); }

// The point (a cos u, b sin u) gives (a^2 - b^2) |sin u cos u| / sqrt(b^2 cos^2 u + a^2 sin^2 u),
// largest at tan^2 u = b / a, where it is a - b.
inline double turning_reach(const Ellipse& e) { return std::abs(e.a - e.b); }

inline double support_along(const Ellipse& e, const Vec2& local) {
  return std::sqrt(e.a * e.a * local.x() * local.x() + e.b * e.b * local.y() * local.y());
}

}  // namespace collide2d::detail
