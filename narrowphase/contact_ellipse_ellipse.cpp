#include "narrowphase/curved_contact.h"

namespace collide2d {

Contact contact_ellipse_ellipse(const Ellipse& a, const Ellipse& b) {
  const auto p = detail::EllipsePair<double>::of(a, b);
  return detail::curved_contact(p, a.center, b.center);
}

// A circle is the ellipse with a = b; the search is the same.
Contact contact_circle_ellipse(const Circle& a, const Ellipse& b) {
  return contact_ellipse_ellipse({a.center, a.radius, a.radius, 0.0}, b);
}

}  // namespace collide2d
