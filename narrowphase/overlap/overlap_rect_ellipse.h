// Private: the overlap of a solid oriented rectangle and a solid ellipse, overlap_rect_ellipse in
// kernels.h: a yes/no answer, nothing more.
//
// Source: D. Eberly, "Intersection of Rectangle and Ellipse" (Geometric Tools). All tests work in the
// rectangle's frame after subtracting the centres, so the pair's distance from the world origin
// costs no accuracy; the ellipse quadratic is evaluated from projections onto the ellipse axes.
//
// Method. The ellipse centre K must lie in the Minkowski sum S = R + E0 (E0 the
//   ellipse moved to the origin): a box R' (R grown by the support half-widths l_i) minus four
//   corner pieces, each outside the ellipse copy E_P centred at a corner P. Choosing the corner P
//   by the signs of K's coordinates, as Eberly's article does, is not enough: for a slanted,
//   eccentric ellipse the piece of corner (+,+) reaches into the other quadrants, and that test
//   reports overlap for separated shapes (e.g. rectangle half extents 0.1, ellipse a = 10,
//   b = 0.01 at 45 degrees, centre (1.1, 6.1): 3.39 apart). Here every corner is tested, and the piece
//   is characterised exactly: K - P lies in the cone spanned by the support offsets of E0 in the
//   two rectangle normals at P (Eberly's z0, z1 > 0) and Q_P(K) > 1. Any such point is outside S
//   (the ray from P through K leaves E_P at a point of the boundary of S), and every point of
//   R' \ S is such a point, so the test is exact in exact arithmetic.
//   Filter: every decision quantity carries a forward error bound (16 u L for lengths, where
//   u = 2^-53 and L = |x0| + |x1| + e0 + e1 + a + b in the rectangle frame, propagated to Q and to
//   the cone coordinates, then doubled). When a margin lies inside its bound the pair goes to the
//   fallback: the closest-features test evaluated in double-double (104-bit significand, the same
//   on every platform), recomputing the frame from the raw shapes with cos_sin_extended.
//   The fallback, closest features: the minimum of the ellipse quadratic over the one or two
//   rectangle edges facing the ellipse centre, in closed form (Lagrange and a clamp).
//
// Accuracy (tests/accuracy/test_rect_ellipse.cpp, against a 50-digit reference): the verdict is the
// exact verdict of the rounded input in every hard-case family (gaps +-1e-3 ... +-1e-12 of the
// size, aspect ratios to 1e6, sizes 1e-6 and 1e6, offsets to 1e9) and in contacts at the rounding
// level (gap 0, +-1e-14 ... +-1e-16 of the size), where the filter defers and the fallback decides.
// The plain-double tests it is measured against (narrowphase/baselines/) err there.
// Limit: the rectangle's frame holds the ellipse centre to u times the centres' distance, so a
// rectangle far along a needle (6.8e38 from the centre of an ellipse 3e48 long, 1.09 beside it)
// can be called overlapping; that is within the stated target (1e-12 of the centre distance), and
// the World never reports such a pair, since it also requires the tight boxes to meet.
#pragma once

#include <collide2d/shapes.h>

namespace collide2d::detail {

// The verdict of a test that may defer: `uncertain` when a decision margin is inside its
// rounding-error bound.
enum class FilterVerdict { overlap, separated, uncertain };

// The Minkowski filter alone, in double (for the tests of the fallback rate).
FilterVerdict overlap_rect_ellipse_filter(const Rect& r, const Ellipse& e);

}  // namespace collide2d::detail
