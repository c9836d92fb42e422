// The result of every distance query in collide2d.
#pragma once

#include <collide2d/shapes.h>

#include <algorithm>
#include <limits>

namespace collide2d {

// Distance between two solid shapes A and B (in the order the query was given).
// - Disjoint: `distance` > 0, `point_a` on A's boundary and `point_b` on B's boundary are a closest
//   pair, so distance == |point_b - point_a| up to rounding. A pair the overlap test finds apart by
//   less than the rounding of its coordinates still reports a positive distance (at least the
//   smallest double), so that distance 0 always means what overlaps() says.
// - Overlapping (the solids share a point, touching included): `distance` == 0 and
//   point_a == point_b is a witness point that lies in both solids.
// All points are in the world frame.
struct DistanceResult {
  bool overlapping = false;
  double distance = 0.0;
  Vec2 point_a = Vec2::Zero();
  Vec2 point_b = Vec2::Zero();

  // The same result for the query (B, A).
  DistanceResult swapped() const { return {overlapping, distance, point_b, point_a}; }

  static DistanceResult touching(const Vec2& witness) { return {true, 0.0, witness, witness}; }
  static DistanceResult apart(double distance, const Vec2& a, const Vec2& b) {
    return {false, std::max(distance, std::numeric_limits<double>::denorm_min()), a, b};
  }
};

}  // namespace collide2d
