// Circle–ellipse overlap through the exact point–ellipse distance (distance_point_ellipse.h), not a
// general ellipse–ellipse solver: the circle overlaps the ellipse iff its centre is within r of the
// solid ellipse. It answers without the root finder when the centre is inside the ellipse, farther than r
// from the ellipse's bounding box in the ellipse frame, within r of the boundary point on the ray
// from the ellipse's centre through the circle's, or beyond r of the tangent line there (each by
// more than the rounding of the distance). Overlap witness: the circle centre when it
// is inside the ellipse, else the nearest ellipse point.

#include <collide2d/kernels.h>

#include "narrowphase/shared/ellipse/distance_point_ellipse.h"
#include "narrowphase/shared/lanes.h"
#include "shapes/internal.h"

#include <limits>

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/overlap_circle-inl.h"
}  // namespace detail

// The centre inside the ellipse, or the point–ellipse distance within r: the same decision as
// distance_circle_ellipse, so the two always agree. Certain cases come first
// (overlap_circle-inl.h), the root only for the pairs they leave.
bool overlap_circle_ellipse(const Circle& c, const Ellipse& e) {
  return overlap_circle_ellipse(c, e, Orientation::of(e.angle));
}

bool overlap_circle_ellipse(const Circle& c, const Ellipse& e, const Orientation& eo) {
  const detail::CircleEllipseLanes<double> f = detail::circle_ellipse_lanes(c, e, eo);
  const detail::LaneVerdicts<bool> v = detail::CircleEllipseFilter<detail::Scalar, double>(detail::Scalar{}, f).run();
  return v.separated || v.overlap ? v.overlap : detail::circle_ellipse_exact(f);
}

bool detail::circle_ellipse_exact(const CircleEllipseLanes<double>& f) {
  return distance_point_ellipse(f.a, f.b, Vec2(f.px, f.py)).distance <= f.r;
}

}  // namespace collide2d
