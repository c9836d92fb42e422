// Private: the point of a core shape's core least in an ellipse's quadratic (x/a)^2 + (y/b)^2,
// written once over lanes (lanes.h): core_ellipse.cpp runs it on one pair, the batched overlap
// (overlap_batch.cpp) on Highway vectors of pairs, with the same IEEE operations in the same order,
// so that the batch's certain verdicts are the one-off test's.
//
// In the frame scaled to make the ellipse the unit disc the core is still a convex polygon (or a
// segment), and its point nearest the origin is the least point: the least of each edge's nearest
// point, or the origin itself where the core holds it strictly inside.
//
// Included inside a namespace, once per Highway target (no #pragma once; the includer brings
// <array> and <limits>).
#if defined(COLLIDE2D_LEAST_QUADRATIC_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef COLLIDE2D_LEAST_QUADRATIC_INL_H_
#undef COLLIDE2D_LEAST_QUADRATIC_INL_H_
#else
#define COLLIDE2D_LEAST_QUADRATIC_INL_H_
#endif

template <class V>
struct LeastQuadratic {
  V q;       // the least value; 0 where the core holds the ellipse's centre
  V wx, wy;  // where, in the scaled frame
  V bound;   // of q's rounding: 32 u of the largest squared scaled vertex
};

// A core's N vertex slots in the scaled frame, and the largest of their squared lengths.
template <class V, std::size_t N>
struct ScaledCore {
  std::array<V, N> wx, wy;
  V largest;
};

// x, y: the core's vertices in the ellipse's frame, every slot set (those past the count repeat the
// first, so that edge i runs from slot i to the next and an edge past the last is empty).
template <class D, class V, std::size_t N>
ScaledCore<V, N> scaled_core(D d, const std::array<V, N>& x, const std::array<V, N>& y, const V& a, const V& b) {
  const V one = Set(d, 1.0);
  const V to_x = one / a, to_y = one / b;  // two divisions rather than two per vertex
  ScaledCore<V, N> w;
  w.largest = Set(d, 0.0);
  for (std::size_t i = 0; i < N; ++i) {
    w.wx[i] = x[i] * to_x, w.wy[i] = y[i] * to_y;
    w.largest = Max(w.largest, w.wx[i] * w.wx[i] + w.wy[i] * w.wy[i]);
  }
  return w;
}

// count: the vertices, 2 for a segment and 1 for a point (one edge each, and neither holds
// anything). `slots` edges are taken: the count for one pair, every slot for a vector of pairs of
// different counts.
template <class D, class V, std::size_t N>
LeastQuadratic<V> least_quadratic(D d, const ScaledCore<V, N>& w, const V& count, int slots) {
  const V one = Set(d, 1.0), zero = Set(d, 0.0);
  const V edges = IfThenElse(count == Set(d, 2.0), one, count);
  auto holds = count >= Set(d, 3.0);
  LeastQuadratic<V> out{Set(d, std::numeric_limits<double>::infinity()), zero, zero,
                        w.largest * Set(d, 16 * std::numeric_limits<double>::epsilon())};
#pragma GCC unroll 8
  for (int i = 0; i < slots; ++i) {
    const std::size_t j = (i + 1) % N;
    const V w0x = w.wx[i], w0y = w.wy[i];
    const V ex = w.wx[j] - w0x, ey = w.wy[j] - w0y;
    const V at = Set(d, static_cast<double>(i));
    holds = And(holds, Or(at >= count, ex * Neg(w0y) - ey * Neg(w0x) > zero));
    const V length = ex * ex + ey * ey;
    const V t = IfThenElse(length > zero, Min(Max(Neg(w0x * ex + w0y * ey) / length, zero), one), zero);
    const auto end = t == one;
    const V px = IfThenElse(end, w.wx[j], w0x + t * ex), py = IfThenElse(end, w.wy[j], w0y + t * ey);
    const V q = px * px + py * py;
    const auto better = And(at < edges, q < out.q);
    out.q = IfThenElse(better, q, out.q);
    out.wx = IfThenElse(better, px, out.wx);
    out.wy = IfThenElse(better, py, out.wy);
  }
  out.q = IfThenElse(holds, zero, out.q);
  out.wx = IfThenElse(holds, zero, out.wx);
  out.wy = IfThenElse(holds, zero, out.wy);
  return out;
}

// core_ellipse_overlap's certain verdicts from the least quadratic, for a core of radius r. In the
// scaled frame the disc of radius r about a point becomes an ellipse holding the disc of radius
// r / max(a, b) and held by that of r / min(a, b), so that the solids overlap where the least point
// lies within 1 + r / max(a, b) of the centre, and are apart where it lies beyond 1 + r / min(a, b).
// Between the two, where the least point P lies outside the ellipse, the ellipse's point q on the
// ray from its centre through P is a witness of overlap within r of P, and the ellipse lies behind
// its tangent line at q: apart where every vertex (x, y) lies beyond that line by more than r. Each
// test by a slack of far more than the rounding of the exact test (64 epsilon of the pair's size,
// the squared scaled reach standing in for the reach where it passes 1) and of this one. A sharp
// core has no slack: overlapping where the quadratic is below 1 beyond its rounding (the least
// point is in both solids), apart where it is above 1 beyond it; nor has a radius the slack passes.
template <class D, class V, std::size_t N>
detail::LaneVerdicts<decltype(V() < V())> quadratic_verdicts(D d, const LeastQuadratic<V>& least,
                                                             const std::array<V, N>& x, const std::array<V, N>& y,
                                                             const V& r, const V& a, const V& b) {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const V zero = Set(d, 0.0), one = Set(d, 1.0);
  const auto rounded = r > zero;
  const V longer = Max(a, b);
  const V slack = IfThenElse(rounded, Set(d, 64 * kEps) * (r + longer) + Set(d, 8.0) * longer * least.bound, zero);
  const V inner = one + Max(r - slack, zero) / longer, outer = one + (r + slack) / Min(a, b);
  const V inner2 = inner * inner, outer2 = outer * outer;
  const V tight = IfThenElse(rounded, Set(d, 8 * kEps), zero);
  detail::LaneVerdicts<decltype(V() < V())> out{least.q > outer2 + tight * outer2 + least.bound,
                                                least.q <= inner2 - tight * inner2 - least.bound};
  const auto open = AndNot(Or(out.separated, out.overlap), And(rounded, least.q > one));
  if (AllFalse(d, open)) return out;
  const V root = Sqrt(least.q);
  const V px = least.wx * a, py = least.wy * b;
  const V to_ray = Sqrt(px * px + py * py) * (one - one / root);
  const V nx = least.wx * b, ny = least.wy * a;  // along the ellipse's normal at the ray's point
  V lowest = nx * x[0] + ny * y[0];
  for (std::size_t i = 1; i < N; ++i) lowest = Min(lowest, nx * x[i] + ny * y[i]);
  const V beyond = (lowest - (nx * px + ny * py) / root) / Sqrt(nx * nx + ny * ny);
  out.overlap = Or(out.overlap, And(open, to_ray < r - slack));
  out.separated = Or(out.separated, And(open, beyond > r + slack));
  return out;
}

// The batch's verdicts on a core and an ellipse: the core placed in the ellipse's frame as core_of()
// places it, then quadratic_verdicts(). The lanes left neither go to the one-off test.
template <class D, class V, std::size_t N>
detail::LaneVerdicts<decltype(V() < V())> core_ellipse_verdicts(D d, const detail::CoreEllipseLanes<V, N>& f) {
  std::array<V, N> x, y;
  for (std::size_t i = 0; i < N; ++i) {
    x[i] = f.ox + (f.c * f.vx[i] - f.s * f.vy[i]);
    y[i] = f.oy + (f.s * f.vx[i] + f.c * f.vy[i]);
  }
  const LeastQuadratic<V> least = least_quadratic(d, scaled_core(d, x, y, f.a, f.b), f.count, static_cast<int>(N));
  return quadratic_verdicts(d, least, x, y, f.radius, f.a, f.b);
}

#endif  // COLLIDE2D_LEAST_QUADRATIC_INL_H_
