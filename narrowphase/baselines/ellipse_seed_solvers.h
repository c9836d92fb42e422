// Private to the baselines: the two solvers for the distance between two ellipse curves
// (baselines.h). Both return the curve-to-curve result, whatever the solids do.
#pragma once

#include "narrowphase/distance/distance_ellipse_ellipse.h"

namespace collide2d::detail {

// Gradient descent on the two curve parameters (ellipse_gradient.cpp).
SolverReport gradient_descent_curves(const Ellipse& a, const Ellipse& b);

// The degree-12 polynomial, the quartic when either ellipse is a circle (ellipse_polynomial.cpp).
SolverReport polynomial_curves(const Ellipse& a, const Ellipse& b);

}  // namespace collide2d::detail
