// The reference methods that collide2d's kernels are measured against, kept runnable outside the
// public API: a library of their own (collide2d_baselines), linked by the command line's --method,
// the speed-against-error report and the tests.
//
// - Rectangle–ellipse overlap in plain double: closest features (the minimum of the ellipse
//   quadratic over the rectangle edges facing the ellipse centre, in closed form; the Minkowski
//   test's fallback runs it in long double) and all features (any corner in the ellipse, any edge
//   crossing it, or the ellipse centre in the rectangle; the edge test uses the cross-product form
//   of the discriminant, |d|^2 - (p x d)^2 >= 0 in the frame where the ellipse is the unit disc,
//   where q1^2 - q0 q2 cancels for needles). Both are right wherever the gap is clear of 1e-10 of
//   the size, which the hard-case families assert; nearer touching they err.
// - The distance between two ellipse curves: gradient descent as M. Pewsey's "Minimum Distance
//   Between Ellipses" (2021) publishes it, and the degree-12 polynomial of D. Eberly's "Distance
//   Between Ellipses in 2D" (Geometric Tools). They find local minima or stationary points of the
//   distance between the curves; docs/accuracy.md gives what they achieve on each hard-case family
//   (measured, not asserted), and the seed samples test asserts their documented accuracy on the
//   published sample pairs.
#pragma once

#include <collide2d/query.h>

#include "narrowphase/distance/distance_ellipse_ellipse.h"

namespace collide2d::baselines {

enum class RectEllipseTest { closest_features, all_features };
enum class EllipseSolver { gradient, polynomial };

bool overlap_rect_ellipse(const Rect& r, const Ellipse& e, RectEllipseTest test);

// The curve-to-curve result, whatever the solids do.
detail::SolverReport curve_distance(const Ellipse& a, const Ellipse& b, EllipseSolver solver);
// The solid distance: the exact overlap test first (its common point when the solids overlap),
// else the solver's curve distance.
detail::SolverReport distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b, EllipseSolver solver);

// The pairs the methods cover, in either order: the rectangle–ellipse tests a rectangle and an
// ellipse; the ellipse solvers two ellipses, and for the boundary also a circle and an ellipse (the
// circle as an ellipse with a = b).
bool rect_ellipse_covers(const Shape& a, const Shape& b);
bool ellipse_solver_covers(const Shape& a, const Shape& b, bool boundary);

// Any pair, either order, validated as query.h validates: the method where it covers the pair,
// else query.h's query.
bool overlaps(const Shape& a, const Shape& b, RectEllipseTest test);
DistanceResult distance(const Shape& a, const Shape& b, EllipseSolver solver);
DistanceResult boundary_distance(const Shape& a, const Shape& b, EllipseSolver solver);

}  // namespace collide2d::baselines
