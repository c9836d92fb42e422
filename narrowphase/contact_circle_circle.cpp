#include "narrowphase/contact.h"

#include <cmath>

namespace collide2d {

// Concentric circles: every direction is a maximiser; +x is reported. Centres 1e-160 apart square
// to a denormal, and a normal from norm() came out 1.00004 long (the fuzzer): below 1e-150 hypot
// takes over (it costs half the query everywhere). Centres a few denormals apart have a difference
// of a bit or two, and dividing it by its rounded length gave normals 0.90 to 1.41 long (the
// fuzzer again): there the difference is first scaled by its largest coordinate, exactly enough.
// Eigen's stableNormalized() does not serve: it divides by sqrt(z) * w, a product that rounds to
// the same bit or two.
Contact contact_circle_circle(const Circle& a, const Circle& b) {
  const Vec2 delta = b.center - a.center;
  const double squared = delta.squaredNorm();
  const bool tiny = !(squared > 1e-300);
  const double d = tiny ? std::hypot(delta.x(), delta.y()) : std::sqrt(squared);
  const Vec2 n = !tiny ? Vec2(delta / d) : d > 0 ? Vec2(delta / delta.cwiseAbs().maxCoeff()).normalized() : Vec2::UnitX();
  return Contact::of(d - a.radius - b.radius, n, a.center + a.radius * n, b.center - b.radius * n);
}

}  // namespace collide2d
