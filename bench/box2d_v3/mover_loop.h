// Box2D v3's mover sample's loop, for the benchmarks that race it (bench/box2d_v3/movers.cpp,
// bench/box2d_v3/mover_course.cpp): an upright capsule, at most so many times
// b2World_CollideMover, b2SolvePlanes and b2World_CastMover, stopping on a move under the sample's
// tolerance of 0.01.
#pragma once

#include <box2d/box2d.h>
#include <box2d/collision.h>

#include <array>

namespace collide2d::box2d_v3 {

// The planes of one collide, at most the sample's 8; those past them are dropped, as the sample
// drops them.
struct MoverPlanes {
  std::array<b2CollisionPlane, 8> planes{};
  int count = 0;
  void add(const b2CollisionPlane& p) {
    if (count < static_cast<int>(planes.size())) planes[count++] = p;
  }
};

struct LoopResult {
  float fraction = 1.0f;  // the last cast's
  int iterations = 0;
};

// Moves the capsule of half length `half` and radius `radius`, upright about `at`, toward `target`;
// `keep` (with `context`) adds to `planes` the planes of each collide it keeps, and `planes` ends
// with the last collide's. The casts go past what `cast_filter` leaves out.
inline LoopResult mover_loop(b2WorldId world, b2Vec2& at, const b2Vec2& target, float half, float radius,
                             const b2QueryFilter& filter, const b2QueryFilter& cast_filter, b2PlaneResultFcn* keep,
                             void* context, MoverPlanes& planes, int max_iterations) {
  LoopResult r;
  while (r.iterations < max_iterations) {
    ++r.iterations;
    planes.count = 0;
    const b2Capsule mover{{at.x, at.y - half}, {at.x, at.y + half}, radius};
    b2World_CollideMover(world, b2Pos{0.0f, 0.0f}, &mover, filter, keep, context);
    const b2PlaneSolverResult solved = b2SolvePlanes(b2Sub(target, at), planes.planes.data(), planes.count);
    r.fraction = b2World_CastMover(world, b2Pos{0.0f, 0.0f}, &mover, solved.delta, cast_filter);
    const b2Vec2 delta = b2MulSV(r.fraction, solved.delta);
    at = b2Add(at, delta);
    if (b2LengthSquared(delta) < 0.01f * 0.01f) break;
  }
  return r;
}

}  // namespace collide2d::box2d_v3
