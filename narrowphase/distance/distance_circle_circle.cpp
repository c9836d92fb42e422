// Circle–circle distance: the closed form along the line of centres (|c_b - c_a| against
// r_a + r_b). Overlap witness: the midpoint of the chord of the centre line shared by both discs.
#include <collide2d/kernels.h>

#include <algorithm>

namespace collide2d {

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
