#include "narrowphase/distance_point_ellipse.h"

#include <algorithm>
#include <cmath>

namespace collide2d {
namespace {

// The root of g for z0, z1 > 0 and r0 = (e0/e1)^2 >= 1, in t = s + 1 rather than Eberly's s:
// g(t) = (r0 z0 / (t + r0 - 1))^2 + (z1 / t)^2 - 1 on [z1, |(r0 z0, z1)|]. For a point inside
// near the major axis the root sits at t ~ z1 / sqrt(1 - x^2), far below 1: as s = t - 1 it kept
// only the absolute precision of s, and the closest point's y1 / (s + 1) came out wrong (a
// point 1e-17 off the axis near the evolute's cusp got a distance off by 1.3e-2, and 1e-14 off by
// 2.3e-6; the contact tests' rigid motions found it). g0 = g at t = 1 tells which side of 1 the
// root lies. Newton steps inside the bracket, with a bisection step whenever Newton would leave
// it: g is convex and decreasing, so Newton converges quadratically near the root, and the
// bracket keeps Eberly's guarantee of termination.
double secular_root(double r0, double z0, double z1, double g0) {
  const double n0 = r0 * z0;
  const double shift = r0 - 1.0;
  double lo = z1;
  double hi = g0 < 0.0 ? 1.0 : std::hypot(n0, z1);
  double t = 0.5 * (lo + hi);
  for (;;) {
    const double r_0 = n0 / (t + shift);
    const double r_1 = z1 / t;
    const double g = r_0 * r_0 + r_1 * r_1 - 1.0;
    if (g > 0.0) {
      lo = t;
    } else if (g < 0.0) {
      hi = t;
    } else {
      return t;
    }
    const double slope = -2.0 * (r_0 * r_0 / (t + shift) + r_1 * r_1 / t);
    double next = t - g / slope;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (next == t || next == lo || next == hi) return t;
    t = next;
  }
}

// First quadrant, e0 >= e1 > 0, y0 >= 0, y1 >= 0. Returns the closest point; distance by caller.
Vec2 closest_in_quadrant(double e0, double e1, double y0, double y1) {
  if (y1 > 0.0) {
    if (y0 > 0.0) {
      const double z0 = y0 / e0;
      const double z1 = y1 / e1;
      const double g0 = z0 * z0 + z1 * z1 - 1.0;
      if (g0 == 0.0) return {y0, y1};
      const double r0 = (e0 / e1) * (e0 / e1);
      const double t = secular_root(r0, z0, z1, g0);
      return {r0 * y0 / (t + (r0 - 1.0)), y1 / t};
    }
    return {0.0, e1};
  }
  // On the major axis: the nearest point leaves the axis only inside the evolute's cusp.
  const double numer = e0 * y0;
  const double denom = e0 * e0 - e1 * e1;
  if (numer < denom) {
    const double x = numer / denom;
    return {e0 * x, e1 * std::sqrt(std::max(0.0, 1.0 - x * x))};
  }
  return {e0, 0.0};
}

}  // namespace

PointEllipseResult distance_point_ellipse(double a, double b, const Vec2& p) {
  const bool swap_axes = b > a;
  const double e0 = swap_axes ? b : a;
  const double e1 = swap_axes ? a : b;
  const double y0 = std::abs(swap_axes ? p.y() : p.x());
  const double y1 = std::abs(swap_axes ? p.x() : p.y());

  const Vec2 q = closest_in_quadrant(e0, e1, y0, y1);
  const double u = y0 / e0;
  const double v = y1 / e1;

  PointEllipseResult result;
  result.inside = u * u + v * v <= 1.0;
  result.distance = std::hypot(q.x() - y0, q.y() - y1);
  const double x = std::copysign(swap_axes ? q.y() : q.x(), p.x());
  const double y = std::copysign(swap_axes ? q.x() : q.y(), p.y());
  result.closest = Vec2(x, y);
  return result;
}

}  // namespace collide2d
