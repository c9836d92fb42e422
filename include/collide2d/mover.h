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
#include <collide2d/world.h>

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

/// The fraction of `translation` the mover moves (no turn) before it comes too near `target`.
/// Too near: its separation below its floor, min(initial separation, skin) less 1e-12 of the
/// larger of the mover's reach and its centre's magnitude; the fraction is 1 where it never is, and
/// the mover stops within 1e-9 of its reach above the floor. So a mover starting within the skin of a surface, or
/// slightly inside it, moves along it and away from it and stops only going deeper, and one sliding at the skin never
/// sticks on the rounding of its pose (Box2D v3's encroaching b2ShapeCast, to the skin rather than to a slop). Throws
/// InvalidShape for an invalid shape, a translation that is not finite or carries the centre beyond +-1e50, or a skin
/// that is negative or not finite.
double cast_mover(const Shape& mover, const Vec2& translation, const Shape& target, double skin);

/// The plane of a surface a mover touches (World::collide_mover()), for solve_planes(): the mover
/// may come no nearer than `skin`.
CollisionPlane plane_of(const MoverPlane& plane, double skin);

/// How move() moves a character.
struct MoverOptions {
  /// What the mover sees: its skin (the gap it keeps from surfaces), filter and own body.
  MoverQuery query{};
  /// The steepest floor, in radians from `up`: a surface whose normal lies within it is a floor,
  /// which holds the mover up (it stands on it without sliding, and walks along it at the
  /// commanded horizontal speed); a steeper one facing up is a wall the mover cannot climb, one
  /// facing down a ceiling. In [0, pi/2).
  double max_slope = 0.7853981633974483;
  /// The highest step the mover climbs while on the ground, >= 0.
  double step_height = 0.0;
  /// How far down the mover follows the ground it stood on, >= 0: walking down slopes and steps,
  /// while not moving up.
  double snap_distance = 0.0;
  Vec2 up = Vec2::UnitY();  ///< unit length
  int max_iterations = 5;   ///< of collide, solve and cast, >= 1
  /// Categories of soft shapes, such as other movers: the mover's cast passes them, and each
  /// pushes it at most `soft_push_limit` a move and does not clip its velocity.
  std::uint64_t soft_categories = 0;
  double soft_push_limit = 0.0;  ///< >= 0
};

/// Where the mover stands.
struct Ground {
  bool on_ground = false;       ///< it touches a floor
  Vec2 normal = Vec2::UnitY();  ///< the floor's, the one nearest `up` where it touches several
  BodyId body;                  ///< the floor's body and shape (on_ground only)
  ShapeId shape;
  std::uint64_t user_id = 0;  ///< the body's
};

/// What move() did.
struct MoveResult {
  Vec2 position = Vec2::Zero();  ///< the mover's centre
  Vec2 velocity = Vec2::Zero();  ///< clipped by the surfaces it touches where it ends
  Ground ground{};
  int iterations = 0;  ///< of collide, solve and cast
  /// Whether the move ended where a cast stopped it, the skin from a surface.
  /// That cast is its last, or its step's or snap's landing. A surface touched where the move
  /// starts holds the mover by its plane instead: the clipped velocity shows that.
  bool blocked = false;
};

/// Moves `mover` (no turn) by velocity * dt through the World as a character does: it slides along
/// walls, stands on floors, stops under ceilings, climbs steps up to the step height and follows
/// the ground down by the snap distance; it never comes nearer a surface than the skin, and a
/// seam between two surfaces in line (tiles, a chain's vertices) is never felt. Each iteration
/// collides (World::collide_mover()), solves the planes (solve_planes()) and casts
/// (World::cast_mover()), as Box2D v3's mover sample does; the World is not changed. `ground` is
/// the last move's: a mover standing on a body that moved over the last update moves with it
/// (World::displacement()). Throws std::invalid_argument for a velocity or dt that is not finite, a
/// negative dt, or options outside their ranges, and InvalidShape for an invalid shape.
MoveResult move(const World& world, const Shape& mover, const Vec2& velocity, double dt,
                const MoverOptions& options = {}, const Ground& ground = {});

}  // namespace collide2d
