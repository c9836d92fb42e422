#include "narrowphase/overlap_circle_circle.h"

#include "narrowphase/within_reach.h"

#include <algorithm>

namespace collide2d {

// Near contact the verdict is distance_circle_circle's: apart when n - ra - rb > 0.
bool overlap_circle_circle(const Circle& a, const Circle& b) {
  return detail::within_reach((b.center - a.center).squaredNorm(), a.radius + b.radius,
                              [&](double n) { return n - a.radius - b.radius > 0.0; });
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
