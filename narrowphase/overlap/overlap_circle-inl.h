// Private: the overlap tests of a circle with a circle, a rectangle or an ellipse, written once over
// lanes like overlap_rect_ellipse-inl.h (see there, and lanes.h): the one-off kernels run them on a
// double, the batch on vectors. The circle and rectangle tests decide every lane; the ellipse test
// leaves the lanes near contact to the point–ellipse root (the caller's exact fallback).
//
// Included inside a namespace, once per Highway target (no #pragma once; the includer brings
// <limits>).
#if defined(COLLIDE2D_CIRCLE_OVERLAP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_CIRCLE_OVERLAP_INL_H_
#undef COLLIDE2D_CIRCLE_OVERLAP_INL_H_
#else
#define COLLIDE2D_CIRCLE_OVERLAP_INL_H_
#endif

// The overlap verdict for a point at squared distance q from a shape grown by `reach` (a circle's
// centre against the other shape). Squares decide when they clear reach^2 by far more than their
// rounding, without a square root. Near contact the verdict is "not apart(sqrt(q))", the very test
// the matching distance query makes, so overlap and distance always agree there. The root is
// taken only when some lane needs it.
template <class D, class V, class Apart>
auto within_reach(D d, const V& q, const V& reach, const Apart& apart) {
  const V r2 = reach * reach;
  const auto far = q > r2 * Set(d, 1 + 1e-12);
  const auto near = q < r2 * Set(d, 1 - 1e-12);
  if (AllTrue(d, Or(far, near))) return near;
  return Or(near, AndNot(far, Not(apart(Sqrt(q)))));
}

// distance_circle_circle's test: apart when n - ra - rb > 0.
template <class V>
struct CirclesApart {
  V ra, rb, zero;
  auto operator()(const V& n) const { return n - ra - rb > zero; }
};

// distance_rect_circle's test: apart when n > r.
template <class V>
struct BeyondRadius {
  V r;
  auto operator()(const V& n) const { return n > r; }
};

template <class D, class V>
auto circle_circle_overlap(D d, const detail::CircleCircleLanes<V>& f) {
  return within_reach(d, f.dx * f.dx + f.dy * f.dy, f.ra + f.rb, CirclesApart<V>{f.ra, f.rb, Set(d, 0.0)});
}

// The squared distance from p to the box [-hx, hx] x [-hy, hy] (box_local.h's clamp, over lanes).
template <class V>
V squared_distance_to_box(const V& px, const V& py, const V& hx, const V& hy) {
  const V gx = px - Min(Max(px, Neg(hx)), hx);
  const V gy = py - Min(Max(py, Neg(hy)), hy);
  return gx * gx + gy * gy;
}

// In the rectangle's frame the nearest rectangle point to the centre p is p clamped to the box.
template <class D, class V>
auto rect_circle_overlap(D d, const detail::RectCircleLanes<V>& f) {
  return within_reach(d, squared_distance_to_box(f.px, f.py, f.hx, f.hy), f.r, BeyondRadius<V>{f.r});
}

// The centre p in the ellipse's frame. Certain cases first, each only when it clears r by more than
// the rounding of the distance (16 epsilon of the lengths involved), so that the root would have
// said the same: the centre inside the ellipse; the box around the ellipse beyond r; the boundary
// point q on the ray from the ellipse's centre through p (p / |(p_x / a, p_y / b)|) within r, as
// the distance is at most |p - q|; and the tangent line at q beyond r, as the ellipse lies behind
// it. The last two decide most of the pairs the first two leave, before the root.
template <class D, class V>
class CircleEllipseFilter {
 public:
  using M = decltype(V() < V());

  CircleEllipseFilter(D d, const detail::CircleEllipseLanes<V>& f) : d_(d), f_(f) {}

  detail::LaneVerdicts<M> run() {
    const V u = f_.px / f_.a, v = f_.py / f_.b;
    const V w2 = u * u + v * v;
    if (decide(out_.overlap, w2 <= k(1.0))) return out_;
    const V margin =
        k(16 * std::numeric_limits<double>::epsilon()) * (Sqrt(f_.px * f_.px + f_.py * f_.py) + f_.a + f_.b + f_.r);
    const V clear = f_.r + margin;
    if (decide(out_.separated, squared_distance_to_box(f_.px, f_.py, f_.a, f_.b) > clear * clear)) return out_;
    const V root = Sqrt(w2);
    const V qx = f_.px / root, qy = f_.py / root;
    const V ex = f_.px - qx, ey = f_.py - qy;
    if (decide(out_.overlap, Sqrt(ex * ex + ey * ey) < f_.r - margin)) return out_;
    const V gx = qx / (f_.a * f_.a), gy = qy / (f_.b * f_.b);
    const V g = Sqrt(gx * gx + gy * gy);
    decide(out_.separated, gx / g * ex + gy / g * ey > clear);
    return out_;
  }

 private:
  V k(double x) const { return Set(d_, x); }
  // Records the verdict m for the lanes no earlier test decided; true once every lane is decided.
  bool decide(M& verdict, const M& m) {
    verdict = Or(verdict, AndNot(Or(out_.separated, out_.overlap), m));
    return AllTrue(d_, Or(out_.separated, out_.overlap));
  }

  D d_;
  detail::CircleEllipseLanes<V> f_;
  detail::LaneVerdicts<M> out_{k(0.0) < k(0.0), k(0.0) < k(0.0)};
};

#endif  // COLLIDE2D_CIRCLE_OVERLAP_INL_H_
