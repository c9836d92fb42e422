// Circle–ellipse distance through the exact point–ellipse distance of the circle's centre
// (distance_point_ellipse.h) less the radius. Overlap witness: the circle centre when it is inside
// the ellipse, else the nearest ellipse point. Accuracy: that of distance_point_ellipse.
#include <collide2d/kernels.h>

#include "narrowphase/shared/ellipse/distance_point_ellipse.h"
#include "narrowphase/shared/lanes.h"
#include "shapes/internal.h"

namespace collide2d {

DistanceResult distance_circle_ellipse(const Circle& c, const Ellipse& e) {
  const Orientation eo = Orientation::of(e.angle);
  const detail::Rotation<double> rot = detail::Rotation<double>::of(eo);
  const detail::CircleEllipseLanes<double> f = detail::circle_ellipse_lanes(c, e, eo);
  const Vec2 p(f.px, f.py);
  const PointEllipseResult pe = distance_point_ellipse(e.a, e.b, p);
  if (pe.inside) return DistanceResult::touching(c.center);
  const Vec2 on_ellipse = e.center + rot.apply(pe.closest);
  if (pe.distance <= c.radius) return DistanceResult::touching(on_ellipse);
  const Vec2 toward = rot.apply(Vec2(pe.closest - p));  // world direction, centre to ellipse point
  return DistanceResult::apart(pe.distance - c.radius, c.center + (c.radius / pe.distance) * toward, on_ellipse);
}

}  // namespace collide2d
