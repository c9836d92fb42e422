#include "narrowphase/overlap/overlap_circle_ellipse.h"

#include "narrowphase/batch/lanes.h"
#include "narrowphase/ellipse/distance_point_ellipse.h"
#include "shapes/rotation.h"

#include <limits>

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/circle_overlap-inl.h"
}  // namespace detail

// The centre inside the ellipse, or the point–ellipse distance within r: the same decision as
// distance_circle_ellipse, so the two always agree. Certain cases come first
// (circle_overlap-inl.h), the root only for the pairs they leave.
bool overlap_circle_ellipse(const Circle& c, const Ellipse& e) { return overlap_circle_ellipse(c, e, Orientation::of(e.angle)); }

bool overlap_circle_ellipse(const Circle& c, const Ellipse& e, const Orientation& eo) {
  const detail::CircleEllipseLanes<double> f = detail::circle_ellipse_lanes(c, e, eo);
  const detail::LaneVerdicts<bool> v = detail::CircleEllipseFilter<detail::Scalar, double>(detail::Scalar{}, f).run();
  return v.separated || v.overlap ? v.overlap : detail::circle_ellipse_exact(f);
}

bool detail::circle_ellipse_exact(const CircleEllipseLanes<double>& f) {
  return distance_point_ellipse(f.a, f.b, Vec2(f.px, f.py)).distance <= f.r;
}

DistanceResult distance_circle_ellipse(const Circle& c, const Ellipse& e) {
  const Orientation eo = Orientation::of(e.angle);
  const detail::Rotation<double> rot{eo.c, eo.s};
  const detail::CircleEllipseLanes<double> f = detail::circle_ellipse_lanes(c, e, eo);
  const Vec2 p(f.px, f.py);
  const PointEllipseResult pe = distance_point_ellipse(e.a, e.b, p);
  if (pe.inside) return DistanceResult::touching(c.center);
  const Vec2 on_ellipse = e.center + rot.apply(pe.closest);
  if (pe.distance <= c.radius) return DistanceResult::touching(on_ellipse);
  const Vec2 toward = rot.apply(Vec2(pe.closest - p));  // world direction, centre to ellipse point
  return DistanceResult::apart(pe.distance - c.radius, c.center + (c.radius / pe.distance) * toward,
                               on_ellipse);
}

}  // namespace collide2d
