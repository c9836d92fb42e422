// Distance between two solid oriented rectangles, with closest points.
// Separated: a closest pair of two disjoint convex polygons always has a vertex of one of them, so
// the distance is the least of the eight vertex-to-box distances (each a clamp in the box's frame).
// Overlapping (overlap_rect_rect): distance 0 and the centroid of the vertices of B clipped to A
// (Sutherland–Hodgman) as witness. Computed in A's frame after subtracting centres; accurate to a
// few ulps of the pair's scale.
#pragma once

#include <collide2d/distance_result.h>

namespace collide2d {

DistanceResult distance_rect_rect(const Rect& a, const Rect& b);

}  // namespace collide2d
