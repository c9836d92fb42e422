// Where a ray first meets a solid shape: exact for circles and ellipses (the root of the quadratic
// of the ray against the curve, not a polygon), slabs for rectangles.
//
// The ray is origin + t direction for 0 <= t <= max_distance, direction a unit vector. A ray that
// starts inside the shape hits it at t = 0 with a zero normal. Inputs are assumed valid (World and
// the command line validate them).
#pragma once

#include <collide2d/shapes.h>

#include <optional>

namespace collide2d {

struct RayShapeHit {
  double distance = 0.0;       // t at the hit
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::Zero();  // outward unit normal at the hit
};

std::optional<RayShapeHit> ray_cast(const Shape& shape, const Vec2& origin, const Vec2& direction,
                                    double max_distance);

}  // namespace collide2d
