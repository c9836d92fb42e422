// Circle–circle overlap: |c_b - c_a| against r_a + r_b, written over lanes (overlap_circle-inl.h)
// for the batch.

#include <collide2d/kernels.h>

#include "narrowphase/shared/lanes.h"

#include <limits>

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/overlap_circle-inl.h"
}  // namespace detail

// Near contact the verdict is distance_circle_circle's (overlap_circle-inl.h).
bool overlap_circle_circle(const Circle& a, const Circle& b) {
  return detail::circle_circle_overlap(detail::Scalar{}, detail::circle_circle_lanes(a, b));
}

}  // namespace collide2d
