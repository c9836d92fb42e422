// Rectangle–circle distance: the closed form. The circle centre is moved into the rectangle's frame
// (centres subtracted first) and clamped to the box; that clamp is the rectangle point nearest the
// centre. Overlap witness: the circle centre when it is inside the rectangle, else that nearest
// rectangle point.
#include <collide2d/kernels.h>

#include "narrowphase/shared/frames/box_local.h"
#include "narrowphase/shared/lanes.h"
#include "shapes/internal.h"

namespace collide2d {

DistanceResult distance_rect_circle(const Rect& r, const Circle& c) {
  const Orientation ro = Orientation::of(r.angle);
  const detail::Rotation<double> rot = detail::Rotation<double>::of(ro);
  const detail::RectCircleLanes<double> f = detail::rect_circle_lanes(r, ro, c);
  const Vec2 center(f.px, f.py);
  const Vec2 nearest = detail::clamp_to_box(center, r.half_extents);
  const auto to_world = [&](const Vec2& p) -> Vec2 { return r.center + rot.apply(p); };
  const Vec2 d = center - nearest;
  const double n = d.norm();
  if (n == 0.0) return DistanceResult::touching(c.center);
  if (n <= c.radius) return DistanceResult::touching(to_world(nearest));
  return DistanceResult::apart(n - c.radius, to_world(nearest), to_world(Vec2(center - (c.radius / n) * d)));
}

}  // namespace collide2d
