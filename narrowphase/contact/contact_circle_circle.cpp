#include <collide2d/kernels.h>
#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/frames/unit_vector.h"

namespace collide2d {

// Along the line of centres (unit_vector.h says how its direction stays unit for centres a few
// denormals apart). Concentric circles: every direction is a maximiser; +x is reported. Without
// options, the closed form alone: the pair costs little more than building the options would.
Contact contact_circle_circle(const Circle& a, const Circle& b) {
  const detail::LengthAndDirection line = detail::length_and_direction(b.center - a.center);
  const Vec2& n = line.direction;
  return Contact::of(line.length - a.radius - b.radius, n, a.center + a.radius * n, b.center - b.radius * n);
}

Contact contact_circle_circle(const Circle& a, const Circle& b, const ContactOptions& options) {
  return detail::limited(options, [&] { return contact_circle_circle(a, b); });
}

}  // namespace collide2d
