// Private: the area of two rectangles' overlap (narrowphase/area/overlap_rect_rect.cpp gives the
// method), written once over lanes like the overlap tests (narrowphase/shared/lanes.h): the one-off
// kernel runs it on a double, the IoU batch (narrowphase/area/overlap_rect_rect_batch.cpp) on
// vectors, with the same operations in the same order.
//
// Included inside a namespace, once per Highway target (no #pragma once, no includes).
#if defined(COLLIDE2D_RECT_RECT_AREA_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_RECT_RECT_AREA_INL_H_
#undef COLLIDE2D_RECT_RECT_AREA_INL_H_
#else
#define COLLIDE2D_RECT_RECT_AREA_INL_H_
#endif

// The length inside [lo, hi] of the interval [a0, a1] or [a1, a0] and [b0, b1] or [b1, b0]: 0 where
// they do not meet.
template <class V>
V shared_length(V a0, V a1, V b0, V b1, V lo, V hi) {
  const V from = Max(Max(Min(a0, a1), Min(b0, b1)), lo), to = Min(Min(Max(a0, a1), Max(b0, b1)), hi);
  return Max(from, to) - from;
}

// One of B's edges in A's frame: its midpoint, direction (unit), the reciprocals of the direction,
// and the parameters along it (lengths from the midpoint) where its line meets A's four sides.
template <class V>
struct EdgeInA {
  V mx, my, dx, dy;
  V left, right, bottom, top;  // at x = -ax, x = ax, y = -ay, y = ay

  EdgeInA(V mx_, V my_, V dx_, V dy_, V ix, V iy, V ax, V ay)
      : mx(mx_),
        my(my_),
        dx(dx_),
        dy(dy_),
        left((Neg(ax) - mx_) * ix),
        right((ax - mx_) * ix),
        bottom((Neg(ay) - my_) * iy),
        top((ay - my_) * iy) {}
  // The length of the edge inside A, from its half length back to its half length forward.
  V inside(V half) const { return shared_length(left, right, bottom, top, Neg(half), half); }
  // Where its line meets A's side x = +-ax (the parameter given) in y, or y = +-ay in x.
  V y_at(V t) const { return my + t * dy; }
  V x_at(V t) const { return mx + t * dx; }
};

// The overlap of A's box and the box of B's centre (tx, ty) and half extents (ex, ey) in A's frame.
template <class V>
V box_overlap(V ax, V ay, V tx, V ty, V ex, V ey, V zero) {
  const V width = Min(ax, tx + ex) - Max(Neg(ax), tx - ex), height = Min(ay, ty + ey) - Max(Neg(ay), ty - ey);
  return Max(width, zero) * Max(height, zero);
}

// The area of the overlap, lane by lane, in A's frame: 0 or a little either side of it where the
// rectangles are apart or touch. B's edge k runs through its midpoint along u, v, -u, -v
// (v = perp(u)); its part of length w adds w cross(m, direction), which for these midpoints is
// +-cross(t, u) or +-cross(t, v) plus the half extent across. A's side x = ax adds ax times its
// length inside B, and so on round. The part of A's side inside B lies between the points where B's
// two pairs of parallel edge lines cross it, the very parameters that clip B's edges: each crossing
// is computed once for both, so that where edges are nearly parallel its error slides it along both
// lines alike. A rotation within 2^-60 of a whole number of right angles is taken for one: what
// that moves is far inside the rounding of the rest.
template <class D, class V>
V rect_rect_area(D d, const detail::RectRectLanes<V>& f) {
  const V zero = Set(d, 0.0), one = Set(d, 1.0), aligned = Set(d, 0x1p-60);
  const V ux = f.c, uy = f.s, vx = Neg(f.s), vy = f.c;
  const V iux = one / ux, iuy = one / uy, ivx = Neg(iuy), ivy = iux;
  const EdgeInA<V> e0(f.tx - f.by * vx, f.ty - f.by * vy, ux, uy, iux, iuy, f.ax, f.ay);
  const EdgeInA<V> e1(f.tx + f.bx * ux, f.ty + f.bx * uy, vx, vy, ivx, ivy, f.ax, f.ay);
  const EdgeInA<V> e2(f.tx + f.by * vx, f.ty + f.by * vy, Neg(ux), Neg(uy), Neg(iux), Neg(iuy), f.ax, f.ay);
  const EdgeInA<V> e3(f.tx - f.bx * ux, f.ty - f.bx * uy, Neg(vx), Neg(vy), Neg(ivx), Neg(ivy), f.ax, f.ay);
  const V cu = f.tx * uy - f.ty * ux, cv = f.tx * vy - f.ty * vx;
  const V b_edges = e0.inside(f.bx) * (cu + f.by) + e2.inside(f.bx) * (f.by - cu) + e1.inside(f.by) * (cv + f.bx) +
                    e3.inside(f.by) * (f.bx - cv);
  const V ax = f.ax, ay = f.ay, nax = Neg(f.ax), nay = Neg(f.ay);
  const V right = shared_length(e0.y_at(e0.right), e2.y_at(e2.right), e1.y_at(e1.right), e3.y_at(e3.right), nay, ay);
  const V left = shared_length(e0.y_at(e0.left), e2.y_at(e2.left), e1.y_at(e1.left), e3.y_at(e3.left), nay, ay);
  const V top = shared_length(e0.x_at(e0.top), e2.x_at(e2.top), e1.x_at(e1.top), e3.x_at(e3.top), nax, ax);
  const V bottom =
      shared_length(e0.x_at(e0.bottom), e2.x_at(e2.bottom), e1.x_at(e1.bottom), e3.x_at(e3.bottom), nax, ax);
  const V turned = (b_edges + ax * (right + left) + ay * (top + bottom)) * Set(d, 0.5);
  return IfThenElse(Abs(f.s) <= aligned, box_overlap(f.ax, f.ay, f.tx, f.ty, f.bx, f.by, zero),
                    IfThenElse(Abs(f.c) <= aligned, box_overlap(f.ax, f.ay, f.tx, f.ty, f.by, f.bx, zero), turned));
}

#endif  // COLLIDE2D_RECT_RECT_AREA_INL_H_
