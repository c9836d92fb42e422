// Private: the nearest point of an ellipse's curve to a point, written once over lanes (lanes.h):
// distance_point_ellipse runs it on a double, the batched circle–ellipse contact on vectors, with
// the same IEEE operations in the same order, so both give the same bits. The method and its
// accuracy are in distance_point_ellipse.h; the lanes it leaves (Quadrant::general false) go to
// the closed forms of the axis cases there.
//
// Included inside a namespace, once per Highway target (no #pragma once).
#if defined(COLLIDE2D_POINT_ELLIPSE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_POINT_ELLIPSE_INL_H_
#undef COLLIDE2D_POINT_ELLIPSE_INL_H_
#else
#define COLLIDE2D_POINT_ELLIPSE_INL_H_
#endif

// The root of g for z0, z1 > 0 and r0 = (e0/e1)^2 >= 1, in t = s + 1 rather than Eberly's s:
// g(t) = (r0 z0 / (t + r0 - 1))^2 + (z1 / t)^2 - 1. For a point inside near the major axis the root
// sits at t ~ z1 / sqrt(1 - x^2), far below 1: as s = t - 1 it would keep only the absolute
// precision of s, and the closest point's y1 / (s + 1) would come out wrong (for a point 1e-17 off
// the axis near the evolute's cusp, a distance off by 1.3e-2).
//
// Newton runs on q(t) = (g(t) + 1)^(-1/2) = 1 rather than on g = 0. q is a weighted power mean of
// order -2 of t + r0 - 1 and t, hence concave and increasing (and exactly linear for a circle), so
// Newton started left of the root never steps past it and climbs monotonically: no bracket and no
// bisection. t <= r0 z0 + z1 bounds the root, and stops a step that rounding could carry past it.
//
// A lane ends when a step no longer climbs, or as soon as a step d is so short that the next one
// would round away. Why that holds: with A_k = sum of w_i x_i^(-k) (x_i = t, t + r0 - 1, all >= t),
// q''/q' = -3 (A2 A4 - A3^2) / (A2 A3), so |q''| <= 3 q' / t; q' falls as t grows, so the root
// after a step from t to t + d lies within 1.5 (r - t)^2 / t, about 1.5 d^2 / t, of the new t:
// below 2^-53 t once d <= 2^-27 t. Started from the bound max(z1, r0 z0 - (r0 - 1)), that stop
// saves the step that would only confirm the root; safeguarded Newton on g from the middle of its
// bracket takes about twice the steps. Lanes that have ended keep their t while the others go on.
template <class D, class V>
class SecularRoot {
 public:
  using M = decltype(V() < V());

  SecularRoot(D d, const V& r0, const V& z0, const V& z1)
      : d_(d),
        n0_(r0 * z0),
        z1_(z1),
        shift_(r0 - Set(d, 1.0)),
        hi_(n0_ + z1),
        t_(Max(z1, n0_ - shift_)),
        reach_(Set(d, 1.0)),
        climb_(Set(d, 0.0)),
        running_(t_ == t_) {}

  // One Newton step in every lane still running; false once none is.
  bool step() {
    const V one = Set(d_, 1.0);
    // t >= z1 > 1e-50 (the axis cases go to the closed forms), so neither reciprocal overflows.
    const V u = one / (t_ + shift_);
    const V v = one / t_;
    const V a = n0_ * u;
    const V b = z1_ * v;
    const V sum = a * a + b * b;
    // The step is (sqrt(sum) - 1) sum / (q' sum^(3/2)); the quotient is formed while the square
    // root runs rather than after it (a fifth off each step's latency, which bounds the batch).
    const V gain = sum / (a * a * u + b * b * v);
    reach_ = Sqrt(sum);
    const V next = t_ + (reach_ - one) * gain;
    climb_ = (next - t_) * v;
    const M climbs = And(running_, And(next > t_, next < hi_));
    running_ = AndNot(next - t_ <= Set(d_, 0x1p-27) * t_, climbs);
    t_ = IfThenElse(climbs, next, t_);
    return !AllFalse(d_, running_);
  }
  const V& t() const { return t_; }

  // After a step that climbed from t' to t = t' + d, how near the root r is, relative to t: r - t
  // <= w t with w = (3x^2 + 2x^3) / (c (1 + (1 + x) c) (1 + x)), c = sqrt(1 - 2x), x = d / t'
  // (infinite for x >= 1/2). Why: q' decreases and |q''| <= 3 q' / t (above), so q'(s) >= q'(t')
  // (t' / s)^3, and 1 - q(t') = q'(t') d (the Newton step) >= q(r) - q(t') >= q'(t') (t' / 2) (1 -
  // (t' / r)^2): r <= t' / c, and t' / c - t = t' (1 - (1 + x) c) / c, whose numerator is written
  // without cancellation as (1 - (1 + x)^2 (1 - 2x)) / (1 + (1 + x) c). 2^-20 more covers the
  // rounding of the bound itself. The scalar form only, for a contact to a tolerance.
  double width() const {
    if (!(climb_ < 0.5)) return std::numeric_limits<double>::infinity();
    const double x = climb_, c = std::sqrt(1 - 2 * x);
    return (1 + 0x1p-20) * (x * x * (3 + 2 * x)) / (c * (1 + (1 + x) * c) * (1 + x));
  }
  // sqrt(a_^2 + b_^2) at t' (nearest_at_root's a_ and b_): it bounds both, and |g|, for every t >= t'.
  const V& reach() const { return reach_; }

 private:
  D d_;
  V n0_, z1_, shift_, hi_, t_;
  V reach_, climb_;
  M running_;
};

// The point p = (px, py) in the ellipse's frame (semi-axes a along x, b along y), reflected into
// the first quadrant of the frame whose x axis is the major one: e0 >= e1, y = |p|, z = y / e;
// whether it lies in the solid, and whether the root serves it (`general`; else an axis case, which
// distance_point_ellipse's closed forms decide).
template <class V, class M>
struct Quadrant {
  M swap;
  V e0, e1, y0, y1, z0, z1, r0;
  M inside, general;

  template <class D>
  static Quadrant of(D d, const V& px, const V& py, const V& a, const V& b) {
    Quadrant q;
    q.swap = b > a;
    q.e0 = IfThenElse(q.swap, b, a);
    q.e1 = IfThenElse(q.swap, a, b);
    q.y0 = Abs(IfThenElse(q.swap, py, px));
    q.y1 = Abs(IfThenElse(q.swap, px, py));
    q.z0 = q.y0 / q.e0;
    q.z1 = q.y1 / q.e1;
    const V ratio = q.e0 / q.e1;
    q.r0 = ratio * ratio;
    const V rho2 = q.z0 * q.z0 + q.z1 * q.z1;
    q.inside = rho2 <= Set(d, 1.0);
    q.general = And(q.z1 > Set(d, 1e-50), And(q.y0 > Set(d, 0.0), rho2 != Set(d, 1.0)));
    return q;
  }
};

// The nearest point at the root t: (e0 a_, e1 b_) with a_ = r0 z0 / (t + r0 - 1) and b_ = z1 / t
// on the unit circle, and y minus it is (t - 1) (e1^2 / e0 a_, e1 b_): the distance is |t - 1| e1 |g|
// with g = (a_ e1 / e0, b_) the outward normal's direction, no difference of nearby points taken.
// |g| >= 1e-100 (a_^2 + b_^2 = 1 and e1 / e0 >= 1e-100 for valid sizes), so its square is normal.
template <class D, class V, class M>
detail::NearestOnEllipse<V, M> nearest_at_root(D d, const Quadrant<V, M>& q, const V& t, const V& px, const V& py) {
  const V one = Set(d, 1.0);
  const V a_ = q.r0 * q.z0 / (t + (q.r0 - one));
  const V b_ = q.z1 / t;
  const V g0 = a_ * (q.e1 / q.e0), g1 = b_;
  const V g = Sqrt(g0 * g0 + g1 * g1);
  const V n0 = g0 / g, n1 = g1 / g;
  const V q0 = q.e0 * a_, q1 = q.e1 * b_;
  detail::NearestOnEllipse<V, M> out;
  out.distance = Abs(t - one) * (q.e1 * g);
  out.qx = CopySign(IfThenElse(q.swap, q1, q0), px);
  out.qy = CopySign(IfThenElse(q.swap, q0, q1), py);
  out.nx = CopySign(IfThenElse(q.swap, n1, n0), px);
  out.ny = CopySign(IfThenElse(q.swap, n0, n1), py);
  out.inside = q.inside;
  return out;
}

// The circle's centre in the ellipse's frame (Rotation::apply_inverse of the centres' difference).
template <class V>
void circle_centre_in_ellipse_frame(const detail::CirclePosedEllipseLanes<V>& f, V& px, V& py) {
  const V dx = f.cx - f.ex, dy = f.cy - f.ey;
  px = f.c * dx + f.s * dy;
  py = Neg(f.s) * dx + f.c * dy;
}

// The circle–ellipse contact from the nearest ellipse point n to the circle's centre: the signed
// distance of the centre less the radius; the normal, from the circle to the ellipse, the ellipse's
// outward normal reversed (exact to rounding however near the centre lies to the curve, where the
// difference of the two points would cancel); the deepest points along it.
template <class V, class M>
detail::ContactLanes<V> circle_ellipse_contact(const detail::CirclePosedEllipseLanes<V>& f,
                                               const detail::NearestOnEllipse<V, M>& n) {
  detail::ContactLanes<V> out;
  out.nx = Neg(f.c * n.nx - f.s * n.ny);
  out.ny = Neg(f.s * n.nx + f.c * n.ny);
  out.separation = IfThenElse(n.inside, Neg(n.distance), n.distance) - f.r;
  out.ax = f.cx + f.r * out.nx;
  out.ay = f.cy + f.r * out.ny;
  out.bx = f.ex + (f.c * n.qx - f.s * n.qy);
  out.by = f.ey + (f.s * n.qx + f.c * n.qy);
  return out;
}

#endif  // COLLIDE2D_POINT_ELLIPSE_INL_H_
