// Circle–circle overlap: |c_b - c_a| against r_a + r_b, written over lanes (circle_overlap-inl.h)
// for the batch.

#include <collide2d/kernels.h>

#include "narrowphase/batch/lanes.h"

#include <limits>

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/circle_overlap-inl.h"
}  // namespace detail

// Near contact the verdict is distance_circle_circle's (circle_overlap-inl.h).
bool overlap_circle_circle(const Circle& a, const Circle& b) {
  return detail::circle_circle_overlap(detail::Scalar{}, detail::circle_circle_lanes(a, b));
}

}  // namespace collide2d
