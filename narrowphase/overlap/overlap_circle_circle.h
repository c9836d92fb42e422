// Circle–circle overlap and distance: exact closed forms (|c_b - c_a| against r_a + r_b).
// Overlap witness: the midpoint of the chord of the centre line shared by both discs.
#pragma once

#include <collide2d/distance_result.h>

namespace collide2d {

bool overlap_circle_circle(const Circle& a, const Circle& b);
DistanceResult distance_circle_circle(const Circle& a, const Circle& b);

}  // namespace collide2d
