#include "narrowphase/contact/circle_circle.h"

#include <collide2d/kernels.h>

#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/frames/unit_vector.h"

namespace collide2d {

namespace detail {
namespace {

// Along the line of centres (unit_vector.h says how its direction stays unit for centres a few
// denormals apart). Concentric circles: every direction is a maximiser; +x is reported.
Contact closed_form(const Circle& a, const Circle& b, bool swapped) {
  const LengthAndDirection line = length_and_direction(b.center - a.center);
  const Vec2& n = line.direction;
  const double separation = line.length - a.radius - b.radius;
  const Vec2 on_a = a.center + a.radius * n, on_b = b.center - b.radius * n;
  return swapped ? Contact::of(separation, -n, on_b, on_a) : Contact::of(separation, n, on_a, on_b);
}

}  // namespace

Contact circle_circle_contact(const Circle& a, const Circle& b, const ContactOptions& options, bool swapped) {
  return limited(options, [&] { return closed_form(a, b, swapped); });
}

}  // namespace detail

// Without options, the closed form alone: the pair costs little more than building the options
// would.
Contact contact_circle_circle(const Circle& a, const Circle& b) { return detail::closed_form(a, b, false); }

Contact contact_circle_circle(const Circle& a, const Circle& b, const ContactOptions& options) {
  return detail::circle_circle_contact(a, b, options, false);
}

}  // namespace collide2d
