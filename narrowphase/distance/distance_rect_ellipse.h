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
// families (tests/test_rect_ellipse.cpp, 50-digit reference).
#pragma once

#include <collide2d/distance_result.h>

namespace collide2d {

DistanceResult distance_rect_ellipse(const Rect& r, const Ellipse& e);

}  // namespace collide2d
