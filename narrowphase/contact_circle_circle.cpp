#include "narrowphase/contact.h"

namespace collide2d {

// Concentric circles: every direction is a maximiser; +x is reported.
Contact contact_circle_circle(const Circle& a, const Circle& b) {
  const Vec2 delta = b.center - a.center;
  const double d = delta.norm();
  const Vec2 n = d > 0 ? Vec2(delta / d) : Vec2::UnitX();
  return Contact::of(d - a.radius - b.radius, n, a.center + a.radius * n, b.center - b.radius * n);
}

}  // namespace collide2d
