// Distance between a solid oriented rectangle and a solid ellipse, with closest points.
//
// Method: overlap is decided first by overlap_rect_ellipse (minkowski, with its fallback); an
// overlapping pair returns distance 0 and the rectangle point of least ellipse quadratic as the
// witness (it lies in both solids). A separated pair is the distance from the ellipse centre K to
// the Minkowski sum S = R + E0 (see overlap_rect_ellipse.h), whose boundary has four straight edges
// and four elliptic arcs centred at the rectangle corners:
// - K in the outer strip of a straight edge: distance |x_i| - e_i - l_i, the ellipse point being the
//   support point of E in the edge's inward normal (closed form);
// - otherwise the nearest feature of R is a corner P, and the distance is the point–ellipse
//   distance from P (distance_point_ellipse.h). The arc of corner (s0, s1) only serves points with
//   s0 x0 >= e0 + s0 s1 t1 and s1 x1 >= e1 + s0 s1 t0 (t_i = m01 / l_i, the tangential offsets of
//   the support points), so usually one corner, at most two, are solved.
// Frames: computed in the rectangle frame after subtracting centres; points returned in world.
// Accuracy: distance error at most 3.1e-16 of max(size, centre separation) over the hard-case
// families (tests/accuracy/test_rect_ellipse.cpp, 50-digit reference).

#include <collide2d/kernels.h>

#include "narrowphase/shared/ellipse/distance_point_ellipse.h"
#include "narrowphase/shared/frames/rect_ellipse_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace collide2d {
namespace {

using detail::RectEllipseFrame;
using Frame = RectEllipseFrame<double>;

// A closest pair in the rectangle frame: rectangle point, ellipse point.
struct LocalPair {
  double distance = std::numeric_limits<double>::infinity();
  Vec2 on_rect = Vec2::Zero();
  Vec2 on_ellipse = Vec2::Zero();
};

// Support offsets of the origin-centred ellipse along the rectangle axes: A(U0) = (l0, t0),
// A(U1) = (t1, l1).
struct Supports {
  double l[2];
  double t[2];
};

Supports supports(const Frame& f) {
  const double l0 = std::sqrt(f.l0_squared());
  const double l1 = std::sqrt(f.l1_squared());
  const double m01 = f.m01();
  return {{l0, l1}, {m01 / l0, m01 / l1}};
}

// K beyond the straight edge of S facing axis i (within tol), inside its strip: the edge's Voronoi
// region.
std::optional<LocalPair> edge_region(const Frame& f, const Supports& sp, int i, double tol) {
  const int j = 1 - i;
  const double sgn = f.x[i] > 0 ? 1.0 : -1.0;
  const double gap = std::abs(f.x[i]) - f.e[i] - sp.l[i];
  Vec2 support = Vec2::Zero();
  support[i] = sp.l[i];
  support[j] = sp.t[i];
  const Vec2 on_ellipse = f.x - sgn * support;
  if (gap < -tol || std::abs(on_ellipse[j]) > f.e[j]) return std::nullopt;
  Vec2 on_rect = on_ellipse;
  on_rect[i] = sgn * f.e[i];
  return LocalPair{std::max(gap, 0.0), on_rect, on_ellipse};
}

LocalPair nearest_corner(const Frame& f, const Supports& sp, double tol) {
  LocalPair best;
  for (const double s0 : {-1.0, 1.0}) {
    for (const double s1 : {-1.0, 1.0}) {
      const bool serves =
          s0 * f.x[0] >= f.e[0] + s0 * s1 * sp.t[1] - tol && s1 * f.x[1] >= f.e[1] + s0 * s1 * sp.t[0] - tol;
      if (!serves) continue;
      const Vec2 corner(s0 * f.e[0], s1 * f.e[1]);
      const PointEllipseResult pe = distance_point_ellipse(f.a, f.b, f.to_ellipse_axes(corner));
      const double d = pe.inside ? 0.0 : pe.distance;
      if (d < best.distance) best = {d, corner, pe.inside ? corner : f.from_ellipse_axes(pe.closest)};
    }
  }
  return best;
}

}  // namespace

DistanceResult distance_rect_ellipse(const Rect& r, const Ellipse& e) {
  const Frame f = detail::rect_ellipse_frame<double>(r, e);
  const detail::Rotation<double> rot = detail::Rotation<double>::of(r.angle);
  const auto to_world = [&](const Vec2& p) -> Vec2 { return r.center + rot.apply(p); };
  const auto witness = [&]() { return DistanceResult::touching(to_world(detail::closest_in_ellipse_metric(f).point)); };
  if (detail::minkowski_overlap(f, r, e)) return witness();

  const Supports sp = supports(f);
  // Classification slack: about a hundred ulps of the pair's scale, well above the rounding of the
  // compared quantities, so that a centre on a region boundary is served by at least one region.
  const double tol = 64.0 * std::numeric_limits<double>::epsilon() * f.scale();
  std::optional<LocalPair> best = edge_region(f, sp, 0, tol);
  if (!best) best = edge_region(f, sp, 1, tol);
  if (!best) best = nearest_corner(f, sp, tol);
  // A missing region means K lies on S up to rounding while the overlap test, which decides, found
  // the pair apart: apart by less than rounding, at the witness point.
  if (!best || !std::isfinite(best->distance)) {
    const Vec2 w = witness().point_a;
    return DistanceResult::apart(0.0, w, w);
  }
  return DistanceResult::apart(best->distance, to_world(best->on_rect), to_world(best->on_ellipse));
}

}  // namespace collide2d
