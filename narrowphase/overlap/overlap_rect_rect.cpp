// Overlap of two solid oriented rectangles by the separating-axis theorem: the four face normals
// are the only candidate axes in 2D. Computed in A's frame after subtracting centres.
// Exact up to rounding of the projected extents (a few ulps of the pair's scale); touching counts
// as overlap.

#include <collide2d/kernels.h>

#include "narrowphase/shared/frames/rect_pair_frame.h"
#include "narrowphase/shared/lanes.h"

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/overlap_rect_rect-inl.h"
}  // namespace detail

bool overlap_rect_rect(const Rect& a, const Rect& b) {
  return overlap_rect_rect(a, Orientation::of(a.angle), b, Orientation::of(b.angle));
}

bool overlap_rect_rect(const Rect& a, const Orientation& ao, const Rect& b, const Orientation& bo) {
  return detail::rect_rect_overlap(detail::rect_rect_lanes(a, ao, b, bo));
}

}  // namespace collide2d
