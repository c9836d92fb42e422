// Private: the area of two rectangles' overlap (narrowphase/area/overlap_rect_rect.cpp gives the
// method), written once over lanes like the overlap tests (narrowphase/shared/lanes.h): the one-off
// kernel runs it on a double, the IoU batch (narrowphase/area/iou_batch.cpp) on vectors, with the
// same operations in the same order.
//
// Included inside a namespace, once per Highway target (no #pragma once, no includes).
#if defined(COLLIDE2D_RECT_RECT_AREA_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_RECT_RECT_AREA_INL_H_
#undef COLLIDE2D_RECT_RECT_AREA_INL_H_
#else
#define COLLIDE2D_RECT_RECT_AREA_INL_H_
#endif

// The lengths along the edge through (mx, my) with the reciprocals (ix, iy) of its unit direction
// inside the slabs |x| <= bx, |y| <= by, from its half length back to its half length forward.
template <class V>
V inside_length(V mx, V my, V ix, V iy, V half, V bx, V by) {
  const V x0 = (Neg(bx) - mx) * ix, x1 = (bx - mx) * ix;
  const V y0 = (Neg(by) - my) * iy, y1 = (by - my) * iy;
  const V s0 = Max(Max(Neg(half), Min(x0, x1)), Min(y0, y1));
  const V s1 = Min(Min(half, Max(x0, x1)), Max(y0, y1));
  return Max(s0, s1) - s0;  // 0 where the part is empty
}

// A rectangle's edges clipped to a box: twice the area they add about the box's centre, and the
// sum of their clipped vectors.
template <class V>
struct ClippedEdges {
  V twice_area;
  V sum_x, sum_y;
};

// The rectangle of centre (cx, cy), first axis (ux, uy) with reciprocals (iux, iuy), half extents
// (hx, hy), turned parallel to neither axis, clipped to the box |x| <= bx, |y| <= by. Edge k runs
// through its midpoint along u, v, -u, -v (v = perp(u)); a part of length w adds w cross(m, dir),
// which for these midpoints is +-cross(c, u) or +-cross(c, v) plus the half extent across.
template <class V>
ClippedEdges<V> clip_edges(V cx, V cy, V ux, V uy, V iux, V iuy, V hx, V hy, V bx, V by) {
  const V vx = Neg(uy), vy = ux, ivx = Neg(iuy), ivy = iux;
  const V w0 = inside_length(cx - hy * vx, cy - hy * vy, iux, iuy, hx, bx, by);
  const V w2 = inside_length(cx + hy * vx, cy + hy * vy, Neg(iux), Neg(iuy), hx, bx, by);
  const V w1 = inside_length(cx + hx * ux, cy + hx * uy, ivx, ivy, hy, bx, by);
  const V w3 = inside_length(cx - hx * ux, cy - hx * uy, Neg(ivx), Neg(ivy), hy, bx, by);
  const V cu = cx * uy - cy * ux, cv = cx * vy - cy * vx;
  const V along = w0 - w2, across = w1 - w3;
  return {w0 * (cu + hy) + w2 * (hy - cu) + w1 * (cv + hx) + w3 * (hx - cv), along * ux + across * vx,
          along * uy + across * vy};
}

// The overlap of A's box and the box of B's centre (tx, ty) and half extents (ex, ey) in A's frame.
template <class V>
V box_overlap(V ax, V ay, V tx, V ty, V ex, V ey, V zero) {
  const V width = Min(ax, tx + ex) - Max(Neg(ax), tx - ex), height = Min(ay, ty + ey) - Max(Neg(ay), ty - ey);
  return Max(width, zero) * Max(height, zero);
}

// The area of the overlap, lane by lane: 0 or a little either side of it where the rectangles are
// apart or touch. A rotation within 2^-60 of a whole number of right angles is taken for one: what
// that moves is far inside the rounding of the rest.
template <class D, class V>
V rect_rect_area(D d, const detail::RectRectLanes<V>& f) {
  const V zero = Set(d, 0.0), one = Set(d, 1.0), aligned = Set(d, 0x1p-60);
  const V ic = one / f.c, is = one / f.s;
  const ClippedEdges<V> b_in_a = clip_edges(f.tx, f.ty, f.c, f.s, ic, is, f.bx, f.by, f.ax, f.ay);
  // A's centre in B's frame, and A's edges clipped there.
  const V ax_in_b = Neg(f.c * f.tx + f.s * f.ty), ay_in_b = Neg(Neg(f.s) * f.tx + f.c * f.ty);
  const ClippedEdges<V> a_in_b = clip_edges(ax_in_b, ay_in_b, f.c, Neg(f.s), ic, Neg(is), f.ax, f.ay, f.bx, f.by);
  // Their sum turned into A's axes, for the move of their origin from B's centre to A's.
  const V sum_x = f.c * a_in_b.sum_x - f.s * a_in_b.sum_y, sum_y = f.s * a_in_b.sum_x + f.c * a_in_b.sum_y;
  const V turned = (b_in_a.twice_area + a_in_b.twice_area + (f.tx * sum_y - f.ty * sum_x)) * Set(d, 0.5);
  return IfThenElse(Abs(f.s) <= aligned, box_overlap(f.ax, f.ay, f.tx, f.ty, f.bx, f.by, zero),
                    IfThenElse(Abs(f.c) <= aligned, box_overlap(f.ax, f.ay, f.tx, f.ty, f.by, f.bx, zero), turned));
}

#endif  // COLLIDE2D_RECT_RECT_AREA_INL_H_
