// Green's theorem over the overlap's boundary, which is the part of each rectangle's boundary inside
// the other. Each rectangle's edges are clipped to the other in the other's frame, where that one
// is the box |x| <= h.x, |y| <= h.y and clipping a line to it is four slabs (Liang and Barsky, "A
// new concept and method for line clipping", 1984). An edge through m along the unit u, clipped to
// the lengths s0 ... s1 from m, adds cross(m + s0 u, m + s1 u) = (s1 - s0) cross(m, u) to twice the
// area about the frame's centre: no crossing point is formed and no polygon assembled, and the two
// reciprocals of the relative rotation's cosine and sine serve every slab of both rectangles. The
// cross product is the same in either frame; moving the origin of A's clipped edges from B's centre
// to A's adds cross(B's centre, their sum). Rectangles turned a whole number of right angles from
// each other overlap in a box. The kernel itself is narrowphase/area/rect_rect_area-inl.h.
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
