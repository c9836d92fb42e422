// Private: the rectangle–ellipse pair expressed in the rectangle's frame, generic over the scalar
// so that one implementation of each test serves double precision and the double-double fallback.
//
// In that frame the rectangle is [-e0, e0] x [-e1, e1], the ellipse centre is x = (x0, x1), and the
// ellipse's a-axis has direction (c, s). For a point p the ellipse quadratic is evaluated from the
// projections onto the ellipse axes, Q(p) = (u0/a)^2 + (u1/b)^2 with u = V^T (p - x), never from
// an explicit matrix M = V diag(1/a^2, 1/b^2) V^T: for a needle (a/b = 1e6) M's entries are ~1/b^2
// and p^T M p cancels to ~1/a^2, losing twelve digits; the projected form is a sum of squares.
#pragma once

#include <collide2d/shapes.h>
#include "narrowphase/shared/lanes.h"
#include "shapes/internal.h"

#include <Eigen/Core>

#include <cmath>

namespace collide2d::detail {

template <class Real>
using V2 = Eigen::Matrix<Real, 2, 1>;

template <class Real>
struct RectEllipseFrame {
  V2<Real> x;  // ellipse centre
  V2<Real> e;  // rectangle half extents
  Real c = 1;  // ellipse a-axis direction (c, s)
  Real s = 0;
  Real a = 1;
  Real b = 1;

  // Ellipse-axis coordinates of the rectangle-frame point p, relative to the ellipse centre.
  V2<Real> to_ellipse_axes(const V2<Real>& p) const {
    const V2<Real> d = p - x;
    return V2<Real>(c * d[0] + s * d[1], -s * d[0] + c * d[1]);
  }
  // Inverse of to_ellipse_axes.
  V2<Real> from_ellipse_axes(const V2<Real>& u) const { return x + V2<Real>(c * u[0] - s * u[1], s * u[0] + c * u[1]); }
  Real quadratic(const V2<Real>& p) const {
    const V2<Real> u = to_ellipse_axes(p);
    const Real u0 = u[0] / a;
    const Real u1 = u[1] / b;
    return u0 * u0 + u1 * u1;
  }
  // A length bounding every coordinate the tests compute: the unit of their rounding-error bounds.
  Real scale() const {
    using std::abs;
    return abs(x[0]) + abs(x[1]) + e[0] + e[1] + a + b;
  }
  // Entries of M^-1 = V diag(a^2, b^2) V^T: squared support half-widths along the rectangle axes
  // (l0^2, l1^2) and the cross term m01.
  Real l0_squared() const { return a * a * c * c + b * b * s * s; }
  Real l1_squared() const { return a * a * s * s + b * b * c * c; }
  Real m01() const { return (a * a - b * b) * c * s; }
};

// rr and re: the rotations of r.angle and el.angle.
template <class Real>
RectEllipseFrame<Real> rect_ellipse_frame(const Rect& r, const Rotation<Real>& rr, const Ellipse& el,
                                          const Rotation<Real>& re) {
  const Rotation<Real> rel = re.relative_to(rr);
  // Subtract the centres before rotating: far from the origin the difference is exact or nearly so.
  const V2<Real> d(Real(el.center.x()) - Real(r.center.x()), Real(el.center.y()) - Real(r.center.y()));
  RectEllipseFrame<Real> f;
  f.x = rr.apply_inverse(d);
  f.e = V2<Real>(Real(r.half_extents.x()), Real(r.half_extents.y()));
  f.c = rel.c;
  f.s = rel.s;
  f.a = Real(el.a);
  f.b = Real(el.b);
  return f;
}

template <class Real>
RectEllipseFrame<Real> rect_ellipse_frame(const Rect& r, const Ellipse& el) {
  return rect_ellipse_frame(r, Rotation<Real>::of(r.angle), el, Rotation<Real>::of(el.angle));
}

// The rectangle point closest to the ellipse centre in the ellipse's metric, and the quadratic
// there: the minimum of Q over the solid rectangle. The rectangle and ellipse overlap iff q <= 1.
template <class Real>
struct MetricClosest {
  Real q = 0;
  V2<Real> point;
};

// Eberly's closest-features view ("Intersection of Rectangle and Ellipse", sections 3 and 4): when
// the centre is outside the
// rectangle, the minimiser lies on an edge facing the centre. On the line {p_i = sgn e_i} the
// quadratic's minimum is (|x_i| - e_i)^2 / l_i^2 at p_j = x_j + (e_i - |x_i|) sgn m01 / l_i^2
// (Lagrange); Q restricted to the edge is a convex parabola, so the constrained minimum is at that
// foot clamped to the edge. KKT shows a vertex minimiser always ends a facing edge, so the one or
// two facing edges suffice.
template <class Real>
MetricClosest<Real> closest_in_ellipse_metric(const RectEllipseFrame<Real>& f) {
  using std::abs;
  if (abs(f.x[0]) <= f.e[0] && abs(f.x[1]) <= f.e[1]) return {Real(0), f.x};
  MetricClosest<Real> best{Real(-1), f.x};
  const Real l_squared[2] = {f.l0_squared(), f.l1_squared()};
  const Real m01 = f.m01();
  for (int i = 0; i < 2; ++i) {
    if (abs(f.x[i]) <= f.e[i]) continue;
    const int j = 1 - i;
    const Real sgn = f.x[i] > 0 ? Real(1) : Real(-1);
    const Real gap = abs(f.x[i]) - f.e[i];
    const Real foot = f.x[j] - gap * sgn * m01 / l_squared[i];
    V2<Real> p;
    p[i] = sgn * f.e[i];
    Real q;
    if (abs(foot) <= f.e[j]) {
      p[j] = foot;
      q = gap * gap / l_squared[i];
    } else {
      p[j] = foot > 0 ? f.e[j] : -f.e[j];
      q = f.quadratic(p);
    }
    if (best.q < 0 || q < best.q) best = {q, p};
  }
  return best;
}

template <class Real>
bool closest_features_overlap(const RectEllipseFrame<Real>& f) {
  return closest_in_ellipse_metric(f).q <= Real(1);
}

// The Minkowski filter's inputs (overlap_rect_ellipse-inl.h).
inline RectEllipseLanes<double> rect_ellipse_lanes(const RectEllipseFrame<double>& f) {
  return {f.x[0], f.x[1], f.e[0], f.e[1], f.c, f.s, f.a, f.b};
}

// The default rect–ellipse overlap test (filter, then double-double fallback) on a frame the caller
// has already built from r and e; the fallback rebuilds it in double-double from the raw shapes.
bool minkowski_overlap(const RectEllipseFrame<double>& f, const Rect& r, const Ellipse& e);
// The fallback alone: the verdict for a pair the filter left uncertain.
bool minkowski_fallback(const Rect& r, const Ellipse& e);

}  // namespace collide2d::detail
