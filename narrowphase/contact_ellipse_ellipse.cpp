#include "narrowphase/curved_contact.h"
#include "narrowphase/distance_point_ellipse.h"

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
// nearest point q, reversed, from the gradient (q_x / a^2, q_y / b^2): exact to rounding however
// near the centre lies to the curve, where q - p would cancel.
Contact contact_circle_ellipse(const Circle& a, const Ellipse& b) {
  return contact_circle_ellipse(a, b, Orientation::of(b.angle));
}

Contact contact_circle_ellipse(const Circle& a, const Ellipse& b, const Orientation& b_orientation) {
  const detail::Rotation<double> rot{b_orientation.c, b_orientation.s};
  const PointEllipseResult r = distance_point_ellipse(b.a, b.b, rot.apply_inverse(Vec2(a.center - b.center)));
  const Vec2 normal = -rot.apply(Vec2(r.closest.x() / (b.a * b.a), r.closest.y() / (b.b * b.b)).stableNormalized());
  const double separation = (r.inside ? -r.distance : r.distance) - a.radius;
  return Contact::of(separation, normal, a.center + a.radius * normal, b.center + rot.apply(r.closest));
}

}  // namespace collide2d
