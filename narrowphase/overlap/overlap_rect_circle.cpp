// Rectangle–circle overlap: the closed form of distance_rect_circle, the circle centre in the
// rectangle's frame clamped to the box, written over lanes (overlap_circle-inl.h) for the batch.

#include <collide2d/kernels.h>

#include "narrowphase/shared/lanes.h"

#include <limits>

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/overlap_circle-inl.h"
}  // namespace detail

// Near contact the verdict is distance_rect_circle's (overlap_circle-inl.h).
bool overlap_rect_circle(const Rect& r, const Circle& c) { return overlap_rect_circle(r, Orientation::of(r.angle), c); }

bool overlap_rect_circle(const Rect& r, const Orientation& ro, const Circle& c) {
  return detail::rect_circle_overlap(detail::Scalar{}, detail::rect_circle_lanes(r, ro, c));
}

}  // namespace collide2d
