#include "narrowphase/curved_contact.h"
#include "narrowphase/distance_point_ellipse.h"

namespace collide2d {

Contact contact_ellipse_ellipse(const Ellipse& a, const Ellipse& b) {
  const auto p = detail::EllipsePair<double>::of(a, b);
  return detail::curved_contact(p, a.center, b.center);
}

// The signed distance of the circle's centre to the ellipse (Eberly's secular equation, inside and
// out: distance_point_ellipse.h) less the radius. The normal is the ellipse's outward normal at the
// nearest point q, reversed, from the gradient (q_x / a^2, q_y / b^2): exact to rounding however
// near the centre lies to the curve, where q - p would cancel.
Contact contact_circle_ellipse(const Circle& a, const Ellipse& b) {
  const detail::Rotation<double> rot = detail::Rotation<double>::of(b.angle);
  const PointEllipseResult r = distance_point_ellipse(b.a, b.b, rot.apply_inverse(Vec2(a.center - b.center)));
  const Vec2 normal = -rot.apply(Vec2(r.closest.x() / (b.a * b.a), r.closest.y() / (b.b * b.b)).stableNormalized());
  const double separation = (r.inside ? -r.distance : r.distance) - a.radius;
  return Contact::of(separation, normal, a.center + a.radius * normal, b.center + rot.apply(r.closest));
}

}  // namespace collide2d
