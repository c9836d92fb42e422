#include "narrowphase/overlap_rect_ellipse.h"

#include "narrowphase/rect_ellipse_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide2d {
namespace {

using detail::RectEllipseFrame;
using detail::V2;

constexpr double kUnitRoundoff = std::numeric_limits<double>::epsilon() / 2;

// One corner P = (s0 e0, s1 e1) of the Minkowski test; see the header for the geometry. inv_a2 and
// inv_b2 are 1/a^2 and 1/b^2.
FilterVerdict corner_piece(const RectEllipseFrame<double>& f, double s0, double s1, double err, double inv_a2,
                           double inv_b2) {
  const V2<double> u = f.to_ellipse_axes(V2<double>(s0 * f.e[0], s1 * f.e[1]));
  // u is P - K in ellipse axes; Eberly's Delta = K - P flips the sign of the cone coordinates.
  const double q0 = -u[0] * inv_a2;
  const double q1 = -u[1] * inv_b2;
  const double z0 = s0 * (f.c * q0 - f.s * q1);  // s0 * (M Delta)_0
  const double z1 = s1 * (f.s * q0 + f.c * q1);  // s1 * (M Delta)_1
  const double q_abs = std::abs(q0) + std::abs(q1);
  const double z_err = 2.0 * (err * (inv_a2 + inv_b2) + 8.0 * kUnitRoundoff * q_abs);
  if (z0 < -z_err || z1 < -z_err) return FilterVerdict::overlap;
  const double q = u[0] * u[0] * inv_a2 + u[1] * u[1] * inv_b2;
  const double q_err =
      2.0 * (2.0 * err * q_abs + err * err * (inv_a2 + inv_b2) + 8.0 * kUnitRoundoff * q);
  if (q - 1.0 < -q_err) return FilterVerdict::overlap;
  if (z0 > z_err && z1 > z_err && q - 1.0 > q_err) return FilterVerdict::separated;
  return FilterVerdict::uncertain;
}

// Whether the rectangle and the ellipse certainly share a point of the segment between their
// centres: the rectangle holds it from its centre up to s_R = 1 / max_i(|x_i| / e_i), the ellipse
// back from its centre up to s_E = 1 / |(u_0 / a, u_1 / b)| (u the rectangle's centre in the
// ellipse's axes), and s_R + s_E > 1, written without division. Both shapes are first shrunk so
// that the coordinates' rounding (err) cannot move a point of the smaller shapes out of the true
// ones: the rectangle's half extents by 2 err, the ellipse about its centre by 2 err / min(a, b)
// (which erodes it by at least 2 err; shrinking its semi-axes by 2 err would not), and the last
// comparison keeps 16 u for its own rounding. It decides 2,061 of bench_narrowphase's 2,651
// overlapping candidate pairs, which the corner pieces below would all four have to see.
bool centre_segment_shared(const RectEllipseFrame<double>& f, double err) {
  const double e0 = f.e[0] - 2 * err, e1 = f.e[1] - 2 * err;
  const double shrink = 1.0 - 2 * err / std::min(f.a, f.b);
  if (!(e0 > 0 && e1 > 0 && shrink > 0)) return false;
  const double a = shrink * f.a, b = shrink * f.b;
  const V2<double> u = f.to_ellipse_axes(V2<double>(0, 0));
  const double rect = std::max(std::abs(f.x[0]) * e1, std::abs(f.x[1]) * e0);  // e0 e1 / s_R
  const double ellipse = std::sqrt(b * u[0] * b * u[0] + a * u[1] * a * u[1]);  // a b / s_E
  return rect * (a * b) + ellipse * (e0 * e1) > rect * ellipse * (1 + 16 * kUnitRoundoff);
}

FilterVerdict minkowski_filter(const RectEllipseFrame<double>& f) {
  const double err = 16.0 * kUnitRoundoff * f.scale();
  // The ellipse's bounding circle first: most pairs of a scene are that far apart; then the
  // certain overlap most pairs a broad phase hands over show.
  const double radius = std::max(f.a, f.b) + err;
  if (std::abs(f.x[0]) - f.e[0] > radius || std::abs(f.x[1]) - f.e[1] > radius) return FilterVerdict::separated;
  if (centre_segment_shared(f, err)) return FilterVerdict::overlap;
  const double l_squared[2] = {f.l0_squared(), f.l1_squared()};
  bool unsure = false;
  for (int i = 0; i < 2; ++i) {
    // The grown box R': margin = e_i + l_i - |x_i|. Compared squared first (no square root) when the
    // centre is well beyond the rectangle; the root only near the decision.
    const double reach = std::abs(f.x[i]) - f.e[i];
    const double clear = reach - 2.0 * err;  // l_i < clear, with room for the rounding of l_i^2
    if (clear > 0.0 && l_squared[i] < clear * clear) return FilterVerdict::separated;
    const double margin = -reach + std::sqrt(l_squared[i]);
    if (margin < -err) return FilterVerdict::separated;
    unsure = unsure || margin <= err;
  }
  const double inv_a2 = 1.0 / (f.a * f.a);
  const double inv_b2 = 1.0 / (f.b * f.b);
  for (const double s0 : {-1.0, 1.0}) {
    for (const double s1 : {-1.0, 1.0}) {
      const FilterVerdict v = corner_piece(f, s0, s1, err, inv_a2, inv_b2);
      if (v == FilterVerdict::separated) return v;
      unsure = unsure || v == FilterVerdict::uncertain;
    }
  }
  return unsure ? FilterVerdict::uncertain : FilterVerdict::overlap;
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
