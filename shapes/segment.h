// A segment's traits for the generic code (shapes/internal.h says what each is), inline: the World
// boxes every shape at every step and the time of impact takes supports at every step.
#pragma once

#include "shapes/internal.h"

#include <algorithm>
#include <array>

namespace collide2d::detail {

inline Aabb oriented_box(const Segment& s, const Orientation& o) {
  const Vec2 to = Rotation<double>::of(o).apply(s.end);
  return around(s.center, to.cwiseMin(0.0).cwiseAbs(), to.cwiseMax(0.0), to.cwiseAbs());
}

inline Vec2 support(const Segment& s, const Rotation<double>& rot, const Vec2& d) {
  const Vec2 to = rot.apply(s.end);
  return d.dot(to) >= 0.0 ? Vec2(s.center + to) : s.center;
}

inline double reach(const Segment& s) { return s.end.norm(); }
inline double turning_reach(const Segment& s) { return s.end.norm(); }
inline double support_along(const Segment& s, const Vec2& local) { return std::max(0.0, local.dot(s.end)); }
inline std::array<Vec2, 2> core_points(const Segment& s) { return {Vec2::Zero(), s.end}; }

}  // namespace collide2d::detail
