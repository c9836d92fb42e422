// Private: the overlap of two solid ellipses, overlap_ellipse_ellipse in kernels.h: a yes/no
// answer, no distance computed.
//
// Method. The pair overlaps exactly when no direction n separates it, that is when
// s(n) = n.(c_B - c_A) - h_A(n) - h_B(n) <= 0 for every n (h the support functions). The test runs
// GJK on the difference body B - A with the exact support functions, relative to c_A: it stops as
// soon as a direction separates by more than its rounding bound, or a triangle of support points
// holds the origin deeper than that bound (the origin is then a convex combination of points of
// B - A, and the same weights give a point common to both shapes). Cheap certain cases come first:
// centres farther apart than the sum of the largest semi-axes; then the characteristic cubic
// det(lambda A - B) of the two conics (Wang, Wang and Kim 2001; overlap_ellipse_ellipse-inl.h), whose
// discriminant and coefficients decide the pair without iterating where their signs clear their
// error bounds; then either centre inside the other ellipse.
//
// Why the cubic is not the whole test: its coefficients are products of the two quadrics, and in
// double its discriminant loses the verdict for aspect ratios 1e3 and gaps near 1e-8 of the size,
// and far from the origin, where GJK's quantities are lengths measured from c_A with a rounding
// bound of a few u (|c_B - c_A| + the semi-axes). Its bound sends those pairs on, a share of the
// hard cases; random and candidate pairs it decides without iterating, and it runs in the batch
// (overlap_batch.cpp) on vectors of pairs.
//
// Filter and fallback. The double pass answers `uncertain` only when the pair is within
// 64 u (|c_B - c_A| + a_max + b_max) of touching; the same iteration then runs in double-double
// (104-bit significand); a pair still within its bound (about 3e-30 of the scale) is decided by the
// sign of s at the best direction found in double-double, and s = 0 counts as touching, so as
// overlap.
#pragma once

#include "narrowphase/overlap/overlap_rect_ellipse.h"  // FilterVerdict

#include <collide2d/shapes.h>

namespace collide2d::detail {

// The double pass alone (for tests and benchmarks of the fallback rate).
FilterVerdict overlap_ellipse_ellipse_filter(const Ellipse& a, const Ellipse& b);

}  // namespace collide2d::detail
