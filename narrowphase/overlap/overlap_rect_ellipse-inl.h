// Private: the rectangle–ellipse Minkowski filter (overlap_rect_ellipse.h says what it decides and
// why each bound holds), written once over lanes. The one-off kernel runs it on one pair
// (lanes.h: double values, bool masks); the batched kernel (overlap_batch.cpp) runs the same
// template on Highway vectors of 2 to 8 pairs. Every lane evaluates the same IEEE operations in the
// same order as the scalar instance, so the batch decides exactly what the one-off kernel decides;
// where the scalar code returned early, the lanes record the verdict of the first stage that
// decided them, and the run ends once every lane is decided.
//
// Included inside a namespace, once per Highway target (hence no #pragma once and no includes:
// the includer brings <limits>): Highway's target attributes reach only code defined between its
// HWY_BEFORE_NAMESPACE and HWY_AFTER_NAMESPACE, templates included.
#if defined(COLLIDE2D_RECT_ELLIPSE_FILTER_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_RECT_ELLIPSE_FILTER_INL_H_
#undef COLLIDE2D_RECT_ELLIPSE_FILTER_INL_H_
#else
#define COLLIDE2D_RECT_ELLIPSE_FILTER_INL_H_
#endif

template <class D>
class RectEllipseFilter {
 public:
  using V = decltype(Set(D(), 0.0));
  using M = decltype(V() < V());

  RectEllipseFilter(D d, const detail::RectEllipseLanes<V>& f) : d_(d), f_(f) {}

  detail::LaneVerdicts<M> run() {
    const V two = k(2.0);
    err_ = k(16.0 * kU) * (Abs(f_.x0) + Abs(f_.x1) + f_.e0 + f_.e1 + f_.a + f_.b);
    // The ellipse's bounding circle first: most pairs of a scene are that far apart; then the
    // certain overlap most pairs a broad phase hands over show.
    const V radius = Max(f_.a, f_.b) + err_;
    if (decide_separated(Or(Abs(f_.x0) - f_.e0 > radius, Abs(f_.x1) - f_.e1 > radius))) return out_;
    if (decide_overlap(centre_segment_shared())) return out_;
    const V l_squared[2] = {f_.a * f_.a * f_.c * f_.c + f_.b * f_.b * f_.s * f_.s,
                            f_.a * f_.a * f_.s * f_.s + f_.b * f_.b * f_.c * f_.c};
    const V x_abs[2] = {Abs(f_.x0), Abs(f_.x1)};
    const V e[2] = {f_.e0, f_.e1};
    for (int i = 0; i < 2; ++i) {
      // The grown box R': margin = e_i + l_i - |x_i|. Compared squared first (no square root) when
      // the centre is well beyond the rectangle; the root only near the decision.
      const V reach = x_abs[i] - e[i];
      const V clear = reach - two * err_;  // l_i < clear, with room for the rounding of l_i^2
      const V margin = Neg(reach) + Sqrt(l_squared[i]);
      unsure_ = Or(unsure_, margin <= err_);
      if (decide_separated(Or(And(clear > k(0.0), l_squared[i] < clear * clear), margin < Neg(err_)))) return out_;
    }
    const V one = k(1.0);
    const V inv_a2 = one / (f_.a * f_.a);
    const V inv_b2 = one / (f_.b * f_.b);
    for (const double s0 : {-1.0, 1.0}) {
      for (const double s1 : {-1.0, 1.0}) {
        if (corner_piece(k(s0), k(s1), inv_a2, inv_b2)) return out_;
      }
    }
    decide_overlap(k(0.0) <= k(0.0));  // whatever no test left unsure
    return out_;
  }

 private:
  static constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

  V k(double x) const { return Set(d_, x); }

  // Ellipse-axis coordinates of the rectangle-frame point p relative to the ellipse centre.
  void to_ellipse_axes(const V& p0, const V& p1, V& u0, V& u1) const {
    const V d0 = p0 - f_.x0, d1 = p1 - f_.x1;
    u0 = f_.c * d0 + f_.s * d1;
    u1 = Neg(f_.s) * d0 + f_.c * d1;
  }

  // Records the verdict for the lanes no earlier stage decided; true once every lane is decided.
  bool decide_separated(const M& m) {
    out_.separated = Or(out_.separated, AndNot(decided(), m));
    return AllTrue(d_, decided());
  }
  bool decide_overlap(const M& m) {
    out_.overlap = Or(out_.overlap, AndNot(Or(decided(), unsure_), m));
    return AllTrue(d_, decided());
  }
  M decided() const { return Or(out_.separated, out_.overlap); }

  // Whether the rectangle and the ellipse certainly share a point of the segment between their
  // centres: the rectangle holds it from its centre up to s_R = 1 / max_i(|x_i| / e_i), the
  // ellipse back from its centre up to s_E = 1 / |(u_0 / a, u_1 / b)| (u the rectangle's centre in
  // the ellipse's axes), and s_R + s_E > 1, written without division. Both shapes are first shrunk
  // so that the coordinates' rounding (err) cannot move a point of the smaller shapes out of the
  // true ones: the rectangle's half extents by 2 err, the ellipse about its centre by
  // 2 err / min(a, b) (which erodes it by at least 2 err; shrinking its semi-axes by 2 err would
  // not), and the last comparison keeps 16 u for its own rounding. It decides most overlapping
  // pairs, which the corner pieces would all four have to see.
  M centre_segment_shared() const {
    const V two_err = k(2.0) * err_;
    const V e0 = f_.e0 - two_err, e1 = f_.e1 - two_err;
    const V shrink = k(1.0) - two_err / Min(f_.a, f_.b);
    const V a = shrink * f_.a, b = shrink * f_.b;
    V u0, u1;
    to_ellipse_axes(k(0.0), k(0.0), u0, u1);
    const V rect = Max(Abs(f_.x0) * e1, Abs(f_.x1) * e0);       // e0 e1 / s_R
    const V ellipse = Sqrt(b * u0 * b * u0 + a * u1 * a * u1);  // a b / s_E
    const M shared = rect * (a * b) + ellipse * (e0 * e1) > rect * ellipse * k(1 + 16 * kU);
    return And(And(e0 > k(0.0), e1 > k(0.0)), And(shrink > k(0.0), shared));
  }

  // One corner P = (s0 e0, s1 e1) of the Minkowski test; see overlap_rect_ellipse.h for the
  // geometry. A piece that certainly holds the centre separates the pair; one it certainly does
  // not changes nothing; otherwise the pair is unsure. True once every lane is decided.
  bool corner_piece(const V& s0, const V& s1, const V& inv_a2, const V& inv_b2) {
    V u0, u1;
    to_ellipse_axes(s0 * f_.e0, s1 * f_.e1, u0, u1);
    // u is P - K in ellipse axes; Eberly's Delta = K - P flips the sign of the cone coordinates.
    const V q0 = Neg(u0) * inv_a2;
    const V q1 = Neg(u1) * inv_b2;
    const V z0 = s0 * (f_.c * q0 - f_.s * q1);  // s0 * (M Delta)_0
    const V z1 = s1 * (f_.s * q0 + f_.c * q1);  // s1 * (M Delta)_1
    const V q_abs = Abs(q0) + Abs(q1);
    const V two = k(2.0);
    const V z_err = two * (err_ * (inv_a2 + inv_b2) + k(8.0 * kU) * q_abs);
    const V q = u0 * u0 * inv_a2 + u1 * u1 * inv_b2;
    const V q_err = two * (two * err_ * q_abs + err_ * err_ * (inv_a2 + inv_b2) + k(8.0 * kU) * q);
    const V q_margin = q - k(1.0);
    const M outside_piece = Or(Or(z0 < Neg(z_err), z1 < Neg(z_err)), q_margin < Neg(q_err));
    const M inside_piece = And(And(z0 > z_err, z1 > z_err), q_margin > q_err);
    unsure_ = Or(unsure_, AndNot(Or(outside_piece, inside_piece), k(0.0) <= k(0.0)));
    return decide_separated(inside_piece);
  }

  D d_;
  detail::RectEllipseLanes<V> f_;
  V err_;
  detail::LaneVerdicts<M> out_{k(0.0) < k(0.0), k(0.0) < k(0.0)};
  M unsure_ = k(0.0) < k(0.0);
};

#endif  // COLLIDE2D_RECT_ELLIPSE_FILTER_INL_H_
