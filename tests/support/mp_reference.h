// A 50-digit reference for the narrow-phase tests, by algorithms other than the kernels':
// - point–solid ellipse: Newton from the left on the secular equation in t (convex, decreasing);
// - rectangle–ellipse distance: golden-section search over each rectangle edge of the point–ellipse
//   distance (the distance to a convex set is convex along a segment); overlap: the least ellipse
//   quadratic over the rectangle's edges (closed form per edge) or the centre in the rectangle;
// - polygons: least point–segment distance over all vertex–edge pairs, overlap by separating axes;
// - ellipse pairs: the signed distance f(t) from A's boundary point at parameter t to B's boundary
//   (Newton on the secular equation, from the side where it converges monotonically, inside or
//   outside), sampled at 720 parameters in double, each promising extremum narrowed by golden
//   section in double and then in 50 digits; the signs of f and the centres decide overlap,
//   containment and crossing.
// - signed distance (contacts): the dual function s(u) = u.(c_B - c_A) - h_A(u) - h_B(-u) (h the
//   support function, in closed form per shape; a polygon's the largest projection of its vertices)
//   scanned in double at 4,096 even angles and at geometric offsets 10^-1 ... 10^-15 around every
//   axis direction of both shapes and every face normal of a polygon (a needle's
//   support function turns within b/a of its minor axis, a rectangle's has kinks on its axes), each
//   of the six highest local maxima narrowed by golden section in 50 digits to 1e-22 rad. No Newton step and no
//   curvature bound: nothing the kernels do.
// Inputs are the double shapes, taken exactly; angles become exact 50-digit cosines and sines.
#pragma once

#include <collide2d/shapes.h>

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace collide2d::reference {

using Real = boost::multiprecision::cpp_bin_float_50;

struct Point {
  Real x;
  Real y;
};

Point to_mp(const Vec2& p);

// Distance from p to the solid shape (0 inside): for a capsule or a polygon, the nearest of its
// core's edges, less its radius.
Real distance_to(const Shape& s, const Point& p);

// The exact axis-aligned box of a shape (its support function along the axes, in 50 digits),
// rounded outward to doubles: it contains every point of the shape, independently of aabb().
Aabb bounding_box(const Shape& s);

// Whether the two solids overlap, and their distance (0 when they do).
bool overlap(const Shape& a, const Shape& b);
Real distance(const Shape& a, const Shape& b);

// Distance from p to the boundary curve of e (positive inside too).
Real curve_distance(const Ellipse& e, const Point& p);

struct EllipsePairReference {
  bool overlap = false;
  Real distance;  // between the solids
  Real boundary;  // between the boundary curves
};
EllipsePairReference ellipse_pair(const Ellipse& a, const Ellipse& b);

// The gap between the boundary curves of two circles or ellipses (0 when they cross). Pairs with a
// circle need no sampling: the circle's centre against the other curve, nearest and farthest, by
// secular equations; two ellipses use ellipse_pair.
Real boundary_distance(const Shape& a, const Shape& b);

// The signed distance of two solids (minus the penetration depth when they overlap), the unit
// direction attaining it (from A to B), and the best value among the other local maxima found more
// than 1e-6 rad away from it (-infinity if none): close to `separation`, the maximiser is not unique.
// `curvature` is -s'' at the maximiser (a second difference over 1e-12 rad; huge at a kink): an
// error e in the slope of s moves the maximiser by about e / curvature, so the normal of a flat
// maximum is only as good as the rounding of s' over it.
struct SignedDistance {
  Real separation;
  Point normal;
  Real runner_up;
  Real curvature;
};
SignedDistance signed_distance(const Shape& a, const Shape& b);

// The support point of a shape along the unit direction n, in the world: a circle's or an
// ellipse's from its closed form (an ellipse's (a^2 l_0, b^2 l_1) / h(l) in its own axes, l the
// direction there); a core shape's (rectangle, polygon, capsule, segment) its farthest vertex moved
// by its radius along n, unless another vertex lies within 1e-9 of the shape's reach of its support
// value: then the support set is a face, to the precision of n, and there is no one point (nullopt).
std::optional<Point> support_point(const Shape& s, const Point& n);

}  // namespace collide2d::reference
