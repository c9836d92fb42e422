#include "narrowphase/distance_ellipse_ellipse.h"

#include "narrowphase/ellipse_contact.h"
#include "narrowphase/ellipse_pair.h"
#include "narrowphase/ellipse_seed_solvers.h"

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
using V2 = detail::V2<double>;

// A pair found apart only in long double (double puts s at 0 or below): s at the long-double maximum,
// the certified distance between the support lines (kept positive by DistanceResult::apart), with
// A's support point and that point moved by s along n.
SolverReport separated_by_rounding(const Ellipse& a, const Ellipse& b, const detail::EllipseContact& contact,
                                   int iterations) {
  const auto pair = EllipsePair<long double>::of(a, b);
  const detail::V2<long double> n0 = pair.from_world({contact.direction.x(), contact.direction.y()});
  const auto best = detail::best_direction(pair, n0, iterations);
  const long double s = std::max(best.at.s, 0.0L);
  const detail::V2<long double> pa = best.at.offset_a;
  const detail::V2<long double> pb = pa + s * best.n;
  const auto world = [&pair](const Vec2& c, const detail::V2<long double>& p) {
    const detail::V2<long double> w = pair.to_world(p);
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
  const double rounding = 64 * std::numeric_limits<double>::epsilon() *
                          (pair.delta.norm() + e.offset_a.norm() + e.offset_b.norm());
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

// g(n) = n.delta + h_B(n) - h_A(n) with its first two derivatives in the angle of n.
struct Containment {
  double g;
  double slope;
  double curvature;
  V2 offset_a;
  V2 offset_b;
};

Containment containment(const EllipsePair<double>& p, double angle) {
  const V2 n(std::cos(angle), std::sin(angle));
  const auto sa = p.A.at(n);
  const auto sb = p.B.at(n);
  const double g = n.dot(p.delta) + sb.h - sa.h;
  return {g, detail::perp(n).dot(p.delta + sb.offset - sa.offset), -g + sb.rho - sa.rho, sa.offset, sb.offset};
}

// Angles, in the pair's frame, of the outward normals of e at evenly spaced parameter values.
void normal_angles(const detail::EllipseSupport<double>& e, int count, std::vector<double>& out) {
  const double angle = std::atan2(e.rot.s, e.rot.c);
  for (int k = 0; k < count; ++k) {
    const double t = 2 * std::numbers::pi * k / count;
    out.push_back(angle + std::atan2(e.a * std::sin(t), e.b * std::cos(t)));
  }
}

struct Extremes {
  Containment min;
  Containment max;
};

// The global extrema of g: sampled, then each bracketed sign change of g' polished.
Extremes containment_extremes(const EllipsePair<double>& p, int& iterations) {
  constexpr int kSamples = 32;
  std::vector<double> angles;
  for (int k = 0; k < kSamples; ++k) angles.push_back(2 * std::numbers::pi * k / kSamples);
  normal_angles(p.A, kSamples, angles);
  normal_angles(p.B, kSamples, angles);
  for (double& t : angles) t = std::remainder(t, 2 * std::numbers::pi);
  std::sort(angles.begin(), angles.end());
  std::vector<Containment> at;
  for (const double t : angles) at.push_back(containment(p, t));
  iterations += static_cast<int>(at.size());
  Extremes out{at[0], at[0]};
  const auto consider = [&out](const Containment& c) {
    if (c.g < out.min.g) out.min = c;
    if (c.g > out.max.g) out.max = c;
  };
  for (std::size_t i = 0; i < at.size(); ++i) {
    consider(at[i]);
    const std::size_t j = (i + 1) % at.size();
    const double lo = angles[i];
    const double width = j == 0 ? angles[0] + 2 * std::numbers::pi - lo : angles[j] - lo;
    const double sign = at[i].slope < 0 && at[j].slope > 0 ? -1.0 : at[i].slope > 0 && at[j].slope < 0 ? 1.0 : 0.0;
    if (sign == 0 || width <= 0) continue;
    const auto f = [&](double t) {
      const Containment c = containment(p, lo + t);
      return std::pair<double, double>(sign * c.slope, sign * c.curvature);
    };
    consider(containment(p, lo + detail::newton_in_bracket(f, 0.0, width, iterations)));
  }
  return out;
}

// Level function of an ellipse: |(x_u / a, x_v / b)| - 1 for the world point x (0 on the curve).
struct Level {
  const Ellipse& e;
  detail::Rotation<double> rot;
  double operator()(const Vec2& x) const {
    const Vec2 l = rot.apply_inverse(Vec2(x - e.center));
    return std::hypot(l.x() / e.a, l.y() / e.b) - 1.0;
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
    return std::atan2(l.y() / a.b, l.x() / a.a);
  };
  const auto on_a = [&](double t) -> Vec2 {
    return a.center + level_a.rot.apply(Vec2(a.a * std::cos(t), a.b * std::sin(t)));
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
  const Vec2 pb = b.center + pair.to_world(c.offset_b);
  const double gap = (pair.delta + c.offset_b - c.offset_a).norm();
  const DistanceResult r = gap > 0 ? DistanceResult::apart(gap, pa, pb) : DistanceResult::touching(pa);
  return {r, iterations, true};
}

}  // namespace

SolverReport distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b, EllipseDistanceMethod method) {
  std::optional<EllipsePair<double>> pair;
  const detail::EllipseContact contact = detail::ellipse_contact(a, b, pair);
  if (contact.overlap) return {DistanceResult::touching(contact.witness), contact.iterations, true};
  switch (method) {
    case EllipseDistanceMethod::gradient: return detail::gradient_descent_curves(a, b);
    case EllipseDistanceMethod::polynomial: return detail::polynomial_curves(a, b);
    case EllipseDistanceMethod::robust: break;
  }
  if (!pair) pair.emplace(EllipsePair<double>::of(a, b));
  return separated(a, b, *pair, contact);
}

SolverReport boundary_distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b, EllipseDistanceMethod method) {
  switch (method) {
    case EllipseDistanceMethod::gradient: return detail::gradient_descent_curves(a, b);
    case EllipseDistanceMethod::polynomial: return detail::polynomial_curves(a, b);
    case EllipseDistanceMethod::robust: break;
  }
  return robust_boundary(a, b);
}

}  // namespace collide2d
