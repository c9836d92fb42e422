// Private: the bound that spares a vertex of a convex core its roots against an ellipse
// (core_ellipse.cpp), written once over lanes (lanes.h): core_ellipse.cpp runs it on one arc of
// directions, face_supports.cpp on every vertex cone of a polygon at once, with the same IEEE
// operations in the same order.
//
// Along a unit direction u the separation of a vertex v and the ellipse is -(u.v + h(u)), h the
// ellipse's support value. Over an arc of directions from e0 counter-clockwise to e1 (a half turn at
// most), whose ends' separations are at most s, it stays at most s by any of three bounds:
// - at an end e, the ellipse holds the disc of radius r tangent at its support point q there, r its
//   least radius of curvature (ab)^2 / h^3 over the arc (h greatest at an end, or at the major axis
//   where the arc holds it), as far as the support values along the arc go: the separation is at
//   most u.(q + r e - v) - r, which is e's own separation at e (not checked, lest rounding lose
//   it), a sinusoid over the arc;
// - at most minus the least u.v less the least h over the arc, that at the arc's ends or along the
//   ellipse's minor axis where the arc holds it.
//
// Included inside a namespace, once per Highway target (no #pragma once).
#if defined(COLLIDE2D_ARC_BOUND_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_ARC_BOUND_INL_H_
#undef COLLIDE2D_ARC_BOUND_INL_H_
#else
#define COLLIDE2D_ARC_BOUND_INL_H_
#endif

// One arc and its vertex, in the ellipse's frame.
template <class V>
struct ArcLanes {
  V e0x, e0y, e1x, e1y;  // the arc's ends, unit normals of the core's faces or directions
  V q0x, q0y, q1x, q1y;  // the ellipse's support points along -e0 and -e1
  V rho0, rho1;          // its radii of curvature there
  V h0, h1;              // its support values there
  V vx, vy;              // the vertex
};

// Whether u.w <= s over the arc: at the end (endx, endy), and along w where w lies inside.
template <class D, class V>
auto within_arc(D d, const ArcLanes<V>& f, const V& endx, const V& endy, const V& wx, const V& wy, const V& s) {
  const auto at_end = Not(endx * wx + endy * wy > s);
  if (AllFalse(d, at_end)) return at_end;
  const V zero = Set(d, 0.0);
  const auto inside = And(f.e0x * wy - f.e0y * wx >= zero, wx * f.e1y - wy * f.e1x >= zero);
  return And(at_end, Or(Not(inside), And(s >= zero, wx * wx + wy * wy <= s * s)));
}

// Whether the separation of the vertex and the ellipse (semi-axes a along x, b along y) stays at
// most s over the arc, least_rho the ellipse's least radius of curvature, min(a, b)^2 / max(a, b).
template <class D, class V>
auto arc_within(D d, const ArcLanes<V>& f, const V& least_rho, const V& a, const V& b, const V& s) {
  const V zero = Set(d, 0.0);
  // The arc holds the x axis or its opposite where its ends lie on either side of it, and so for y.
  const auto holds_x = f.e0y * f.e1y <= zero, holds_y = f.e0x * f.e1x <= zero;
  const auto wide = a >= b;
  const auto holds_major = Or(And(wide, holds_x), AndNot(wide, holds_y));
  const auto holds_minor = Or(And(wide, holds_y), AndNot(wide, holds_x));
  const V r = IfThenElse(holds_major, least_rho, Min(f.rho0, f.rho1));
  const V sr = s + r;
  const V w1x = f.q1x + r * f.e1x - f.vx, w1y = f.q1y + r * f.e1y - f.vy;  // the disc at e1, checked at e0
  const auto at_e0 = within_arc(d, f, f.e0x, f.e0y, w1x, w1y, sr);
  if (AllTrue(d, at_e0)) return at_e0;
  const V w0x = f.q0x + r * f.e0x - f.vx, w0y = f.q0y + r * f.e0y - f.vy;  // and the disc at e0, at e1
  const auto discs = Or(at_e0, within_arc(d, f, f.e1x, f.e1y, w0x, w0y, sr));
  if (AllTrue(d, discs)) return discs;
  const V sh = s + IfThenElse(holds_minor, Min(a, b), Min(f.h0, f.h1));
  const V wx = Neg(f.vx), wy = Neg(f.vy);
  return Or(discs, And(f.e0x * wx + f.e0y * wy <= sh, within_arc(d, f, f.e1x, f.e1y, wx, wy, sh)));
}

#endif  // COLLIDE2D_ARC_BOUND_INL_H_
