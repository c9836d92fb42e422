// A rival for the overlap area of two ellipses in plain double, following the method of G. B. Hughes
// and M. Chraibi, "Calculating ellipse overlap areas" (Computing and Visualization in Science 15,
// 2012): the second ellipse in the first's frame as a conic; its crossings with the first, the real
// roots of a quartic solved in closed form (Ferrari's, by a resolvent cubic); the overlap as the
// polygon of the crossings plus, between each two, the segment of whichever ellipse bounds it there,
// each segment a sector less a triangle. The benchmarks race it and the accuracy tests measure it on
// the hard families.
#pragma once

#include <collide2d/shapes.h>

namespace collide2d::baselines {

double ellipse_overlap_area(const Ellipse& a, const Ellipse& b);

}  // namespace collide2d::baselines
