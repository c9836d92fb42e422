#include "narrowphase/overlap_circle_ellipse.h"

#include "narrowphase/box_local.h"
#include "narrowphase/distance_point_ellipse.h"
#include "shapes/rotation.h"

#include <limits>

namespace collide2d {
namespace {

// The circle centre in the ellipse frame (centres subtracted first).
Vec2 center_in_ellipse(const detail::Rotation<double>& rot, const Circle& c, const Ellipse& e) {
  return rot.apply_inverse(Vec2(c.center - e.center));
}

}  // namespace

// The centre inside the ellipse, or the point–ellipse distance within r: the same decision as
// distance_circle_ellipse, so the two always agree. The box around the ellipse rejects first, but only
// when it clears r by more than the rounding of the distance (16 u of the lengths involved).
bool overlap_circle_ellipse(const Circle& c, const Ellipse& e) { return overlap_circle_ellipse(c, e, Orientation::of(e.angle)); }

bool overlap_circle_ellipse(const Circle& c, const Ellipse& e, const Orientation& eo) {
  const Vec2 p = center_in_ellipse({eo.c, eo.s}, c, e);
  const double u = p.x() / e.a;
  const double v = p.y() / e.b;
  if (u * u + v * v <= 1.0) return true;
  const double margin = 16 * std::numeric_limits<double>::epsilon() * (p.norm() + e.a + e.b + c.radius);
  const double clear = c.radius + margin;
  if ((p - detail::clamp_to_box(p, Vec2(e.a, e.b))).squaredNorm() > clear * clear) return false;
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
