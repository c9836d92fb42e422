#include "narrowphase/curved_contact.h"
#include "narrowphase/distance_point_ellipse.h"
#include "narrowphase/lanes.h"

namespace collide2d {

Contact contact_ellipse_ellipse(const Ellipse& a, const Ellipse& b, const ContactOptions& options) {
  return contact_ellipse_ellipse(a, Orientation::of(a.angle), b, Orientation::of(b.angle), options);
}

Contact contact_ellipse_ellipse(const Ellipse& a, const Orientation& a_orientation, const Ellipse& b,
                                const Orientation& b_orientation, const ContactOptions& options) {
  using Pair = detail::SupportPair<double, detail::EllipseSupport<double>, detail::EllipseSupport<double>>;
  const Pair p = Pair::of(a, {a_orientation.c, a_orientation.s}, b, {b_orientation.c, b_orientation.s});
  return detail::curved_contact(p, a.center, b.center, options.guess);
}

// The signed distance of the circle's centre to the ellipse (Eberly's secular equation, inside and
// out: distance_point_ellipse.h) less the radius. The normal is the ellipse's outward normal at the
// nearest point, reversed: exact to rounding however near the centre lies to the curve, where the
// difference of the two points would cancel.
Contact contact_circle_ellipse(const Circle& a, const Ellipse& b) {
  return contact_circle_ellipse(a, b, Orientation::of(b.angle));
}

Contact contact_circle_ellipse(const Circle& a, const Ellipse& b, const Orientation& b_orientation) {
  const detail::CircleEllipseLanes<double> f = detail::circle_ellipse_lanes(a, b, b_orientation);
  return detail::circle_ellipse_contact(a, b, b_orientation, distance_point_ellipse(b.a, b.b, Vec2(f.px, f.py)));
}

Contact detail::circle_ellipse_contact(const Circle& c, const Ellipse& e, const Orientation& eo,
                                       const PointEllipseResult& r) {
  const Rotation<double> rot{eo.c, eo.s};
  const Vec2 normal = -rot.apply(r.normal);
  const double separation = (r.inside ? -r.distance : r.distance) - c.radius;
  return Contact::of(separation, normal, c.center + c.radius * normal, e.center + rot.apply(r.closest));
}

}  // namespace collide2d
