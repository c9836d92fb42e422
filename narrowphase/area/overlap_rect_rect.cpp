// Green's theorem over the overlap's boundary, which is the part of each rectangle's boundary inside
// the other, in A's frame, where A is the box |x| <= ax, |y| <= ay and clipping a line to it is four
// slabs (Liang and Barsky, "A new concept and method for line clipping", 1984). An edge of B through
// m along the unit u, clipped to the lengths s0 ... s1 from m, adds cross(m + s0 u, m + s1 u) =
// (s1 - s0) cross(m, u) to twice the area about A's centre; a side of A adds its length inside B
// times its distance from the centre, that length read from where B's edge lines cross the side:
// the same slab parameters, so that each crossing is computed once for both curves. No crossing
// point is formed, no polygon assembled, and the reciprocals of the relative rotation's cosine and
// sine serve every slab. Rectangles turned a whole number of right angles from each other overlap
// in a box. The kernel is narrowphase/area/rect_rect_area-inl.h.
#include "narrowphase/area/overlap_rect_rect.h"

#include "narrowphase/shared/frames/rect_pair_frame.h"
#include "narrowphase/shared/lanes.h"

namespace collide2d::detail {
#include "narrowphase/area/rect_rect_area-inl.h"
}  // namespace collide2d::detail

namespace collide2d::detail::areas {

double rect_rect_area(const Rect& a, const Rect& b) {
  return detail::rect_rect_area(Scalar{}, rect_rect_lanes(a, Orientation::of(a.angle), b, Orientation::of(b.angle)));
}

}  // namespace collide2d::detail::areas
