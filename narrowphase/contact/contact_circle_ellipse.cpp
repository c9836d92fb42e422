#include <collide2d/kernels.h>

#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/ellipse/distance_point_ellipse.h"
#include "narrowphase/shared/lanes.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace collide2d {
namespace detail {
#include "narrowphase/shared/ellipse/point_ellipse-inl.h"
}  // namespace detail

// The signed distance of the circle's centre to the ellipse (Eberly's secular equation, inside and
// out: distance_point_ellipse.h) less the radius: point_ellipse-inl.h, which the batch runs on
// vectors with the same operations. With a tolerance, its Newton's steps stop as soon as
// distance_point_ellipse_within certifies the contact; the ellipse's point is then the circle's
// moved by the separation along the normal, so that their difference stays separation * normal.
Contact contact_circle_ellipse(const Circle& a, const Ellipse& b, const ContactOptions& options) {
  return contact_circle_ellipse(a, b, Orientation::of(b.angle), options);
}

Contact contact_circle_ellipse(const Circle& a, const Ellipse& b, const Orientation& b_orientation,
                               const ContactOptions& options) {
  const detail::CirclePosedEllipseLanes<double> f = detail::circle_posed_ellipse_lanes(a, b, b_orientation);
  double px, py;
  detail::circle_centre_in_ellipse_frame(f, px, py);
  const Vec2 p(px, py);
  if (detail::has_limit(options)) {
    const double floor = distance_floor(b.a, b.b, p) - a.radius;
    if (detail::beyond_limit(floor, std::abs(px) + std::abs(py) + b.a + b.b + a.radius, options))
      return Contact::beyond(floor);
  }
  if (options.tolerance > 0) {
    const double angle = options.tolerance / std::max({a.radius, b.a, b.b});
    if (const auto near = distance_point_ellipse_within(b.a, b.b, p, a.radius, options.tolerance, angle)) {
      detail::ContactLanes<double> c = detail::circle_ellipse_contact(f, detail::nearest_on_ellipse(near->near));
      c.bx = c.ax + c.separation * c.nx;
      c.by = c.ay + c.separation * c.ny;
      return c.contact();
    }
  }
  const PointEllipseResult r = distance_point_ellipse(b.a, b.b, p);
  return detail::circle_ellipse_contact(f, detail::nearest_on_ellipse(r)).contact();
}

}  // namespace collide2d
