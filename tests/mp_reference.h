// A 50-digit reference for the narrow-phase tests, by algorithms other than the kernels':
// - point–solid ellipse: Newton from the left on the secular equation in t (convex, decreasing);
// - rectangle–ellipse distance: golden-section search over each rectangle edge of the point–ellipse
//   distance (the distance to a convex set is convex along a segment); overlap: the least ellipse
//   quadratic over the rectangle's edges (closed form per edge) or the centre in the rectangle;
// - polygons: least point–segment distance over all vertex–edge pairs, overlap by separating axes.
// Inputs are the double shapes, taken exactly; angles become exact 50-digit cosines and sines.
#pragma once

#include "shapes/shapes.h"

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace collide2d::reference {

using Real = boost::multiprecision::cpp_bin_float_50;

struct Point {
  Real x;
  Real y;
};

Point to_mp(const Vec2& p);

// Distance from p to the solid shape (0 inside).
Real distance_to(const Shape& s, const Point& p);

// Whether the two solids overlap, and their distance (0 when they do). Any pair but ellipse–ellipse.
bool overlap(const Shape& a, const Shape& b);
Real distance(const Shape& a, const Shape& b);

}  // namespace collide2d::reference
