#include "narrowphase/overlap_circle_ellipse.h"

#include "narrowphase/box_local.h"
#include "narrowphase/distance_point_ellipse.h"
#include "shapes/rotation.h"

namespace collide2d {
namespace {

// The circle centre in the ellipse frame (centres subtracted first).
Vec2 center_in_ellipse(const detail::Rotation<double>& rot, const Circle& c, const Ellipse& e) {
  return rot.apply_inverse(Vec2(c.center - e.center));
}

}  // namespace

bool overlap_circle_ellipse(const Circle& c, const Ellipse& e) {
  const Vec2 p = center_in_ellipse(detail::Rotation<double>::of(e.angle), c, e);
  const double u = p.x() / e.a;
  const double v = p.y() / e.b;
  if (u * u + v * v <= 1.0) return true;
  const double r2 = c.radius * c.radius;
  if ((p - detail::clamp_to_box(p, Vec2(e.a, e.b))).squaredNorm() > r2) return false;
  return distance_point_ellipse(e.a, e.b, p).distance <= c.radius;
}

DistanceResult distance_circle_ellipse(const Circle& c, const Ellipse& e) {
  const auto rot = detail::Rotation<double>::of(e.angle);
  const Vec2 p = center_in_ellipse(rot, c, e);
  const PointEllipseResult pe = distance_point_ellipse(e.a, e.b, p);
  if (pe.inside) return DistanceResult::touching(c.center);
  const Vec2 on_ellipse = e.center + rot.apply(pe.closest);
  if (pe.distance <= c.radius) return DistanceResult::touching(on_ellipse);
  const Vec2 toward = rot.apply(Vec2(pe.closest - p));  // world direction, centre to ellipse point
  return DistanceResult::apart(pe.distance - c.radius, c.center + (c.radius / pe.distance) * toward,
                               on_ellipse);
}

}  // namespace collide2d
