#include "narrowphase/overlap/overlap_circle_circle.h"

#include "narrowphase/batch/lanes.h"

#include <algorithm>
#include <limits>

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/circle_overlap-inl.h"
}  // namespace detail

// Near contact the verdict is distance_circle_circle's (circle_overlap-inl.h).
bool overlap_circle_circle(const Circle& a, const Circle& b) {
  return detail::circle_circle_overlap(detail::Scalar{}, detail::circle_circle_lanes(a, b));
}

DistanceResult distance_circle_circle(const Circle& a, const Circle& b) {
  const Vec2 d = b.center - a.center;
  const double n = d.norm();
  if (n == 0.0) return DistanceResult::touching(a.center);
  const Vec2 u = d / n;
  const double gap = n - a.radius - b.radius;
  if (gap > 0.0) return DistanceResult::apart(gap, a.center + a.radius * u, b.center - b.radius * u);
  // Along the centre line A covers [-ra, ra] and B covers [n - rb, n + rb] (from A's centre).
  const double lo = std::max(-a.radius, n - b.radius);
  const double hi = std::min(a.radius, n + b.radius);
  return DistanceResult::touching(a.center + (0.5 * (lo + hi)) * u);
}

}  // namespace collide2d
