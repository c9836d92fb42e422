#include <collide2d/kernels.h>

#include "narrowphase/distance/distance_ellipse_ellipse.h"

#include "narrowphase/shared/ellipse/distance_point_ellipse.h"
#include "narrowphase/shared/ellipse/ellipse_contact.h"
#include "narrowphase/shared/ellipse/ellipse_pair.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <vector>

namespace collide2d {
namespace {

using detail::EllipsePair;
using detail::SolverReport;
using V2 = detail::V2<double>;

// A pair found apart only in double-double (double puts s at 0 or below): s at the double-double maximum,
// the certified distance between the support lines (kept positive by DistanceResult::apart), with
// A's support point and that point moved by s along n.
SolverReport separated_by_rounding(const Ellipse& a, const Ellipse& b, const detail::EllipseContact& contact,
                                   int iterations) {
  const auto pair = EllipsePair<detail::DoubleDouble>::of(a, b);
  const detail::V2<detail::DoubleDouble> n0 = pair.from_world({contact.direction.x(), contact.direction.y()});
  const auto best = detail::best_direction(pair, n0, iterations);
  const detail::DoubleDouble s = std::max(best.at.s, detail::DoubleDouble(0));
  const detail::V2<detail::DoubleDouble> pa = best.at.offset_a;
  const detail::V2<detail::DoubleDouble> pb = pa + s * best.n;
  const auto world = [&pair](const Vec2& c, const detail::V2<detail::DoubleDouble>& p) {
    const detail::V2<detail::DoubleDouble> w = pair.to_world(p);
    return Vec2(c.x() + static_cast<double>(w[0]), c.y() + static_cast<double>(w[1]));
  };
  return {DistanceResult::apart(static_cast<double>(s), world(a.center, pa), world(a.center, pb)), iterations, true};
}

// The solid distance of a pair the overlap decision found separated along contact.direction. At the
// best direction n the two support points are the closest points, their gap parallel to n to the
// rounding of its own terms. That bound is local on purpose: the pair's margin grows with the
// longest axis, and for a needle of length 1e20 it would accept a support point 16 units along the
// flat side from the closest point. Where the gap keeps a component across n (the maximum of s is
// a kink finer than the angle resolves, as for ellipses thinner than about 1e-8 of their length,
// see at_maximum), the support lines are still exact and s, the distance between them, accurate.
// The closest point then comes from the rounder shape (the thin one's support point is the one that
// jumps: at the best representable n a needle's support point can sit at its tip, where the radius
// of curvature is tiny but the point is wrong), and its partner is that point moved by s along n.
SolverReport separated(const Ellipse& a, const Ellipse& b, const EllipsePair<double>& pair,
                       const detail::EllipseContact& contact) {
  int iterations = contact.iterations;
  const auto best = detail::best_direction(pair, pair.from_world(contact.direction), iterations);
  const auto& e = best.at;
  if (!(e.s > 0)) return separated_by_rounding(a, b, contact, iterations);
  const double rounding =
      64 * std::numeric_limits<double>::epsilon() * (pair.delta.norm() + e.offset_a.norm() + e.offset_b.norm());
  // The distance is s, the certified distance between the support lines; |gap| = sqrt(s^2 + s'^2)
  // would add the rounding of the gap's component across n, which dominates when s is tiny.
  const Vec2 pa = a.center + pair.to_world(e.offset_a);
  const Vec2 pb = b.center - pair.to_world(e.offset_b);
  if (detail::at_maximum(e, rounding)) return {DistanceResult::apart(e.s, pa, pb), iterations, true};
  const V2 step = e.s * pair.to_world(best.n);
  const auto aspect = [](const Ellipse& x) { return std::max(x.a, x.b) / std::min(x.a, x.b); };
  if (aspect(a) <= aspect(b)) return {DistanceResult::apart(e.s, pa, Vec2(pa + step)), iterations, true};
  return {DistanceResult::apart(e.s, Vec2(pb - step), pb), iterations, true};
}

// g(n) = n.delta + h_B(n) - h_A(n) with its first two derivatives in the angle of n, and the two
// radii of curvature that make up the second (g'' = -g + rho_B - rho_A).
struct Containment {
  double angle;
  double g;
  double slope;
  double rho_a;
  double rho_b;
  V2 offset_a;
  V2 offset_b;
  double curvature() const { return -g + rho_b - rho_a; }
};

Containment containment(const EllipsePair<double>& p, double angle) {
  const detail::CosSin turn = detail::cos_sin(angle);
  const V2 n(turn.c, turn.s);
  const auto sa = p.A.at(n);
  const auto sb = p.B.at(n);
  const double g = n.dot(p.delta) + sb.h - sa.h;
  return {angle, g, detail::perp(n).dot(p.delta + sb.offset - sa.offset), sa.rho, sb.rho, sa.offset, sb.offset};
}

struct Extremes {
  Containment min;
  Containment max;
};

// How far B's curvature can be from A's in any direction, from how far B's axes and angle are from
// A's: bounds on |rho_B - rho_A| and on |g''| = |-n.delta + h_B'' - h_A''| (h'' = rho - h). The
// end values of each radius on an arc (bend_between) bound the difference only by the variation of
// either radius along the arc, which for nearly congruent pairs (a ring between an ellipse and its
// slightly smaller copy) dwarfs the difference itself, and halving until that bound fell below the
// rounding would take many thousands of evaluations (concentric circles, whose g is constant, the
// most). With a >= b, theta modulo pi, h^2 = a^2 cos^2 + b^2 sin^2 of the angle psi
// from the major axis and rho = (ab)^2 / h^3: |d rho / da| <= 2 rho / a <= 2 a / b, |d rho / db|
// <= 2 rho / b <= 2 a^2 / b^2, |d rho / d theta| = 3 (ab)^2 (a^2 - b^2) |sin psi cos psi| / h^5
// <= 3 a (a^2 - b^2) / b^2 (as |sin psi cos psi| / h <= |cos psi| / (a |cos psi|)), and |dh/da|,
// |dh/db| <= 1, |dh / d theta| <= a; along the straight path between the two parameter sets a and
// b stay within their end values. Besides, |h''| <= a^2 / b - b for either ellipse (its extremes at
// the ends of the axes), so |g''| <= |delta| + the two: 0 for concentric circles, where the bounds
// from the parameters' differences still allow a bump of the size of the difference.
struct Congruence {
  double rho;   // bounds |rho_B - rho_A|
  double bend;  // bounds |g''|
};

Congruence congruence_of(const EllipsePair<double>& p) {
  struct Axes {
    double a, b, theta;
  };
  const auto canonical = [](const detail::EllipseSupport<double>& e) {
    const double theta = detail::arc_tangent(e.rot.s, e.rot.c);
    return e.a >= e.b ? Axes{e.a, e.b, theta} : Axes{e.b, e.a, theta + std::numbers::pi / 2};
  };
  const Axes x = canonical(p.A), y = canonical(p.B);
  const double big = std::max(x.a, y.a), small = std::min(x.b, y.b);
  const double da = std::abs(y.a - x.a), db = std::abs(y.b - x.b);
  const double turn = std::abs(std::remainder(y.theta - x.theta, std::numbers::pi));
  const double spread = 2 * big * std::max(x.a - x.b, y.a - y.b);  // >= a^2 - b^2 along the path
  const double rho =
      2 * big / small * da + 2 * big * big / (small * small) * db + 3 * big * spread / (small * small) * turn;
  const auto roundness = [](const Axes& e) { return e.a * e.a / e.b - e.b; };  // max |h''|
  return {rho, p.delta.norm() + std::min(rho + da + db + big * turn, roundness(x) + roundness(y))};
}

// Bounds of g'' over the directions between two samples, and the most g can dip below (or rise
// above) the chord between them. The samples lie within one quarter turn of each ellipse's axes,
// where h, and with it rho = (ab)^2 / h^3, is monotone: each rho lies between its end values, and
// their difference within +-congruence.rho. With |g''| <= G, g lies within G w^2 / 8 of the chord,
// and G <= max|rho_B - rho_A| + max|g|, so G (1 - w^2 / 8) <= max|rho_B - rho_A| + max(|g_0|,
// |g_1|), which holds for w < sqrt(8); and |g''| <= congruence.bend throughout.
struct Bend {
  double lo;
  double hi;
  double dip;
};

Bend bend_between(const Containment& x, const Containment& y, const Congruence& congruence) {
  const double w = y.angle - x.angle;
  const double rho_lo = std::max(std::min(x.rho_b, y.rho_b) - std::max(x.rho_a, y.rho_a), -congruence.rho);
  const double rho_hi = std::min(std::max(x.rho_b, y.rho_b) - std::min(x.rho_a, y.rho_a), congruence.rho);
  const double bound =
      (std::max(std::abs(rho_lo), std::abs(rho_hi)) + std::max(std::abs(x.g), std::abs(y.g))) / (1 - w * w / 8);
  const double rounding = 8 * std::numeric_limits<double>::epsilon();
  const double slack = bound * (w * w / 8 + rounding);
  const double lo = std::max(rho_lo - std::max(x.g, y.g) - slack, -congruence.bend * (1 + rounding));
  const double hi = std::min(rho_hi - std::min(x.g, y.g) + slack, congruence.bend * (1 + rounding));
  return {lo, hi, std::max(std::abs(lo), std::abs(hi)) * w * w / 8};
}

// The global extrema of g, by branch and bound over arcs of directions. The arcs start between the
// axis directions of both ellipses (where the bounds of bend_between hold); an arc whose bound on
// g'' keeps one sign holds at most one extremum, found by safeguarded Newton on g' when g' changes
// sign across it; any other arc is halved while it could still hold a value below the least found
// (or above the greatest) by more than the rounding of g. Sampling alone cannot do this: two
// extrema closer than the sample spacing, or an extremum next to a sample where g' is exactly 0 (a
// symmetric pair: a circle on an ellipse's axis near the cusp of its evolute, where the least gap
// leaves the axis), hide from sign changes of g'. Stops early once the curves surely cross.
Extremes containment_extremes(const EllipsePair<double>& p, int& iterations) {
  std::vector<double> axes;
  for (const auto* e : {&p.A, &p.B}) {
    const double angle = detail::arc_tangent(e->rot.s, e->rot.c);
    for (int k = 0; k < 4; ++k) axes.push_back(std::remainder(angle + k * std::numbers::pi / 2, 2 * std::numbers::pi));
  }
  std::sort(axes.begin(), axes.end());
  axes.erase(std::unique(axes.begin(), axes.end()), axes.end());
  axes.push_back(axes.front() + 2 * std::numbers::pi);
  std::vector<Containment> at;
  for (const double t : axes) at.push_back(containment(p, t));
  iterations += static_cast<int>(at.size());
  Extremes out{at[0], at[0]};
  const auto consider = [&out](const Containment& c) {
    if (c.g < out.min.g) out.min = c;
    if (c.g > out.max.g) out.max = c;
  };
  std::vector<std::pair<Containment, Containment>> arcs;
  for (std::size_t i = 0; i + 1 < at.size(); ++i) {
    consider(at[i]);
    arcs.emplace_back(at[i], at[i + 1]);
  }
  const double rounding = std::numeric_limits<double>::epsilon() * p.scale;
  const double margin = p.margin();
  const Congruence congruence = congruence_of(p);
  while (!arcs.empty() && !(out.min.g < -margin && out.max.g > margin)) {
    const Containment x = arcs.back().first, y = arcs.back().second;  // not a structured binding: clang 14
    arcs.pop_back();                                                  // cannot capture one in the lambda
    const Bend bend = bend_between(x, y, congruence);
    const bool may_lower = std::min(x.g, y.g) - bend.dip < out.min.g - rounding;
    const bool may_raise = std::max(x.g, y.g) + bend.dip > out.max.g + rounding;
    if (!may_lower && !may_raise) continue;
    if (bend.lo > 0 || bend.hi < 0) {
      if (x.slope * y.slope < 0) {
        const double sign = x.slope > 0 ? 1.0 : -1.0;  // a maximum inside, or a minimum
        const auto f = [&](double t) {
          const Containment c = containment(p, x.angle + t);
          return std::pair<double, double>(sign * c.slope, sign * c.curvature());
        };
        consider(containment(p, x.angle + detail::newton_in_bracket(f, 0.0, y.angle - x.angle, iterations)));
      }
      continue;
    }
    const double mid = 0.5 * (x.angle + y.angle);
    if (!(mid > x.angle && mid < y.angle)) continue;
    const Containment m = containment(p, mid);
    ++iterations;
    consider(m);
    arcs.emplace_back(x, m);
    arcs.emplace_back(m, y);
  }
  return out;
}

// Level function of an ellipse: |(x_u / a, x_v / b)| - 1 for the world point x (0 on the curve).
struct Level {
  const Ellipse& e;
  detail::Rotation<double> rot;
  double operator()(const Vec2& x) const {
    const Vec2 l = rot.apply_inverse(Vec2(x - e.center));
    return detail::hypotenuse(l.x() / e.a, l.y() / e.b) - 1.0;
  }
};

// The last point of [from, to] where f is <= 0, for f(from) <= 0 < f(to): bisection to the last bit.
template <class F>
double bisect(F f, double from, double to) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (from + to);
    if (mid == from || mid == to) break;
    (f(mid) <= 0 ? from : to) = mid;
  }
  return from;
}

// A point where the two curves cross, for overlapping solids neither of which contains the other.
// Inputs: w in both solids, out_a on A's curve outside B, out_b on B's curve outside A. The segment
// w -> out_b lies in B and leaves A: where it does is a point of A's curve inside B. Between that
// point and out_a, B's level along A's curve changes sign; bisection on the parameter finds a
// crossing, exactly on A's curve and on B's to rounding.
Vec2 crossing_point(const Ellipse& a, const Ellipse& b, const Vec2& w, const Vec2& out_a, const Vec2& out_b) {
  const Level level_a{a, detail::Rotation<double>::of(a.angle)};
  const Level level_b{b, detail::Rotation<double>::of(b.angle)};
  const double s = bisect([&](double t) { return level_a(w + t * (out_b - w)); }, 0.0, 1.0);
  const auto param = [&](const Vec2& x) {
    const Vec2 l = level_a.rot.apply_inverse(Vec2(x - a.center));
    return detail::arc_tangent(l.y() / a.b, l.x() / a.a);
  };
  const auto on_a = [&](double t) -> Vec2 {
    const detail::CosSin turn = detail::cos_sin(t);
    return a.center + level_a.rot.apply(Vec2(a.a * turn.c, a.b * turn.s));
  };
  const double t_in = param(w + s * (out_b - w));
  double t_out = param(out_a);
  if (t_out < t_in) t_out += 2 * std::numbers::pi;
  return on_a(bisect([&](double t) { return level_b(on_a(t)); }, t_in, t_out));
}

SolverReport robust_boundary(const Ellipse& a, const Ellipse& b) {
  std::optional<EllipsePair<double>> lazy;
  const detail::EllipseContact contact = detail::ellipse_contact(a, b, lazy);
  const EllipsePair<double>& pair = lazy ? *lazy : lazy.emplace(EllipsePair<double>::of(a, b));
  if (!contact.overlap) return separated(a, b, pair, contact);
  int iterations = contact.iterations;
  const Extremes ex = containment_extremes(pair, iterations);
  const double margin = pair.margin();
  const bool a_in_b = ex.min.g >= -margin;
  if (!a_in_b && ex.max.g > margin) {
    const Vec2 x = crossing_point(a, b, contact.witness, a.center + pair.to_world(ex.min.offset_a),
                                  b.center + pair.to_world(ex.max.offset_b));
    return {DistanceResult::touching(x), iterations, true};
  }
  const Containment& c = a_in_b ? ex.min : ex.max;
  const Vec2 pa = a.center + pair.to_world(c.offset_a);
  // The search settles the gap to rounding but not always its direction: for a thin ring (two curves
  // of nearly one shape) the gap hardly changes over a wide arc, and the two support points can sit
  // side by side along the curves rather than across the gap. B's point is therefore the point of
  // B's curve nearest A's, so that the two lie the gap apart.
  const PointEllipseResult foot =
      distance_point_ellipse(pair.B.a, pair.B.b, pair.B.rot.apply_inverse(Vec2(c.offset_a - pair.delta)));
  const Vec2 pb = a.center + pair.to_world(Vec2(pair.delta + pair.B.rot.apply(foot.closest)));
  // The gap is the distance between the two support lines, as for separated pairs; within the
  // margin of 0 its sign is rounding, and a negative one means curves that touch or cross by less
  // than the margin (the points' distance would report the margin itself: 1.2e-14 for a ring
  // whose curves meet, in tests/accuracy/test_ellipse_ellipse.cpp). Their midpoint is then the witness,
  // within half their distance of both curves.
  const double gap = a_in_b ? c.g : -c.g;
  const DistanceResult r =
      gap > 0 ? DistanceResult::apart(gap, pa, pb) : DistanceResult::touching(Vec2(0.5 * (pa + pb)));
  return {r, iterations, true};
}

// `pair` holds the pair's frame when the caller kept the orientations, else is built on demand.
SolverReport distance_of(const Ellipse& a, const Ellipse& b, std::optional<EllipsePair<double>>& pair) {
  const detail::EllipseContact contact = detail::ellipse_contact(a, b, pair);
  if (contact.overlap) return {DistanceResult::touching(contact.witness), contact.iterations, true};
  if (!pair) pair.emplace(EllipsePair<double>::of(a, b));
  return separated(a, b, *pair, contact);
}

}  // namespace

SolverReport detail::robust_distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b) {
  std::optional<EllipsePair<double>> pair;
  return distance_of(a, b, pair);
}

SolverReport detail::robust_distance_ellipse_ellipse(const Ellipse& a, const Orientation& a_orientation,
                                                     const Ellipse& b, const Orientation& b_orientation) {
  std::optional<EllipsePair<double>> pair = EllipsePair<double>::of(a, detail::Rotation<double>::of(a_orientation), b,
                                                                    detail::Rotation<double>::of(b_orientation));
  return distance_of(a, b, pair);
}

SolverReport detail::robust_boundary_distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b) {
  return robust_boundary(a, b);
}

DistanceResult distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b) {
  return detail::robust_distance_ellipse_ellipse(a, b).result;
}

DistanceResult distance_ellipse_ellipse(const Ellipse& a, const Orientation& a_orientation, const Ellipse& b,
                                        const Orientation& b_orientation) {
  return detail::robust_distance_ellipse_ellipse(a, a_orientation, b, b_orientation).result;
}

DistanceResult boundary_distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b) {
  return detail::robust_boundary_distance_ellipse_ellipse(a, b).result;
}

}  // namespace collide2d
