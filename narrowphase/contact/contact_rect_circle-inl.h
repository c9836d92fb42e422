// Private: the rectangle–circle contact written once over lanes (lanes.h): contact_rect_circle runs
// it on a double, the batch on vectors, with the same IEEE operations in the same order, so both
// give the same bits. Every case (corner, either face, inside) is computed and the lane's own one
// selected, so that lanes of different cases share one vector. A corner less than 1e-150 away,
// whose squared distance is no normal double, is left to the one-off kernel (`general` false),
// which takes its direction from length_and_direction (unit_vector.h).
//
// Included inside a namespace, once per Highway target (no #pragma once).
#if defined(COLLIDE2D_RECT_CIRCLE_CONTACT_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_RECT_CIRCLE_CONTACT_INL_H_
#undef COLLIDE2D_RECT_CIRCLE_CONTACT_INL_H_
#else
#define COLLIDE2D_RECT_CIRCLE_CONTACT_INL_H_
#endif

// The contact in the rectangle's frame: the circle's centre p, the rectangle's point `on` nearest
// to it (or, inside, on the nearer face), the normal n and the centre's signed distance d.
template <class V>
struct RectCircleFeature {
  V px, py;
  V on_x, on_y;
  V nx, ny;
  V d;
};

template <class D, class V, class M>
RectCircleFeature<V> rect_circle_feature(D d, const detail::RectCirclePosedLanes<V>& f, M& general) {
  const V zero = Set(d, 0.0), one = Set(d, 1.0), minus_one = Set(d, -1.0);
  const V dx = f.cx - f.rx, dy = f.cy - f.ry;
  RectCircleFeature<V> out;
  out.px = f.c * dx + f.s * dy;
  out.py = Neg(f.s) * dx + f.c * dy;
  const V qx = Min(Max(out.px, Neg(f.hx)), f.hx), qy = Min(Max(out.py, Neg(f.hy)), f.hy);
  const M out_x = qx != out.px, out_y = qy != out.py;
  const M corner = And(out_x, out_y), face_x = AndNot(out_y, out_x), face_y = AndNot(out_x, out_y);
  // Outside a corner: along the corner's direction.
  const V ex = out.px - qx, ey = out.py - qy;
  const V squared = ex * ex + ey * ey;
  const V length = Sqrt(squared);
  general = Or(Not(corner), squared > Set(d, 1e-300));
  // Over a face, or inside through the nearer face: along the face normal on the centre's side.
  const V sx = IfThenElse(out.px < zero, minus_one, one), sy = IfThenElse(out.py < zero, minus_one, one);
  const V room_x = f.hx - Abs(out.px), room_y = f.hy - Abs(out.py);
  const M inside = Not(Or(out_x, out_y));
  const M along_x = Or(face_x, AndNot(face_y, And(inside, room_x <= room_y)));
  const M along_y = AndNot(along_x, Not(corner));
  out.nx = IfThenElse(corner, ex / length, IfThenElse(along_x, sx, zero));
  out.ny = IfThenElse(corner, ey / length, IfThenElse(along_y, sy, zero));
  const V face_d = IfThenElse(along_x, Abs(out.px) - f.hx, Abs(out.py) - f.hy);
  const V inside_d = Neg(IfThenElse(along_x, room_x, room_y));
  out.d = IfThenElse(corner, length, IfThenElse(inside, inside_d, face_d));
  out.on_x = IfThenElse(And(inside, along_x), sx * f.hx, qx);
  out.on_y = IfThenElse(AndNot(along_x, inside), sy * f.hy, qy);
  return out;
}

// The contact in world axes from the feature.
template <class V>
detail::ContactLanes<V> rect_circle_contact(const detail::RectCirclePosedLanes<V>& f, const RectCircleFeature<V>& e) {
  detail::ContactLanes<V> out;
  out.nx = f.c * e.nx - f.s * e.ny;
  out.ny = f.s * e.nx + f.c * e.ny;
  out.separation = e.d - f.r;
  out.ax = f.rx + (f.c * e.on_x - f.s * e.on_y);
  out.ay = f.ry + (f.s * e.on_x + f.c * e.on_y);
  out.bx = f.cx - f.r * out.nx;
  out.by = f.cy - f.r * out.ny;
  return out;
}

#endif  // COLLIDE2D_RECT_CIRCLE_CONTACT_INL_H_
