// Circle–ellipse overlap and distance through the exact point–ellipse distance
// (distance_point_ellipse.h), not a general ellipse–ellipse solver: the circle overlaps the ellipse
// iff its centre is within r of the solid ellipse.
// Overlap answers without the root finder when the centre is inside the ellipse, or farther than r
// from the ellipse's bounding box in the ellipse frame. Overlap witness: the circle centre when it
// is inside the ellipse, else the nearest ellipse point. Accuracy: that of distance_point_ellipse.
#pragma once

#include "narrowphase/distance_result.h"

namespace collide2d {

bool overlap_circle_ellipse(const Circle& c, const Ellipse& e);
// The same, given the ellipse's Orientation::of(angle).
bool overlap_circle_ellipse(const Circle& c, const Ellipse& e, const Orientation& e_orientation);
DistanceResult distance_circle_ellipse(const Circle& c, const Ellipse& e);

}  // namespace collide2d
