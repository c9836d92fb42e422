#include "narrowphase/overlap/overlap_rect_circle.h"

#include "narrowphase/frames/box_local.h"
#include "narrowphase/batch/lanes.h"
#include "shapes/rotation.h"

#include <limits>

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/circle_overlap-inl.h"
}  // namespace detail
namespace {

struct CircleInRect {
  detail::Rotation<double> rot;
  Vec2 center;   // circle centre in the rectangle frame
  Vec2 nearest;  // rectangle point nearest to it
};

CircleInRect circle_in_rect(const Rect& r, const Orientation& ro, const Circle& c) {
  const detail::RectCircleLanes<double> f = detail::rect_circle_lanes(r, ro, c);
  const Vec2 p(f.px, f.py);
  return {{ro.c, ro.s}, p, detail::clamp_to_box(p, r.half_extents)};
}

}  // namespace

// Near contact the verdict is distance_rect_circle's (circle_overlap-inl.h).
bool overlap_rect_circle(const Rect& r, const Circle& c) { return overlap_rect_circle(r, Orientation::of(r.angle), c); }

bool overlap_rect_circle(const Rect& r, const Orientation& ro, const Circle& c) {
  return detail::rect_circle_overlap(detail::Scalar{}, detail::rect_circle_lanes(r, ro, c));
}

DistanceResult distance_rect_circle(const Rect& r, const Circle& c) {
  const CircleInRect f = circle_in_rect(r, Orientation::of(r.angle), c);
  const auto to_world = [&](const Vec2& p) -> Vec2 { return r.center + f.rot.apply(p); };
  const Vec2 d = f.center - f.nearest;
  const double n = d.norm();
  if (n == 0.0) return DistanceResult::touching(c.center);
  if (n <= c.radius) return DistanceResult::touching(to_world(f.nearest));
  return DistanceResult::apart(n - c.radius, to_world(f.nearest),
                               to_world(Vec2(f.center - (c.radius / n) * d)));
}

}  // namespace collide2d
