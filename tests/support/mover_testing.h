// Test helpers for the mover's tests (tests/unit/test_mover_*.cpp, test_world_mover.cpp): a random
// shape of each kind a mover or a level may have.
#pragma once

#include <collide2d/shapes.h>

#include "tools/random.h"

#include <cmath>
#include <random>
#include <vector>

namespace collide2d::testing {

// A shape of kind k, about `size` across from centre c: 0 circle, 1 ellipse, 2 rectangle, 3 capsule,
// 4 convex polygon, 5 rounded polygon, 6 segment (level geometry only).
inline Shape random_kind(std::mt19937_64& rng, int kind, const Vec2& c, double size) {
  const double angle = tool::uniform(rng, 0, 6.3), thin = tool::uniform(rng, 0.05, 1.0);
  const auto polygon = [&](double radius) {
    std::vector<Vec2> points;
    const int n = 3 + static_cast<int>(tool::uniform(rng, 0, 6));
    for (int i = 0; i < n; ++i) points.push_back(tool::uniform_point(rng, -size, size));
    return ConvexPolygon::hull(points, radius).at(c, angle);
  };
  switch (kind) {
    case 0:
      return Circle{c, size};
    case 1:
      return Ellipse{c, size, size * thin, angle};
    case 2:
      return Rect{c, Vec2(size, size * thin), angle};
    case 3:
      return Capsule{c, size, size * thin, angle};
    case 4:
      return polygon(0.0);
    case 5:
      return polygon(0.2 * size);
    default:
      return Segment{c, Vec2(2 * size * std::cos(angle), 2 * size * std::sin(angle)), 0.0};
  }
}

}  // namespace collide2d::testing
