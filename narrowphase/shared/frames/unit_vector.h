// Private: a vector's length and the unit vector along it, for the closed-form contacts (circle
// pairs, a rectangle's corner and a circle).
#pragma once

#include <collide2d/shapes.h>

#include "shapes/internal.h"

#include <cmath>

namespace collide2d::detail {

struct LengthAndDirection {
  double length = 0.0;
  Vec2 direction = Vec2::UnitX();  // +x for the zero vector
};

// The square root of the squared length, a third of the cost of std::hypot, wherever the square
// is a normal double. Vectors of length below 1e-150 square to a denormal, and a direction from
// norm() came out 1.00004 long (the fuzzer, two circles' centres 1e-160 apart): there hypot takes
// over. Vectors a few denormals long have a bit or two per coordinate, and dividing by their
// rounded length gave directions 0.90 to 1.41 long (the fuzzer again): there the vector is first
// scaled by its largest coordinate, exactly enough. Eigen's stableNormalized() does not serve: it
// divides by sqrt(z) * w, a product that rounds to the same bit or two. Within collide2d's range
// (coordinates within 1e50) no square overflows.
inline LengthAndDirection length_and_direction(const Vec2& v) {
  const double squared = v.squaredNorm();
  if (squared > 1e-300) {
    const double length = std::sqrt(squared);
    return {length, v / length};
  }
  const double length = hypotenuse(v.x(), v.y());
  if (!(length > 0)) return {};
  return {length, Vec2(v / v.cwiseAbs().maxCoeff()).normalized()};
}

}  // namespace collide2d::detail
