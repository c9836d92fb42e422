// Private: the algebraic overlap test of two ellipses, written once over lanes (lanes.h): the
// one-off kernel (overlap_ellipse_ellipse.cpp) runs it on one pair, the batch (overlap_batch.cpp)
// on Highway vectors, with the same IEEE operations in the same order.
//
// An ellipse is the conic X^T Q X <= 0 in homogeneous coordinates, Q = [[M, -Mc], [-c^T M, c^T M c
// - 1]]. The pencil's characteristic cubic f(l) = det(l Q_A - Q_B) has f(0) = det M_B > 0 and a
// negative leading coefficient, so at least one positive root; the ellipses are apart exactly when
// its other two roots are real, distinct and negative, touch when they coincide, and overlap
// otherwise (a complex pair, or three positive roots). This is the planar case of Wang, Wang and
// Kim's separation condition for ellipsoids ("An algebraic condition for the separation of two
// ellipsoids", Computer Aided Geometric Design 18, 2001; the sign convention agrees with the GJK
// kernel's verdicts, which the batch tests compare on random and hard-case pairs). In A's frame,
// lengths in units of A's semi-axis a, with B's centre at d there and at g in B's own axes, k =
// (a_A / b_A)^2, delta_i = (a_A / B's semi-axis i)^2, B turned by (c, s) relative to A, and q_A,
// q_B each ellipse's quadratic at the other's centre, expanding the determinant gives
//   f(l) = -k l^3 + (T - k q_B) l^2 + (delta_1 delta_2 q_A - T) l + delta_1 delta_2,
//   T = delta_1 (s^2 + k c^2) + delta_2 (c^2 + k s^2)      (= trace(adj(M_A) M_B), no cancellation),
//   q_A = d_0^2 + k d_1^2 - 1,   q_B = delta_1 g_0^2 + delta_2 g_1^2 - 1.
// With three distinct real roots (discriminant > 0) the number of positive ones is the number of
// sign changes of (-, c2, c1, +) (Descartes, exact for real-rooted cubics): apart when c2 < 0 or
// c1 > 0; with a complex pair (discriminant < 0) they overlap.
//
// Certainty: each quantity x comes with a magnitude X >= |x| (the same operations on absolute
// values) and carries at most e u X of error, e counted through the operations (a sum adds 1 to the
// larger e of its terms, a product adds 1 to their sum; the inputs: coordinates' differences 1,
// each cosine and sine 2, as Orientation::of's are within an ulp). That gives e <= 7 for d and g,
// 21 for q_A and q_B, 23 for T, 26 for c2, 30 for c1 and 119 for the discriminant; a sign is
// trusted only beyond about twice that (2^-45 X for the discriminant, 2^-47 X for c2 and c1), and
// only where every coefficient's magnitude lies in [1e-70, 1e70], so that no product of four
// over- or underflows. Anything else is uncertain: the caller's exact kernel decides it.
//
// Needles of aspect beyond 1e6 are left to that kernel, whatever the bound says: not for this
// test's sake, but so that overlap and the distance query, which shares that kernel's path, agree.
// For needles the two may differ within the rounding of the pair's scale: for a needle of aspect
// 1.3e33 and half-length 6.4 with a speck 5e-33 across sitting 9.5e-34 above its side, this test
// says apart, rightly, and that path overlapping (a gap of 2e-34 of the scale, far below what
// either query promises; the fuzz corpus holds the pair).
//
// Included inside a namespace, once per Highway target (no #pragma once).
#if defined(COLLIDE2D_ELLIPSE_CUBIC_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_ELLIPSE_CUBIC_INL_H_
#undef COLLIDE2D_ELLIPSE_CUBIC_INL_H_
#else
#define COLLIDE2D_ELLIPSE_CUBIC_INL_H_
#endif

template <class D, class V>
auto ellipse_cubic_verdicts(D d, const detail::EllipseEllipseLanes<V>& f) {
  const V one = Set(d, 1.0);
  // B's centre in A's axes (d) and in its own (g), in units of A's semi-axis a, with magnitudes.
  const V unit = one / f.aa;
  const V d0 = (f.ca * f.dx + f.sa * f.dy) * unit, d1 = (f.ca * f.dy - f.sa * f.dx) * unit;
  const V g0 = (f.cb * f.dx + f.sb * f.dy) * unit, g1 = (f.cb * f.dy - f.sb * f.dx) * unit;
  const V ax = Abs(f.dx), ay = Abs(f.dy);
  const V m_d0 = (Abs(f.ca) * ax + Abs(f.sa) * ay) * unit, m_d1 = (Abs(f.ca) * ay + Abs(f.sa) * ax) * unit;
  const V m_g0 = (Abs(f.cb) * ax + Abs(f.sb) * ay) * unit, m_g1 = (Abs(f.cb) * ay + Abs(f.sb) * ax) * unit;
  const V ratio = f.aa / f.ab, ratio1 = f.aa / f.ba, ratio2 = f.aa / f.bb;
  const V k = ratio * ratio, delta1 = ratio1 * ratio1, delta2 = ratio2 * ratio2;
  // B's turn relative to A.
  const V c = f.ca * f.cb + f.sa * f.sb, s = f.ca * f.sb - f.sa * f.cb;
  const V m_c = Abs(f.ca * f.cb) + Abs(f.sa * f.sb), m_s = Abs(f.ca * f.sb) + Abs(f.sa * f.cb);
  const V trace = delta1 * (s * s + k * (c * c)) + delta2 * (c * c + k * (s * s));
  const V m_trace = delta1 * (m_s * m_s + k * (m_c * m_c)) + delta2 * (m_c * m_c + k * (m_s * m_s));
  const V q_a = (d0 * d0 + k * (d1 * d1)) - one, m_q_a = (m_d0 * m_d0 + k * (m_d1 * m_d1)) + one;
  const V q_b = (delta1 * (g0 * g0) + delta2 * (g1 * g1)) - one;
  const V m_q_b = (delta1 * (m_g0 * m_g0) + delta2 * (m_g1 * m_g1)) + one;
  const V c3 = Neg(k), c0 = delta1 * delta2;
  const V c2 = trace - k * q_b, m_c2 = m_trace + k * m_q_b;
  const V c1 = c0 * q_a - trace, m_c1 = c0 * m_q_a + m_trace;
  const V c2c2 = c2 * c2, c1c1 = c1 * c1;
  const V disc = (((Set(d, 18.0) * (((c3 * c2) * c1) * c0) - Set(d, 4.0) * ((c2c2 * c2) * c0)) + c2c2 * c1c1) -
                  Set(d, 4.0) * (c3 * (c1c1 * c1))) -
                 Set(d, 27.0) * ((c3 * c3) * (c0 * c0));
  const V m_disc = Set(d, 18.0) * (((k * m_c2) * m_c1) * c0) + Set(d, 4.0) * (((m_c2 * m_c2) * m_c2) * c0) +
                   (m_c2 * m_c2) * (m_c1 * m_c1) + Set(d, 4.0) * (k * ((m_c1 * m_c1) * m_c1)) +
                   Set(d, 27.0) * ((k * k) * (c0 * c0));
  const auto within = [&](const V& x, double bound) { return And(x >= Set(d, 1 / bound), x <= Set(d, bound)); };
  const auto ranged = And(And(within(c0, 1e70), within(m_c2, 1e70)),
                          And(within(m_c1, 1e70), And(within(k, 1e12), within(delta1 / delta2, 1e12))));
  const auto sure = And(ranged, Abs(disc) > Set(d, 0x1p-45) * m_disc);
  const V zero = Set(d, 0.0);
  const auto c2_negative = c2<Neg(Set(d, 0x1p-47) * m_c2), c2_positive = c2> Set(d, 0x1p-47) * m_c2;
  const auto c1_positive = c1 > Set(d, 0x1p-47) * m_c1, c1_negative = c1 < Neg(Set(d, 0x1p-47) * m_c1);
  const auto real_roots = And(sure, disc > zero);
  detail::LaneVerdicts<decltype(disc > zero)> out;
  out.separated = And(real_roots, Or(c2_negative, c1_positive));
  out.overlap = Or(And(sure, disc < zero), And(real_roots, And(c2_positive, c1_negative)));
  return out;
}

#endif  // COLLIDE2D_ELLIPSE_CUBIC_INL_H_
