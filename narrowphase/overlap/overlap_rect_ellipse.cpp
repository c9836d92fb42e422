#include "narrowphase/overlap/overlap_rect_ellipse.h"

#include "narrowphase/frames/rect_ellipse_frame.h"
#include "narrowphase/batch/lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/rect_ellipse_filter-inl.h"
}  // namespace detail
namespace {

using detail::RectEllipseFrame;
using detail::V2;

// The filter on a single pair (rect_ellipse_filter-inl.h, shared with the batch).
FilterVerdict minkowski_filter(const RectEllipseFrame<double>& f) {
  using detail::Scalar;
  const detail::LaneVerdicts<bool> v = detail::RectEllipseFilter<Scalar>(Scalar{}, detail::rect_ellipse_lanes(f)).run();
  return v.separated ? FilterVerdict::separated : v.overlap ? FilterVerdict::overlap : FilterVerdict::uncertain;
}

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

}  // namespace

bool detail::minkowski_overlap(const RectEllipseFrame<double>& f, const Rect& r, const Ellipse& e) {
  const FilterVerdict v = minkowski_filter(f);
  if (v != FilterVerdict::uncertain) return v == FilterVerdict::overlap;
  return detail::minkowski_fallback(r, e);
}

bool detail::minkowski_fallback(const Rect& r, const Ellipse& e) {
  return detail::closest_features_overlap(detail::rect_ellipse_frame<long double>(r, e));
}

FilterVerdict overlap_rect_ellipse_filter(const Rect& r, const Ellipse& e) {
  return minkowski_filter(detail::rect_ellipse_frame<double>(r, e));
}

bool overlap_rect_ellipse(const Rect& r, const Orientation& ro, const Ellipse& e, const Orientation& eo) {
  return detail::minkowski_overlap(detail::rect_ellipse_frame<double>(r, {ro.c, ro.s}, e, {eo.c, eo.s}), r, e);
}

bool overlap_rect_ellipse(const Rect& r, const Ellipse& e, RectEllipseMethod method) {
  switch (method) {
    case RectEllipseMethod::closest_features:
      return detail::closest_features_overlap(detail::rect_ellipse_frame<double>(r, e));
    case RectEllipseMethod::all_features:
      return all_features_overlap(detail::rect_ellipse_frame<double>(r, e));
    case RectEllipseMethod::minkowski:
      break;
  }
  return detail::minkowski_overlap(detail::rect_ellipse_frame<double>(r, e), r, e);
}

}  // namespace collide2d
