// Private: the overlap verdict for a point at squared distance q from a shape grown by `reach`
// (a circle's centre against the other shape). Squares decide when they clear reach^2 by far more
// than their rounding, without a square root. Near contact the verdict is `!apart(sqrt(q))`, the
// very test the matching distance query makes, so overlap and distance always agree there.
#pragma once

#include <cmath>

namespace collide2d::detail {

template <class Apart>
bool within_reach(double q, double reach, Apart apart) {
  const double r2 = reach * reach;
  if (q > r2 * (1 + 1e-12)) return false;
  if (q < r2 * (1 - 1e-12)) return true;
  return !apart(std::sqrt(q));
}

}  // namespace collide2d::detail
