#include "narrowphase/contact/curved_contact.h"
#include "narrowphase/ellipse/distance_point_ellipse.h"
#include "narrowphase/batch/lanes.h"

namespace collide2d {
namespace detail {
#include "narrowphase/ellipse/point_ellipse-inl.h"
}  // namespace detail

Contact contact_ellipse_ellipse(const Ellipse& a, const Ellipse& b, const ContactOptions& options) {
  return contact_ellipse_ellipse(a, Orientation::of(a.angle), b, Orientation::of(b.angle), options);
}

Contact contact_ellipse_ellipse(const Ellipse& a, const Orientation& a_orientation, const Ellipse& b,
                                const Orientation& b_orientation, const ContactOptions& options) {
  using Pair = detail::SupportPair<double, detail::EllipseSupport<double>, detail::EllipseSupport<double>>;
  const Pair p = Pair::of(a, {a_orientation.c, a_orientation.s}, b, {b_orientation.c, b_orientation.s});
  return detail::curved_contact(p, a.center, b.center, detail::deepest_direction(p, p.from_world(options.guess)));
}

// The signed distance of the circle's centre to the ellipse (Eberly's secular equation, inside and
// out: distance_point_ellipse.h) less the radius: point_ellipse-inl.h, which the batch runs on
// vectors with the same operations.
Contact contact_circle_ellipse(const Circle& a, const Ellipse& b) {
  return contact_circle_ellipse(a, b, Orientation::of(b.angle));
}

Contact contact_circle_ellipse(const Circle& a, const Ellipse& b, const Orientation& b_orientation) {
  const detail::CirclePosedEllipseLanes<double> f = detail::circle_posed_ellipse_lanes(a, b, b_orientation);
  double px, py;
  detail::circle_centre_in_ellipse_frame(f, px, py);
  const PointEllipseResult r = distance_point_ellipse(b.a, b.b, Vec2(px, py));
  return detail::circle_ellipse_contact(f, detail::nearest_on_ellipse(r)).contact();
}

}  // namespace collide2d
