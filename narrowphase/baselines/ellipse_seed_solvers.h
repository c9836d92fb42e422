// Private: the two seed solvers for the distance between two ellipse curves (see
// distance_ellipse_ellipse.h). Both return the curve-to-curve result, whatever the solids do.
#pragma once

#include "narrowphase/distance/distance_ellipse_ellipse.h"

namespace collide2d::detail {

// Seed 000: gradient descent on the two curve parameters.
SolverReport gradient_descent_curves(const Ellipse& a, const Ellipse& b);

// Seed 001: the degree-12 polynomial (the quartic when either ellipse is a circle).
SolverReport polynomial_curves(const Ellipse& a, const Ellipse& b);

}  // namespace collide2d::detail
