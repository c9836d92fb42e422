// A convex core and an ellipse, where the pair has no kernel of its own: apart, the global maximum
// of the separation (core_ellipse.h) less the core's radius; overlapping, a point of both.
#include "narrowphase/shared/cores/core_ellipse.h"

#include <limits>

namespace collide2d::detail {

DistanceResult core_ellipse_distance(const CoreEllipse& p) {
  const CoreEllipseVerdict v = verdict(p);
  if (v.overlapping) {
    // The least point is in the ellipse, unless a rounded core's reach decided.
    const Peak d = v.least_inside ? v.deepest : deepest_after(p, v);
    const Vec2 witness = d.s == -std::numeric_limits<double>::infinity() ? v.least_point : d.s <= 0.0 ? d.on_a : d.on_e;
    return DistanceResult::touching(p.world_point(witness));
  }
  const Peak d = deepest_after(p, v);
  const double r = p.core.radius;
  return DistanceResult::apart(d.s - r, p.world_point(Vec2(d.on_a + r * d.u)), p.world_point(d.on_e));
}

}  // namespace collide2d::detail
