// Private: the rectangle–rectangle separating-axis test (overlap_rect_rect.cpp), written once over
// lanes like overlap_rect_ellipse-inl.h (see there, and lanes.h): the one-off kernel runs it on
// a double, the batch on vectors. It is exact as computed, so no lane is ever uncertain.
//
// Included inside a namespace, once per Highway target (no #pragma once, no includes).
#if defined(COLLIDE2D_RECT_RECT_OVERLAP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_RECT_RECT_OVERLAP_INL_H_
#undef COLLIDE2D_RECT_RECT_OVERLAP_INL_H_
#else
#define COLLIDE2D_RECT_RECT_OVERLAP_INL_H_
#endif

// Whether the rectangles overlap, lane by lane: |t| within the sum of the projected half extents on
// each of the four face normals, A's (t) and B's (t turned into B's frame).
template <class V>
auto rect_rect_overlap(const detail::RectRectLanes<V>& f) {
  const V c = Abs(f.c), s = Abs(f.s);
  const V t_in_b_x = f.c * f.tx + f.s * f.ty;
  const V t_in_b_y = Neg(f.s) * f.tx + f.c * f.ty;
  return And(And(Abs(f.tx) <= f.ax + f.bx * c + f.by * s, Abs(f.ty) <= f.ay + f.bx * s + f.by * c),
             And(Abs(t_in_b_x) <= f.bx + f.ax * c + f.ay * s, Abs(t_in_b_y) <= f.by + f.ax * s + f.ay * c));
}

#endif  // COLLIDE2D_RECT_RECT_OVERLAP_INL_H_
