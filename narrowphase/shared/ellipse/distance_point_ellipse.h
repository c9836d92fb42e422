// Distance from a point to an ellipse curve, and whether the point lies in the solid ellipse.
//
// Frame: the ellipse's own frame (centre at the origin, semi-axis a along x, b along y); callers
// transform the point first, which also keeps the computation accurate far from the world origin.
//
// Method: D. Eberly, "Distance from a Point to an Ellipse, an Ellipsoid, or a Hyperellipsoid"
// (Geometric Tools, 2013): reflect into the first quadrant, reduce the Lagrange conditions to one
// root of the secular function g(t) = (r0 z0 / (t + r0 - 1))^2 + (z1 / t)^2 - 1 (Eberly's s + 1 as
// the unknown t, which keeps its relative precision where the root is tiny: inside, near the major
// axis). Where Eberly bisects to the last bit (60 to ~1100 halvings), this takes Newton steps on
// (g + 1)^(-1/2) = 1, a concave function of t, from a lower bound: they climb to the root without
// ever passing it, and stop once the next step would round away (point_ellipse-inl.h says why). The
// distance is |t - 1| times the length of the gradient there, not the difference of two nearby
// points. The axis cases (a zero coordinate, or one within 1e-50 of the semi-axis across) are
// closed forms.
//
// Accuracy: the closest point and the distance are correct to a few ulps of max(a, b, |p|) for any
// aspect ratio (tested to 1e6) and for points on, near, inside and far from the curve; the
// circle–ellipse families in tests/accuracy/test_circle_pairs.cpp see at most 4.5e-16 of the scale.
#pragma once

#include <collide2d/shapes.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace collide2d {

struct PointEllipseResult {
  double distance = 0.0;        // from the point to the nearest point of the curve
  Vec2 closest = Vec2::Zero();  // that nearest point, in the ellipse frame
  Vec2 normal = Vec2::UnitX();  // the curve's outward unit normal at `closest`, in the ellipse frame
  bool inside = false;          // the point lies in the closed solid ellipse
};

PointEllipseResult distance_point_ellipse(double a, double b, const Vec2& p);

// The nearest point for a contact to a tolerance (ContactOptions::tolerance), where the contact's
// shape reaches `radius` beyond p (a circle's or a rounded core's radius; 0 for a corner): Newton's
// steps stop at the first after which SecularRoot::width (point_ellipse-inl.h) certifies that the
// separation, the signed distance less the radius, lies within `error` <= tolerance with its sign
// certain, the normal within `turn` <= angle rad, and both contact points (p moved by the radius
// along the normal, and p moved by the signed distance, where `closest` is put) within the
// tolerance. Nullopt for the axis cases, which distance_point_ellipse settles in closed form.
struct NearestWithin {
  PointEllipseResult near;
  double signed_distance = 0.0;  // negative inside
  double error = 0.0, turn = 0.0;
};
std::optional<NearestWithin> distance_point_ellipse_within(double a, double b, const Vec2& p, double radius,
                                                           double tolerance, double angle);

// A lower bound of the signed distance from p to the ellipse (negative inside), without its root:
// the larger of the gap to the ellipse's bounding box (exact beyond the ends of the axes) and of
// (rho - 1) times min(a, b) outside or max(a, b) inside, where rho E, the ellipse scaled by rho
// about its centre, passes through p. Outside, rho E holds E grown by (rho - 1) min(a, b), as E's
// support value is at least min(a, b) along every direction; inside, it holds E shrunk by
// (1 - rho) max(a, b), as that value is at most max(a, b).
inline double distance_floor(double a, double b, const Vec2& p) {
  const double u = p.x() / a, v = p.y() / b;
  const double box = std::max(std::abs(p.x()) - a, std::abs(p.y()) - b);
  const double rho = std::sqrt(u * u + v * v);
  return std::max(box, (rho - 1) * (rho >= 1 ? std::min(a, b) : std::max(a, b)));
}

// A point of the curve where the distance from p has a local minimum along the curve, the curve's
// outward unit normal there, and the signed distance (p - point).normal (negative: p lies on the
// inner side of the tangent).
struct CurveFoot {
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::UnitX();
  double signed_distance = 0.0;
};

// The other local minimum of the distance from p along the curve, beside the nearest point, if
// there is one. The normals through p meet the curve where the secular function has its roots, at
// most four (a quartic); around the curve the distance's critical points alternate between minima
// and maxima, so there are at most two minima, and the second exists only when p lies inside the
// evolute (the astroid (a x)^(2/3) + (b y)^(2/3) = (a^2 - b^2)^(2/3) for a >= b), where the four
// normals are. It lies on the far side of the major axis from p. Found by Newton's method as the
// nearest point is (distance_point_ellipse.cpp says how); nullopt where there is none.
std::optional<CurveFoot> other_local_nearest(double a, double b, const Vec2& p);

// The nearest foot of p where only a range of normals counts (a vertex's cone of directions, a
// corner's quarter turn): `in_range(normal, margin)` says whether the curve's outward normal there
// lies in the range with `margin` (a sine) to spare on both sides, a negative margin widening it.
// To the tolerance (distance_point_ellipse_within) where that normal lies in the range, or out of
// it, by more than its turn, so that the exact one certainly does the same; else the exact root.
// `error` bounds the signed distance's error (0 for an exact root); `early` says the root stopped
// within the tolerance. A tolerance of 0 takes the exact root.
struct RangeFoot {
  CurveFoot foot;
  double error = 0.0;
  bool early = false;
  bool in_range = false;
};
template <class InRange>
RangeFoot nearest_in_range(double a, double b, const Vec2& p, double radius, double tolerance, double angle,
                           InRange in_range) {
  if (tolerance > 0) {
    if (const std::optional<NearestWithin> near = distance_point_ellipse_within(a, b, p, radius, tolerance, angle)) {
      const CurveFoot foot{near->near.closest, near->near.normal, near->signed_distance};
      if (in_range(foot.normal, near->turn)) return {foot, near->error, true, true};
      if (!in_range(foot.normal, -near->turn)) return {foot, near->error, true, false};
    }
  }
  const PointEllipseResult exact = distance_point_ellipse(a, b, p);
  const CurveFoot foot{exact.closest, exact.normal, exact.inside ? -exact.distance : exact.distance};
  return {foot, 0.0, false, in_range(foot.normal, 0.0)};
}

}  // namespace collide2d
