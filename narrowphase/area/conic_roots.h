// Private: where the unit circle meets an ellipse, the crossings of two conic arcs.
#pragma once

#include <collide2d/shapes.h>

#include <Eigen/Core>

#include <array>

namespace collide2d::detail::areas {

struct UnitCircleRoots {
  std::array<Vec2, 4> u{};
  int count = 0;
};

// The unit vectors u at which |N u + h| = 1: where the unit circle meets the ellipse that the
// linear map N and the offset h carry onto the unit circle (another conic seen in the first one's
// frame). None for two curves that coincide to rounding.
UnitCircleRoots unit_circle_meets(const Eigen::Matrix2d& n, const Vec2& h);

}  // namespace collide2d::detail::areas
