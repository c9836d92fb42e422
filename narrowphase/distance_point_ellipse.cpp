#include "narrowphase/distance_point_ellipse.h"

#include "narrowphase/lanes.h"

#include <algorithm>
#include <cmath>

namespace collide2d {
namespace detail {
#include "narrowphase/point_ellipse-inl.h"
}  // namespace detail

namespace {

// The nearest point in the axis cases the root leaves, in the first quadrant with e0 >= e1 > 0:
// a point on the minor axis (y0 = 0), exactly on the curve, or on the major axis. A point within
// 1e-50 of e1 of the major axis counts as on it. Its distance moves by at most that height, and its
// closest point, which leaves the axis as the cube root of the height near the evolute's cusp, by
// less than 1e-16 of the size; whereas below 1e-308 the root and the heights are subnormal, a few
// bits each, and the root's quotients lost all precision (the fuzzer's circle-ellipse contact, 0.25
// from the centre of an ellipse 1.08e16 across turned by 2e-314 rad, came out infinite; a test then
// found distances off by 1e-2 of the size).
Vec2 closest_on_axis(double e0, double e1, double y0, double y1) {
  if (y1 / e1 > 1e-50) return y0 > 0.0 ? Vec2(y0, y1) : Vec2(0.0, e1);
  // On the major axis: the nearest point leaves the axis only inside the evolute's cusp.
  const double numer = e0 * y0;
  const double denom = e0 * e0 - e1 * e1;
  if (numer < denom) {
    const double x = numer / denom;
    return {e0 * x, e1 * std::sqrt(std::max(0.0, 1.0 - x * x))};
  }
  return {e0, 0.0};
}

PointEllipseResult axis_case(const detail::Quadrant<double, bool>& q, const Vec2& p) {
  const Vec2 c = closest_on_axis(q.e0, q.e1, q.y0, q.y1);
  const Vec2 g = Vec2(c.x() / q.e0 * (q.e1 / q.e0), c.y() / q.e1).normalized();
  const auto unswap = [&](const Vec2& v) {
    return Vec2(std::copysign(q.swap ? v.y() : v.x(), p.x()), std::copysign(q.swap ? v.x() : v.y(), p.y()));
  };
  PointEllipseResult result;
  result.inside = q.inside;
  result.distance = std::hypot(c.x() - q.y0, c.y() - q.y1);
  result.closest = unswap(c);
  result.normal = unswap(g);
  return result;
}

}  // namespace

PointEllipseResult distance_point_ellipse(double a, double b, const Vec2& p) {
  const detail::Scalar d;
  const auto q = detail::Quadrant<double, bool>::of(d, p.x(), p.y(), a, b);
  if (!q.general) return axis_case(q, p);
  detail::SecularRoot<detail::Scalar, double> root(d, q.r0, q.z0, q.z1);
  while (root.step()) {
  }
  return detail::point_ellipse_result(detail::nearest_at_root(d, q, root.t(), p.x(), p.y()));
}

}  // namespace collide2d
