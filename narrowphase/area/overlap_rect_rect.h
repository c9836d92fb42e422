// Private: the area of two rectangles' overlap in double, for IoU, which needs neither the centroid
// nor the crossings.
#pragma once

#include <collide2d/shapes.h>

namespace collide2d::detail::areas {

// The area of A ∩ B to a few eps of the larger rectangle's area; 0 or below where they are apart or
// touch. The callers take a small result again in double-double.
double rect_rect_area(const Rect& a, const Rect& b);

}  // namespace collide2d::detail::areas
