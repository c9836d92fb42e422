#include "narrowphase/distance_point_ellipse.h"

#include <algorithm>
#include <cmath>

namespace collide2d {
namespace {

// The root of g for z0, z1 > 0 and r0 = (e0/e1)^2 >= 1, in t = s + 1 rather than Eberly's s:
// g(t) = (r0 z0 / (t + r0 - 1))^2 + (z1 / t)^2 - 1. For a point inside near the major axis the root
// sits at t ~ z1 / sqrt(1 - x^2), far below 1: as s = t - 1 it kept only the absolute precision of
// s, and the closest point's y1 / (s + 1) came out wrong (a point 1e-17 off the axis near the
// evolute's cusp got a distance off by 1.3e-2; the contact tests' rigid motions found it).
//
// Newton runs on q(t) = (g(t) + 1)^(-1/2) = 1 rather than on g = 0. q is a weighted power mean of
// order -2 of t + r0 - 1 and t, hence concave and increasing (and exactly linear for a circle), so
// Newton started left of the root never steps past it and climbs monotonically: no bracket and no
// bisection. From the bound max(z1, r0 z0 - (r0 - 1)) it evaluates q 4.4 times on average on
// bench_contact's candidate circle-ellipse pairs, where safeguarded Newton on g, from the middle of
// its bracket, evaluated g 7.8 times. The loop ends when a step no longer climbs;
// t <= r0 z0 + z1 bounds the root, and stops a step that rounding could carry past it.
double secular_root(double r0, double z0, double z1) {
  const double n0 = r0 * z0;
  const double shift = r0 - 1.0;
  const double hi = n0 + z1;
  double t = std::max(z1, n0 - shift);
  for (;;) {
    // t >= z1 > 1e-50 (the caller sends points nearer the axis to its closed form), so neither
    // reciprocal overflows.
    const double u = 1.0 / (t + shift);
    const double v = 1.0 / t;
    const double a = n0 * u;
    const double b = z1 * v;
    const double sum = a * a + b * b;
    const double next = t + sum * (std::sqrt(sum) - 1.0) / (a * a * u + b * b * v);
    if (!(next > t && next < hi)) return t;
    t = next;
  }
}

// First quadrant, e0 >= e1 > 0, y0 >= 0, y1 >= 0. Returns the closest point; distance by caller.
Vec2 closest_in_quadrant(double e0, double e1, double y0, double y1) {
  // A point within 1e-50 of e1 of the major axis counts as on it. Its distance moves by at most
  // that height, and its closest point, which leaves the axis as the cube root of the height near
  // the evolute's cusp, by less than 1e-16 of the size; whereas below 1e-308 the root and the
  // heights are subnormal, a few bits each, and the root's quotients lost all precision (the
  // fuzzer's circle-ellipse contact, 0.25 from the centre of an ellipse 1.08e16 across turned by
  // 2e-314 rad, came out infinite; a test then found distances off by 1e-2 of the size).
  if (y1 / e1 > 1e-50) {
    if (y0 > 0.0) {
      const double z0 = y0 / e0;
      const double z1 = y1 / e1;
      if (z0 * z0 + z1 * z1 == 1.0) return {y0, y1};
      const double r0 = (e0 / e1) * (e0 / e1);
      const double t = secular_root(r0, z0, z1);
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
