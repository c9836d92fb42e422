#include "narrowphase/contact.h"

#include <cmath>

namespace collide2d {

// Concentric circles: every direction is a maximiser; +x is reported. Centres 1e-160 apart square
// to a denormal, and a normal from norm() came out 1.00004 long (the fuzzer): below 1e-150 hypot
// takes over (it costs half the query everywhere).
Contact contact_circle_circle(const Circle& a, const Circle& b) {
  const Vec2 delta = b.center - a.center;
  const double squared = delta.squaredNorm();
  const double d = squared > 1e-300 ? std::sqrt(squared) : std::hypot(delta.x(), delta.y());
  const Vec2 n = d > 0 ? Vec2(delta / d) : Vec2::UnitX();
  return Contact::of(d - a.radius - b.radius, n, a.center + a.radius * n, b.center - b.radius * n);
}

}  // namespace collide2d
