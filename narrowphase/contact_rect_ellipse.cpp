#include "narrowphase/curved_contact.h"

namespace collide2d {

Contact contact_rect_ellipse(const Rect& a, const Ellipse& b) {
  using Pair = detail::SupportPair<double, detail::RectSupport<double>, detail::EllipseSupport<double>>;
  const Pair p = Pair::of(a, b);
  return detail::curved_contact(p, a.center, b.center);
}

}  // namespace collide2d
