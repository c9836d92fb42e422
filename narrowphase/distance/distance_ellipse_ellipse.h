// Private: distances between two ellipses, distance_ellipse_ellipse and
// boundary_distance_ellipse_ellipse in kernels.h: between the solids (0 when they overlap) and
// between the boundary curves (0 when the curves meet; the gap of nested ellipses otherwise), with
// closest points.
//
// Method. Solid distance: the overlap decision of overlap_ellipse_ellipse.h (GJK on
//   the exact support functions, double-double when double cannot decide) yields either a common
//   point or a direction n0 that separates. From n0, safeguarded Newton maximises the separation
//   s(n) = n.(c_B - c_A) - h_A(n) - h_B(n) over the angle of n: on the arc of separating
//   directions s is concave (s'' = -(s + rho_A + rho_B), rho the radii of curvature at the support
//   points), the arc is shorter than pi, and every step outside the bracket is replaced by
//   bisection, so the iteration cannot leave the basin and converges quadratically. The result is
//   its own certificate: the lines normal to n through the two support points separate the shapes,
//   so s(n) is a lower bound of the distance and |x_B - x_A| an upper bound, and at the returned n
//   they agree to rounding.
//   Boundary distance: separated pairs as above. Otherwise, with g(n) = n.(c_B - c_A) + h_B(n) -
//   h_A(n), A lies in B exactly when min g >= 0 (the gap is then min g, attained by the support
//   points of the minimising n) and B in A when max g <= 0 (gap -max g); else the curves cross.
//   The extrema of g are found by branch and bound over arcs of directions, starting from the arcs
//   between the axis directions of the two ellipses. On such an arc each radius of curvature lies
//   between its end values, which bounds g'' = -g + rho_B - rho_A: an arc where that bound keeps
//   one sign holds at most one extremum (polished by the same safeguarded Newton), and any other
//   arc is halved while g could still dip below the least value found (or rise above the greatest)
//   by more than its rounding. No extremum can hide between samples, as it can for a sampler that
//   brackets sign changes of g' at fixed directions: a circle on an ellipse's axis near the cusp
//   of its evolute has two minima beside a maximum, and a sample where g' = 0 misses them. Nearly
//   congruent pairs, where g is flat, are bounded separately (congruence_of in the .cpp).
//   Accuracy (tests/accuracy/test_ellipse_ellipse.cpp and test_circle_pairs.cpp, against a 50-digit
//   reference, as a fraction of max(size, centre distance); asserted at 8 u = 8.9e-16, the target
//   being 1e-12): worst 3.7e-16 for the distance and for the boundary distance over all families
//   (near-tangent gaps +-1e-3 ... +-1e-12, aspect ratios to 1e6, offsets to 1e9, sizes 1e-6 and 1e6,
//   nested, inner-tangent, concentric, identical, mirror-symmetric and axis-aligned contacts,
//   nesting at the cusps of the evolute, thin rings between an ellipse and its near copy).
#pragma once

#include <collide2d/query.h>

namespace collide2d::detail {

// A distance with the work that found it.
struct SolverReport {
  DistanceResult result;
  int iterations = 0;     // support evaluations (the robust solvers), descent steps or roots (baselines)
  bool converged = true;  // the method met its own stopping rule
};

// The kernels of kernels.h with their support evaluations, for tests and benchmarks.
SolverReport robust_distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b);
SolverReport robust_distance_ellipse_ellipse(const Ellipse& a, const Orientation& a_orientation, const Ellipse& b,
                                             const Orientation& b_orientation);
SolverReport robust_boundary_distance_ellipse_ellipse(const Ellipse& a, const Ellipse& b);

}  // namespace collide2d::detail
