// A 50-digit reference for the overlap area and its centroid, by an algorithm other than the
// library's: no crossing is solved for in closed form and no arc's area is taken from a formula.
// Each shape's boundary is a loop of parametrised pieces (edges, and arcs of circles and ellipses
// by their angle), in 50 digits with the exact cosines and sines of the angles. Each piece of one
// shape is cut where it crosses each piece of the other: the roots of the other piece's curve
// function (its line's cross product, its conic's quadratic form) along it, found by halving
// [0, 1] and dropping each interval whose ends lie too far from zero for the slope (its value at
// the middle and a bound on the second derivative) to reach it, down to 2^-120, where a change of
// sign is a root. Between those cuts a run is kept where it lies inside the other shape (on its
// boundary too for the first shape's pieces, where the two boundaries run together the same way),
// and Green's theorem integrates x dy - y dx and the moments over the kept runs by 24-point
// Gauss-Legendre quadrature (four panels per arc).
#pragma once

#include "mp_reference.h"

namespace collide2d::reference {

struct AreaReference {
  Real area;
  Point centroid;  // meaningless where the area is 0
};

AreaReference overlap_area(const Shape& a, const Shape& b);

// The area of one solid, by the same quadrature over its whole boundary.
Real area(const Shape& s);

}  // namespace collide2d::reference
