#include "narrowphase/overlap_circle_circle.h"

#include <algorithm>
#include <cmath>

namespace collide2d {

// Squares decide when they are clear by far more than their rounding; near contact the verdict is
// the one distance_circle_circle reaches (gap = n - ra - rb > 0), so the two always agree.
bool overlap_circle_circle(const Circle& a, const Circle& b) {
  const double reach = a.radius + b.radius;
  const double q = (b.center - a.center).squaredNorm();
  if (q > reach * reach * (1 + 1e-12)) return false;
  if (q < reach * reach * (1 - 1e-12)) return true;
  return !(std::sqrt(q) - a.radius - b.radius > 0.0);
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
