#include "narrowphase/baselines/baselines.h"
#include "shapes/kinds.h"

#include "narrowphase/baselines/ellipse_seed_solvers.h"
#include "narrowphase/shared/ellipse/ellipse_contact.h"
#include "narrowphase/shared/frames/rect_ellipse_frame.h"

#include <cmath>
#include <optional>
#include <type_traits>

namespace collide2d::baselines {
namespace {

using detail::RectEllipseFrame;

// The segment p -> q (rectangle frame) meets the solid ellipse. In ellipse-normalised coordinates
// w = (u0/a, u1/b) the ellipse is the unit disc and the edge is w(t) = p + t d, t in [0, 1].
bool edge_meets_ellipse(const RectEllipseFrame<double>& f, const Vec2& p, const Vec2& q) {
  const Vec2 up = f.to_ellipse_axes(p);
  const Vec2 uq = f.to_ellipse_axes(q);
  const Vec2 w(up[0] / f.a, up[1] / f.b);
  const Vec2 d(uq[0] / f.a - w[0], uq[1] / f.b - w[1]);
  const double dd = d.squaredNorm();
  const double cross = w[0] * d[1] - w[1] * d[0];
  const double disc = dd - cross * cross;  // = dd * (q1^2 - q0 q2) / dd^2 without the cancellation
  if (disc < 0) return false;
  const double root = std::sqrt(disc);
  const double wd = w.dot(d);
  const double t0 = (-wd - root) / dd;
  const double t1 = (-wd + root) / dd;
  return t0 <= 1.0 && t1 >= 0.0;
}

bool all_features_overlap(const RectEllipseFrame<double>& f) {
  const Vec2 corners[4] = {{-f.e[0], -f.e[1]}, {f.e[0], -f.e[1]}, {f.e[0], f.e[1]}, {-f.e[0], f.e[1]}};
  for (const Vec2& p : corners) {
    if (f.quadratic(p) <= 1.0) return true;
  }
  for (int k = 0; k < 4; ++k) {
    if (edge_meets_ellipse(f, corners[k], corners[(k + 1) % 4])) return true;
  }
  return std::abs(f.x[0]) <= f.e[0] && std::abs(f.x[1]) <= f.e[1];
}

Ellipse as_ellipse(const Circle& c) { return {c.center, c.radius, c.radius, 0.0}; }

// Whether a and b are an X and a Y, in either order.
template <class X, class Y>
bool is_pair(const Shape& a, const Shape& b) {
  return (std::holds_alternative<X>(a) && std::holds_alternative<Y>(b)) ||
         (std::holds_alternative<Y>(a) && std::holds_alternative<X>(b));
}

// kernel(x, y) on two shapes of kinds X and Y in kernel order (by key within one kind), the result
// swapped back; nullopt for other kinds.
template <class X, class Y, class Kernel>
std::optional<DistanceResult> in_order(const Shape& a, const Shape& b, Kernel kernel) {
  validate(a);
  validate(b);
  if (std::holds_alternative<X>(a) && std::holds_alternative<Y>(b)) {
    const X& x = std::get<X>(a);
    const Y& y = std::get<Y>(b);
    if constexpr (std::is_same_v<X, Y>) {
      if (detail::precedes(y, x)) return kernel(y, x).swapped();
    }
    return kernel(x, y);
  }
  if (std::holds_alternative<Y>(a) && std::holds_alternative<X>(b))
    return kernel(std::get<X>(b), std::get<Y>(a)).swapped();
  return std::nullopt;
}

}  // namespace

bool overlap_rect_ellipse(const Rect& r, const Ellipse& e, RectEllipseTest test) {
  const RectEllipseFrame<double> f = detail::rect_ellipse_frame<double>(r, e);
  return test == RectEllipseTest::closest_features ? detail::closest_features_overlap(f) : all_features_overlap(f);
}

detail::SolverReport curve_distance(const Ellipse& a, const Ellipse& b, EllipseSolver solver) {
  return solver == EllipseSolver::gradient ? detail::gradient_descent_curves(a, b) : detail::polynomial_curves(a, b);
}

detail::SolverReport distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b, EllipseSolver solver) {
  std::optional<detail::EllipsePair<double>> pair;
  const detail::EllipseContact contact = detail::ellipse_contact(a, b, pair);
  if (contact.overlap) return {DistanceResult::touching(contact.witness), contact.iterations, true};
  return curve_distance(a, b, solver);
}

bool rect_ellipse_covers(const Shape& a, const Shape& b) { return is_pair<Rect, Ellipse>(a, b); }

bool ellipse_solver_covers(const Shape& a, const Shape& b, bool boundary) {
  return is_pair<Ellipse, Ellipse>(a, b) || (boundary && is_pair<Circle, Ellipse>(a, b));
}

bool overlaps(const Shape& a, const Shape& b, RectEllipseTest test) {
  validate(a);
  validate(b);
  if (!rect_ellipse_covers(a, b)) return collide2d::overlaps(a, b);
  const bool rect_first = std::holds_alternative<Rect>(a);
  return overlap_rect_ellipse(std::get<Rect>(rect_first ? a : b), std::get<Ellipse>(rect_first ? b : a), test);
}

DistanceResult distance(const Shape& a, const Shape& b, EllipseSolver solver) {
  if (!ellipse_solver_covers(a, b, false)) return collide2d::distance(a, b);
  return *in_order<Ellipse, Ellipse>(
      a, b, [solver](const Ellipse& x, const Ellipse& y) { return distance_ellipse_ellipse(x, y, solver).result; });
}

DistanceResult boundary_distance(const Shape& a, const Shape& b, EllipseSolver solver) {
  if (!ellipse_solver_covers(a, b, true)) return collide2d::boundary_distance(a, b);
  const auto curves = [solver](const Ellipse& x, const Ellipse& y) { return curve_distance(x, y, solver).result; };
  if (const auto r = in_order<Ellipse, Ellipse>(a, b, curves)) return *r;
  return *in_order<Circle, Ellipse>(a, b, [&](const Circle& x, const Ellipse& y) { return curves(as_ellipse(x), y); });
}

}  // namespace collide2d::baselines
