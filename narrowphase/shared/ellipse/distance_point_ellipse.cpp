#include "narrowphase/shared/ellipse/distance_point_ellipse.h"

#include "narrowphase/shared/lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide2d {
namespace detail {
#include "narrowphase/shared/ellipse/point_ellipse-inl.h"
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
  result.distance = detail::hypotenuse(c.x() - q.y0, c.y() - q.y1);
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

// With the root within t (1 + w) and |g| <= reach, the normal turns by at most w / 2 up to the root
// (its angle moves at most 1 / (2t) per unit of t), and the distance |t - 1| e1 |g| by at most
// e1 reach w (t + |t - 1|) (|g| falls at most as fast as 1 / t). The point moved by the radius
// moves with the normal, by the radius times the turn; the point moved by the signed distance, by
// the error and the separation times the turn beyond that. The last step (w = 0) is the exact root.
std::optional<NearestWithin> distance_point_ellipse_within(double a, double b, const Vec2& p, double radius,
                                                           double tolerance, double angle) {
  const detail::Scalar d;
  const auto q = detail::Quadrant<double, bool>::of(d, p.x(), p.y(), a, b);
  if (!q.general) return std::nullopt;
  const double rounding =
      16 * std::numeric_limits<double>::epsilon() * (std::abs(p.x()) + std::abs(p.y()) + q.e0 + radius);
  detail::SecularRoot<detail::Scalar, double> root(d, q.r0, q.z0, q.z1);
  for (bool running = true; running;) {
    running = root.step();
    const double w = running ? root.width() : 0.0, turn = w / 2;
    if (!(turn <= angle)) continue;
    const double t = root.t();
    const double error = q.e1 * root.reach() * w * (t + std::abs(t - 1)) + rounding;
    const PointEllipseResult near = detail::point_ellipse_result(detail::nearest_at_root(d, q, t, p.x(), p.y()));
    const double signed_distance = near.inside ? -near.distance : near.distance;
    const double s = std::abs(signed_distance - radius);
    const bool within = s > error && error <= tolerance && radius * turn + error + (s + error) * turn <= tolerance;
    if (running && !within) continue;
    NearestWithin out{near, signed_distance, running ? error : 0.0, turn};
    out.near.closest = p - signed_distance * near.normal;
    return out;
  }
  return std::nullopt;
}

// In the reflected first quadrant (Quadrant) the feet across the major axis are the roots of the
// secular function at t = -w in (1 - r0, 0), (r0 z0 / (r0 - 1 - w))^2 + (z1 / w)^2 = 1: none, or
// two, of which the one nearer w = 0 is the distance's local minimum (at p on the major axis it is
// the mirror image of the nearest point; on the minor axis, the far vertex), the other its local
// maximum. G(w) = (a_^2 + b_^2)^(-1/2), with a_ = r0 z0 / (r0 - 1 - w) and b_ = z1 / w, is a power
// mean of order -2 of two functions affine in w, positive on the interval, so it is concave there,
// as q is for the nearest point: Newton on G = 1 from w = z1 (where b_ = 1, so G <= 1) climbs to the
// nearer root without passing it. G <= min(1 / a_, 1 / b_), so a root needs z1 <= w <=
// r0 - 1 - r0 z0, which excludes every p outside the evolute's convex hull, the rhombus
// e0 y0 + e1 y1 < e0^2 - e1^2; inside it but outside the evolute G stays below 1, and the climb
// passes G's peak (its slope turns) or leaves the interval.
std::optional<CurveFoot> other_local_nearest(double a, double b, const Vec2& p) {
  // Outside the rhombus, before any division: most points are.
  const bool wide = a >= b;
  if (!((wide ? a : b) * std::abs(wide ? p.x() : p.y()) + (wide ? b : a) * std::abs(wide ? p.y() : p.x()) <
        (a - b) * (a + b) * (wide ? 1.0 : -1.0))) {
    return std::nullopt;
  }
  const detail::Scalar d;
  const auto q = detail::Quadrant<double, bool>::of(d, p.x(), p.y(), a, b);
  const double pole = (q.e0 - q.e1) * (q.e0 + q.e1) / (q.e1 * q.e1);  // r0 - 1 without its rounding
  const double n0 = q.r0 * q.z0;
  const double hi = pole - n0;
  Vec2 foot;  // in the reflected quadrant, the minor coordinate across the axis from p's
  if (!(q.z1 > 1e-50)) {
    // On the major axis (as closest_on_axis): the mirror image of the nearest point, inside the cusp.
    const double numer = q.e0 * q.y0, denom = (q.e0 - q.e1) * (q.e0 + q.e1);
    if (!(numer < denom)) return std::nullopt;
    const double x = numer / denom;
    foot = Vec2(q.e0 * x, -q.e1 * std::sqrt(std::max(0.0, 1.0 - x * x)));
  } else {
    if (!(q.z1 < hi)) return std::nullopt;
    double w = q.z1;
    for (int k = 0;; ++k) {
      const double u = 1 / (pole - w), v = 1 / w;
      const double a_ = n0 * u, b_ = q.z1 * v;
      const double sum = a_ * a_ + b_ * b_;
      const double rise = b_ * b_ * v - a_ * a_ * u;     // G' sum^(3/2)
      if (!(rise > 0) || k == 100) return std::nullopt;  // past G's peak below 1: no root
      const double next = w + (std::sqrt(sum) - 1) * sum / rise;
      if (!(next > w)) break;  // at the root to rounding
      if (!(next < hi)) return std::nullopt;
      const bool last = next - w <= 0x1p-50 * w;
      w = next;
      if (last) break;
    }
    foot = Vec2(q.e0 * (n0 / (pole - w)), -q.e1 * (q.z1 / w));
  }
  const Vec2 g(foot.x() / q.e0 * (q.e1 / q.e0), foot.y() / q.e1);  // the outward normal's direction
  const Vec2 normal = g.normalized();
  const auto back = [&](const Vec2& v) {  // undo the reflection (the minor sign is p's, flipped by v's own)
    const double major = std::copysign(v.x(), q.swap ? p.y() : p.x());
    const double minor = std::copysign(1.0, q.swap ? p.x() : p.y()) * v.y();
    return q.swap ? Vec2(minor, major) : Vec2(major, minor);
  };
  CurveFoot out;
  out.point = back(foot);
  out.normal = back(normal);
  out.signed_distance = (Vec2(q.y0, q.y1) - foot).dot(normal);
  return out;
}

}  // namespace collide2d
