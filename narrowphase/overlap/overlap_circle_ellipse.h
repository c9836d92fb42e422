// Circle–ellipse overlap and distance through the exact point–ellipse distance
// (distance_point_ellipse.h), not a general ellipse–ellipse solver: the circle overlaps the ellipse
// iff its centre is within r of the solid ellipse.
// Overlap answers without the root finder when the centre is inside the ellipse, farther than r
// from the ellipse's bounding box in the ellipse frame, within r of the boundary point on the ray
// from the ellipse's centre through the circle's, or beyond r of the tangent line there (each by
// more than the rounding of the distance). Overlap witness: the circle centre when it
// is inside the ellipse, else the nearest ellipse point. Accuracy: that of distance_point_ellipse.
#pragma once

#include <collide2d/distance_result.h>

namespace collide2d {

bool overlap_circle_ellipse(const Circle& c, const Ellipse& e);
// The same, given the ellipse's Orientation::of(angle).
bool overlap_circle_ellipse(const Circle& c, const Ellipse& e, const Orientation& e_orientation);
DistanceResult distance_circle_ellipse(const Circle& c, const Ellipse& e);

}  // namespace collide2d
