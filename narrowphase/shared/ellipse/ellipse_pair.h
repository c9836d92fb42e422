// Private: two solid ellipses seen through their exact support functions, generic over the scalar
// so that the overlap test can repeat itself in double-double when double cannot decide.
//
// For an ellipse centred at the origin and a unit direction n, the support function is
// h(n) = |(a n_u, b n_v)| (n_u, n_v the components of n on the ellipse axes), the support point is
// (a^2 n_u, b^2 n_v) / h on the axes, and the radius of curvature there is (a b)^2 / h^3. These are
// evaluated from the axis components, never from the matrix R diag(a^2, b^2) R^T, whose entries
// cancel for needles.
//
// With delta = c_B - c_A, the separation of the pair along n (A towards B) is
//   s(n) = n.delta - h_A(n) - h_B(n),
// positive exactly when the lines normal to n through the two support points separate the shapes.
// The distance of disjoint convex shapes is the largest s over all n (duality), and the shapes
// overlap when no n gives s > 0.
#pragma once

#include "narrowphase/overlap/overlap_rect_ellipse.h"  // FilterVerdict
#include "narrowphase/shared/curved/support_pair.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

namespace collide2d::detail {

// Everything here (directions, offsets, delta) is in the pair's frame: the axes of the longer
// ellipse, whose rotation is then exactly the identity (see SupportPair).
template <class Real>
struct EllipsePair : SupportPair<Real, EllipseSupport<Real>, EllipseSupport<Real>> {
  // The magnitudes of the shorter ellipse's cosine and sine in the frame, |c_f c| + |s_f s| and
  // |c_f s| + |s_f c| with (c_f, s_f) the frame's and (c, s) its own orientation: each composed
  // value lies within 4 u of its magnitude of the true one. Zero where the angles are equal (the
  // turn is then exactly the identity).
  V2<Real> turn = V2<Real>::Zero();

  static EllipsePair of(const Ellipse& a, const Ellipse& b) {
    return of(a, Rotation<Real>::of(a.angle), b, Rotation<Real>::of(b.angle));
  }
  static EllipsePair of(const Ellipse& a, const Rotation<Real>& ra, const Ellipse& b, const Rotation<Real>& rb) {
    using std::abs;
    EllipsePair p{SupportPair<Real, EllipseSupport<Real>, EllipseSupport<Real>>::of(a, ra, b, rb)};
    if (a.angle != b.angle) {
      const Rotation<Real>&f = p.frame, &o = longest(a) >= longest(b) ? rb : ra;
      p.turn = V2<Real>(abs(f.c * o.c) + abs(f.s * o.s), abs(f.c * o.s) + abs(f.s * o.c));
    }
    return p;
  }
};

// Root of f on [lo, hi] for f(lo) > 0 >= f(hi) (f returns {value, derivative}; `cur` is f(lo)):
// Newton steps from the latest point, and a step to mid(lo, hi) whenever Newton would leave the
// bracket or would not take a step under half the last one (as in rtsafe: on either side of a
// peak much sharper than its surroundings, a needle's flat side beside a far rectangle, Newton
// swung from side to side with steps of one size, and 200 of them gained 1e-6 of the bracket).
// Stops at a point where f is exactly 0, when the bracket reaches the last bits of the
// parameter, or (unless only_at_zero) when a step does. `iterations` counts evaluations.
template <class Real, class F, class Mid>
Real newton_in_bracket(F f, Real lo, Real hi, std::pair<Real, Real> cur, int& iterations, Mid mid,
                       bool only_at_zero = false) {
  using std::abs;
  const auto tiny = [](Real step, Real at) {
    return abs(step) <= 4 * std::numeric_limits<Real>::epsilon() * std::max(Real(1), abs(at));
  };
  Real t = lo;
  Real last = std::numeric_limits<Real>::infinity();  // the last step's length
  for (int k = 0; k < 200; ++k) {
    Real next = t - cur.first / cur.second;
    const bool newton = cur.second < 0 && next > lo && next < hi && abs(next - t) <= last / 2;
    // With only_at_zero, a step too small to move t (a derivative huge only locally, as at a kink)
    // gives way to the bracket instead of ending the search.
    if (!newton || (only_at_zero && tiny(next - t, t))) next = mid(lo, hi);
    if (next == lo || next == hi) break;
    const auto ev = f(next);
    ++iterations;
    const Real step = next - t;
    last = abs(step);
    t = next;
    cur = ev;
    if (ev.first > 0) {
      lo = next;
    } else if (ev.first < 0) {
      hi = next;
    } else {
      break;
    }
    if (!only_at_zero && tiny(step, t)) break;
  }
  return t;
}

template <class Real, class F>
Real newton_in_bracket(F f, Real lo, Real hi, int& iterations) {
  return newton_in_bracket(f, lo, hi, f(lo), iterations, [](Real x, Real y) { return (x + y) / 2; });
}

// The unit vector turned from n0 by the angle 2 atan(tau) (counter-clockwise for turn = 1,
// clockwise for -1): rational in tau, so the Newton iteration below pays no cos/sin per step.
// Always inlined: it sits in the climbs' inner loops, where a call costs more than its body.
template <class Real>
[[gnu::always_inline]] inline V2<Real> turned(const V2<Real>& n0, Real turn, Real tau) {
  const Real d = 1 + tau * tau;
  return ((1 - tau * tau) / d) * n0 + (turn * 2 * tau / d) * perp(n0);
}

// Halley's correction to a Newton step on s' in tau = tan(angle / 2), at tau from the step's origin
// (counted counter-clockwise): the step slope / s'' is divided by it. With s''' = -(slope +
// rho_slope) (support_pair.h), the iteration converges with the cube of the error instead of its
// square, in fewer support evaluations than Newton's. In tau, d2(s')/dtau2 = phi_tau^2 (bend tau -
// slope - rho_slope) with phi_tau = 2 / (1 + tau^2), hence the factor below. Where it leaves [1/2,
// 2] (far from the root, the cubic model no better than the quadratic), 1: the Newton step.
template <class Real>
Real halley(const Separation<Real>& e, Real tau) {
  const Real d = 1 + e.slope * (e.slope + e.rho_slope - e.bend * tau) / (2 * e.bend * e.bend);
  return d >= Real(0.5) && d <= Real(2) ? d : Real(1);
}

// The direction maximising s near n0. On the arc of separating directions, and wherever s > -(rho_A
// + rho_B), s is concave in the angle t (s'' = -(s + rho_A + rho_B)); the arc is shorter than pi.
// Turning from n0 towards increasing s, the maximiser is the first sign change of s', and every
// direction where s has fallen below s(n0) lies beyond it: safeguarded Halley steps on s' with that
// bracket, in tau = tan(t / 2) (t < pi: tau up to 1e9). From a separating n0 this is the global
// maximum, the distance. Whether n is at the maximum of s to rounding: the gap between the support
// points has no component across n beyond the rounding of the gap itself (`tolerance`, the pair's
// margin). The closest points are then exact to rounding too. Where the maximum is a kink finer
// than a double angle resolves (ellipses thinner than about 1e-8 of their length, bend ~ a^2 / b),
// the slope stays larger at the best representable angle, and this stays false.
template <class Real>
bool at_maximum(const Separation<Real>& e, Real tolerance) {
  using std::abs;
  return e.s > 0 && abs(e.slope) <= tolerance;
}

template <class Real>
struct Direction {
  V2<Real> n;
  Separation<Real> at;  // the separation along n
};

template <class Real>
Direction<Real> best_direction(const EllipsePair<Real>& p, const V2<Real>& n0, int& iterations) {
  const Separation<Real> first = p.separation(n0);
  if (first.slope == 0) return {n0, first};
  const Real floor = first.s - p.margin();
  const Real turn = first.slope > 0 ? Real(1) : Real(-1);
  Direction<Real> last{n0, first};
  Real last_tau = 0;
  const auto converged = [&p](const Separation<Real>& e) { return at_maximum(e, p.margin()); };
  const auto f = [&](Real tau) {
    last = {turned(n0, turn, tau), p.separation(turned(n0, turn, tau))};
    last_tau = tau;
    if (last.at.s < floor) return std::pair<Real, Real>(-1, 0);  // beyond the maximum: bisect
    const Real dslope = -last.at.bend * 2 / (1 + tau * tau) * halley(last.at, turn * tau);  // dt/dtau = 2 / (1 + tau^2)
    return std::pair<Real, Real>(converged(last.at) ? Real(0) : turn * last.at.slope, dslope);
  };
  if (converged(first)) return last;
  const std::pair<Real, Real> at_start(turn * first.slope, -first.bend * 2 * halley(first, Real(0)));
  // Bisect the angle, not tau: halving tau from 1e9 would take thirty steps to reach the arc. The
  // tangent of the mean of two angles is the sum of their sines over the sum of their cosines, which
  // square roots give from the tangents, exactly rounded on every platform.
  const auto mid = [](Real lo, Real hi) {
    using std::sqrt;
    const Real secant_lo = sqrt(1 + lo * lo), secant_hi = sqrt(1 + hi * hi);
    return (lo * secant_hi + hi * secant_lo) / (secant_lo + secant_hi);
  };
  const Real tau = newton_in_bracket(f, Real(0), Real(1e9), at_start, iterations, mid, true);
  Direction<Real> end = last;
  if (tau != last_tau) end = {turned(n0, turn, tau), p.separation(turned(n0, turn, tau))};
  // At a kink finer than the angle resolves the iteration can end clearly below its start.
  return end.at.s >= first.s - p.margin() ? end : Direction<Real>{n0, first};
}

template <class Real>
struct GjkVertex {
  V2<Real> w;  // point of the difference body D = B - A (relative to c_A: b - a)
  V2<Real> a;  // the point of A it came from, relative to c_A
};

template <class Real>
struct GjkOutcome {
  FilterVerdict verdict = FilterVerdict::uncertain;
  V2<Real> direction = V2<Real>::UnitX();  // separating when separated, else the most separating seen
  V2<Real> witness = V2<Real>::Zero();     // relative to c_A, within residual / 2 of both shapes
  Real residual = std::numeric_limits<Real>::infinity();
  int iterations = 0;
  Real separation = 0;  // uncertain: s at the most separating direction found (a sign within rounding)
};

// The simplex of the GJK iteration: up to three vertices and the barycentric weights of the point
// of their hull nearest the origin.
template <class Real>
struct GjkSimplex {
  GjkVertex<Real> v[3];
  Real weight[3] = {1, 0, 0};
  int count = 0;

  // The unit direction from the origin to the hull's nearest point, and the distance to it. On a
  // segment the direction is the segment's normal, exact to rounding even when the origin is
  // within rounding of the segment's line (the nearest point itself would cancel, and for thin
  // bodies the support point moves by (radius of curvature) x (direction error)).
  std::pair<V2<Real>, Real> towards_nearest() const {
    if (count == 1) {
      const Real length = v[0].w.norm();
      return {v[0].w / length, length};
    }
    V2<Real> n = perp<Real>(v[1].w - v[0].w).normalized();
    if (n.dot(v[0].w) < 0) n = -n;
    return {n, n.dot(v[0].w)};
  }
  // The weighted points of A and B (weights normalised: rounding in thin triangles can leave their
  // sum off 1) give a point of A and a point of B; their midpoint is within half their distance,
  // the residual, of both shapes.
  std::pair<V2<Real>, Real> witness() const {
    Real total = 0;
    for (int i = 0; i < count; ++i) total += weight[i];
    V2<Real> a = V2<Real>::Zero();
    V2<Real> w = V2<Real>::Zero();
    for (int i = 0; i < count; ++i) {
      a += (weight[i] / total) * v[i].a;
      w += (weight[i] / total) * v[i].w;
    }
    return {a + w / 2, w.norm()};
  }

  // Nearest point of segment (i, j) to the origin as a simplex of one or two vertices.
  GjkSimplex segment(int i, int j) const {
    const V2<Real> d = v[j].w - v[i].w;
    const Real dd = d.squaredNorm();
    const Real t = dd > 0 ? -v[i].w.dot(d) / dd : Real(0);
    if (t <= 0) return {{v[i]}, {1, 0, 0}, 1};
    if (t >= 1) return {{v[j]}, {1, 0, 0}, 1};
    return {{v[i], v[j]}, {1 - t, t, 0}, 2};
  }

  // Reduces to the face nearest the origin; true when the origin lies in the triangle, and then
  // `depth` is its distance to the nearest edge.
  bool reduce(Real& depth) {
    if (count == 2) *this = segment(0, 1);
    if (count != 3) return false;
    const Real area = cross(v[1].w - v[0].w, v[2].w - v[0].w);
    if (area != 0) {
      const Real l0 = cross(v[1].w, v[2].w) / area;
      const Real l1 = cross(v[2].w, v[0].w) / area;
      const Real l2 = cross(v[0].w, v[1].w) / area;
      if (l0 >= 0 && l1 >= 0 && l2 >= 0) {
        weight[0] = l0, weight[1] = l1, weight[2] = l2;
        using std::abs;
        depth = abs(area) *
                std::min({l0 / (v[2].w - v[1].w).norm(), l1 / (v[0].w - v[2].w).norm(), l2 / (v[1].w - v[0].w).norm()});
        return true;
      }
    }
    GjkSimplex best = segment(0, 1);
    for (const auto& [i, j] : {std::pair{1, 2}, std::pair{2, 0}}) {
      const GjkSimplex s = segment(i, j);
      if (s.towards_nearest().second < best.towards_nearest().second) best = s;
    }
    *this = best;
    return false;
  }
};

// GJK on the difference body D = B - A with the exact support functions: stops as soon as a
// direction separates by more than the rounding margin, or a triangle of D holds the origin deeper
// than it. Otherwise (D's nearest point within the margin of the origin, or no progress: for thin
// bodies a direction error of u turns into a support error of u times the radius of curvature)
// the answer is `uncertain` with the most separating direction seen.
template <class Real>
GjkOutcome<Real> gjk(const EllipsePair<Real>& p, int max_iterations = 48) {
  const Real margin = p.margin();
  GjkSimplex<Real> simplex;
  Real length = p.delta.norm();  // distance from the origin to the current point of D
  if (length == 0) return {FilterVerdict::overlap, V2<Real>::UnitX(), V2<Real>::Zero(), 0, 0};
  V2<Real> n = p.delta / length;
  V2<Real> best = n;
  Real best_s = -std::numeric_limits<Real>::infinity();
  const auto outcome = [&](FilterVerdict verdict, const V2<Real>& direction, int it) {
    GjkOutcome<Real> out{verdict, direction, V2<Real>::Zero(), std::numeric_limits<Real>::infinity(), it};
    if (simplex.count > 0) std::tie(out.witness, out.residual) = simplex.witness();
    return out;
  };
  for (int it = 1; it <= max_iterations; ++it) {
    const Separation<Real> e = p.separation(n);
    if (e.s > margin) return outcome(FilterVerdict::separated, n, it);
    if (e.s > best_s) best_s = e.s, best = n;
    // D is within `length` of the origin and no closer than s: both inside the margin is touching.
    if (length - e.s <= margin) return outcome(FilterVerdict::uncertain, best, it);
    simplex.v[simplex.count++] = {e.gap, e.offset_a};
    Real depth = 0;
    if (simplex.reduce(depth)) {
      return outcome(depth > margin ? FilterVerdict::overlap : FilterVerdict::uncertain, best, it);
    }
    const Real previous = simplex.count > 1 ? length : std::numeric_limits<Real>::infinity();
    std::tie(n, length) = simplex.towards_nearest();
    if (length <= margin || !(length < previous)) return outcome(FilterVerdict::uncertain, best, it);
  }
  return outcome(FilterVerdict::uncertain, best, max_iterations);
}

// GJK, and when it cannot decide, Newton on s from its most separating direction: near contact
// that settles separated pairs (s > margin at the maximum). For pairs that touch or overlap, the
// support points at the maximum are a second candidate witness pair (|s| apart); the witness is the
// midpoint of whichever pair is closer, so it lies within half that distance of both shapes.
template <class Real>
GjkOutcome<Real> decide(const EllipsePair<Real>& p) {
  GjkOutcome<Real> g = gjk(p);
  if (g.verdict == FilterVerdict::separated) return g;
  if (g.verdict == FilterVerdict::overlap && g.residual <= p.margin()) return g;
  const Direction<Real> best = best_direction(p, g.direction, g.iterations);
  const V2<Real>& n = best.n;
  const Separation<Real>& e = best.at;
  g.separation = e.s;
  if (g.verdict == FilterVerdict::uncertain && e.s > p.margin()) {
    g.verdict = FilterVerdict::separated;
    g.direction = n;
    return g;
  }
  if (e.gap.norm() < g.residual) {
    g.witness = (e.offset_a + p.delta - e.offset_b) / 2;
    g.residual = e.gap.norm();
  }
  return g;
}

}  // namespace collide2d::detail
