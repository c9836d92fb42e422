/// @file
/// Moving a character: the planes a mover must not pass, the translation that respects them and the
/// velocity with the blocked components removed (Box2D v3's b2SolvePlanes and b2ClipVector, solved
/// exactly rather than to a slop).
///
///   CollisionPlane planes[] = {{.normal = Vec2(0, 1)},    // a floor under the mover
///                              {.normal = Vec2(-1, 0)}};  // and a wall to its right
///   solve_planes(Vec2(0.375, -0.25), planes).delta;       // (0, 0): blocked both ways
///   clip_vector(Vec2(2.0, -1.0), planes);                 // (0, 0) too
///   solve_planes(Vec2(-0.5, 0.5), planes).delta;          // (-0.5, 0.5): away from both
#pragma once

#include <collide2d/shapes.h>

#include <limits>
#include <span>

namespace collide2d {

/// A surface the mover touches, as a plane through the mover's start: a translation delta respects
/// it where normal.delta >= offset. A surface the mover rests `skin` from at a separation s gives
/// offset = skin - s (negative: it may come that much closer; positive: it must back out).
struct CollisionPlane {
  Vec2 normal = Vec2::UnitY();  ///< unit length, from the surface towards the mover
  double offset = 0.0;          ///< the least translation along the normal
  /// The most the plane pushes the mover, a length: infinite for level geometry, finite for a soft
  /// surface such as another character, which the mover may then overlap.
  double push_limit = std::numeric_limits<double>::infinity();
  bool clip_velocity = true;  ///< whether clip_vector() removes the velocity into the plane
  double push = 0.0;          ///< written by solve_planes(): how far the plane pushed the mover
};

/// What solve_planes() found.
struct PlaneSolution {
  Vec2 delta = Vec2::Zero();  ///< the translation: target_delta plus each plane's push along its normal
  int iterations = 0;         ///< sweeps over the planes, for diagnostics
};

/// The translation nearest `target_delta` that the planes allow; each plane's push is written into it.
/// delta = target_delta + the sum of push * normal, 0 <= push <= push_limit; a plane pushing less
/// than its limit is respected (normal.delta >= offset), a soft one pushing its limit may be
/// overlapped. Projected Gauss-Seidel sweeps (as Box2D's solver) find which planes push; those then
/// hold exactly, the translation computed from them and checked against every plane to a few units
/// in the last place of the offsets and the target. Planes no translation can respect together
/// (opposed walls closer than the mover) leave the last sweep's translation. Throws
/// std::invalid_argument for a target or offset that is not finite, a normal not of unit length,
/// or a push limit that is negative or NaN, naming the plane.
PlaneSolution solve_planes(const Vec2& target_delta, std::span<CollisionPlane> planes);

/// The velocity nearest `v` that moves into no plane that pushed (push > 0) and clips velocity.
/// That is v less its component into one plane, or zero in a crease of two: the nearest point of
/// the cone normal.v >= 0, so that clipping by one plane never turns it into another. Validates as
/// solve_planes().
Vec2 clip_vector(const Vec2& v, std::span<const CollisionPlane> planes);

}  // namespace collide2d
