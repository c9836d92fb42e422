#include "narrowphase/curved_contact.h"

namespace collide2d {

Contact contact_rect_ellipse(const Rect& a, const Ellipse& b, const ContactOptions& options) {
  return contact_rect_ellipse(a, Orientation::of(a.angle), b, Orientation::of(b.angle), options);
}

Contact contact_rect_ellipse(const Rect& a, const Orientation& a_orientation, const Ellipse& b,
                             const Orientation& b_orientation, const ContactOptions& options) {
  using Pair = detail::SupportPair<double, detail::RectSupport<double>, detail::EllipseSupport<double>>;
  const Pair p = Pair::of(a, {a_orientation.c, a_orientation.s}, b, {b_orientation.c, b_orientation.s});
  return detail::curved_contact(p, a.center, b.center, options.guess);
}

}  // namespace collide2d
