// Rectangle–circle overlap and distance: exact closed forms. The circle centre is moved into the
// rectangle's frame (centres subtracted first) and clamped to the box; that clamp is the rectangle
// point nearest the centre. Overlap witness: the circle centre when it is inside the rectangle,
// else that nearest rectangle point.
#pragma once

#include <collide2d/distance_result.h>

namespace collide2d {

bool overlap_rect_circle(const Rect& r, const Circle& c);
// The same, given the rectangle's Orientation::of(angle).
bool overlap_rect_circle(const Rect& r, const Orientation& r_orientation, const Circle& c);
DistanceResult distance_rect_circle(const Rect& r, const Circle& c);

}  // namespace collide2d
