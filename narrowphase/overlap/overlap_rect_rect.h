// Overlap of two solid oriented rectangles by the separating-axis theorem: the four face normals
// are the only candidate axes in 2D. Computed in A's frame after subtracting centres.
// Exact up to rounding of the projected extents (a few ulps of the pair's scale); touching counts
// as overlap.
#pragma once

#include <collide2d/shapes.h>

namespace collide2d {

bool overlap_rect_rect(const Rect& a, const Rect& b);
// The same, given each one's Orientation::of(angle) (callers that keep them: the World).
bool overlap_rect_rect(const Rect& a, const Orientation& a_orientation, const Rect& b, const Orientation& b_orientation);

}  // namespace collide2d
