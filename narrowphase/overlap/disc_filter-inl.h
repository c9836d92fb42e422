// Private: the disc test that settles most pairs of a core shape (a polygon or a capsule) before its
// vertices are read, written once over lanes (lanes.h): the one-off overlap tests run it first on
// one pair (disc_verdict, disc_filter.cpp, called from query.cpp), the batch (overlap_batch.cpp) on
// Highway vectors of pairs, so that the batch's verdicts are the one-off's.
//
// A core shape lies within the disc of its reach about its centre and, where its core holds the
// centre, holds the disc of its inner radius about it (PolygonOutline::inner; a circle is both
// discs). Each test clears its bound by 16 epsilon of the
// pair's size, far more than the rounding of the exact tests it stands in for.
//
// Included inside a namespace, once per Highway target (no #pragma once; the includer brings
// <limits>).
#if defined(COLLIDE2D_DISC_FILTER_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_DISC_FILTER_INL_H_
#undef COLLIDE2D_DISC_FILTER_INL_H_
#else
#define COLLIDE2D_DISC_FILTER_INL_H_
#endif

// A core shape A against an ellipse: A's centre o inside the ellipse; else the ellipse's point q
// on the ray from its centre through o within A's inner disc, or, o outside the ellipse, the tangent
// line at q (the ellipse lies behind it) beyond A's reach. (A centre inside the ellipse that A's core
// does not hold, as a polygon's whose outline lies off its origin, or a segment's first point,
// settles nothing.)
template <class D, class V>
detail::LaneVerdicts<decltype(V() < V())> disc_verdicts(D d, const detail::DiscEllipseLanes<V>& f) {
  const V zero = Set(d, 0.0), one = Set(d, 1.0);
  const V margin = Set(d, 16 * std::numeric_limits<double>::epsilon()) * (Abs(f.ox) + Abs(f.oy) + f.reach + f.a + f.b);
  const V gx = f.ox - Min(Max(f.ox, Neg(f.a)), f.a), gy = f.oy - Min(Max(f.oy, Neg(f.b)), f.b);
  const V clear = f.reach + margin;
  const auto holds = f.inner >= zero;
  const V u = f.ox / f.a, v = f.oy / f.b;
  const V w2 = u * u + v * v;
  detail::LaneVerdicts<decltype(V() < V())> out{gx * gx + gy * gy > clear * clear,
                                                And(holds, w2 < one - margin / Max(f.a, f.b))};
  const auto open = Not(Or(out.separated, out.overlap));
  if (AllFalse(d, open)) return out;
  // q = o / s: o lies |o| (s - 1) / s past q, and n.o (s - 1) / (s |n|) past the tangent line, n
  // along the ellipse's normal at q (n.o > 0). Compared squared, with one square root.
  const V s = Sqrt(w2), past = s - one;
  const V nx = u * f.b, ny = v * f.a;
  const V along = (nx * f.ox + ny * f.oy) * past;
  const V held = f.inner - margin;
  const V o2 = f.ox * f.ox + f.oy * f.oy;
  const auto within = And(held > zero, o2 * past * past < held * held * w2);
  const auto beyond = And(past > zero, along * along > clear * clear * w2 * (nx * nx + ny * ny));
  out.overlap = Or(out.overlap, And(open, And(holds, within)));
  out.separated = Or(out.separated, And(open, beyond));
  return out;
}

// Two core shapes, or a core shape and a circle.
template <class D, class V>
detail::LaneVerdicts<decltype(V() < V())> disc_verdicts(D d, const detail::DiscPairLanes<V>& f) {
  const V zero = Set(d, 0.0);
  const V margin =
      Set(d, 16 * std::numeric_limits<double>::epsilon()) * (Abs(f.dx) + Abs(f.dy) + f.a_reach + f.b_reach);
  const V gap2 = f.dx * f.dx + f.dy * f.dy;
  const V clear = f.a_reach + f.b_reach + margin;
  const V held = f.a_inner + f.b_inner - margin;
  const auto both_hold = And(f.a_inner >= zero, f.b_inner >= zero);
  return {gap2 > clear * clear, And(both_hold, And(held > zero, gap2 < held * held))};
}

#endif  // COLLIDE2D_DISC_FILTER_INL_H_
