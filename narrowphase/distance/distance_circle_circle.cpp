// Circle–circle distance: the closed form along the line of centres (|c_b - c_a| against
// r_a + r_b). Overlap witness: the midpoint of the chord of the centre line shared by both discs.
// The gap between the two curves too (boundary_distance_circle_circle).
#include <collide2d/kernels.h>

#include <algorithm>
#include <cmath>

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

// Nested circles: the gap lies on the line of centres, on the side away from the larger circle's
// centre (any side when the centres coincide).
DistanceResult boundary_distance_circle_circle(const Circle& a, const Circle& b) {
  const Vec2 delta = b.center - a.center;
  const double d = delta.norm();
  if (d >= a.radius + b.radius) return distance_circle_circle(a, b);
  const Vec2 u = d > 0 ? Vec2(delta / d) : Vec2::UnitX();
  if (d <= std::abs(a.radius - b.radius)) {
    const Vec2 away = a.radius >= b.radius ? u : Vec2(-u);
    const Vec2 pa = a.center + a.radius * away;
    const Vec2 pb = b.center + b.radius * away;
    const double gap = std::abs(a.radius - b.radius) - d;
    return gap > 0 ? DistanceResult::apart(gap, pa, pb) : DistanceResult::touching(pa);
  }
  const double along = (d * d + a.radius * a.radius - b.radius * b.radius) / (2 * d);
  const double across = std::sqrt(std::max(0.0, a.radius * a.radius - along * along));
  return DistanceResult::touching(a.center + along * u + across * Vec2(-u.y(), u.x()));
}

}  // namespace collide2d
