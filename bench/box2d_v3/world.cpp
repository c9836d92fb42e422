// A World frame against Box2D v3's (linked into bench_world when a Box2D v3 source is given): the
// moving bodies of frame/alone_contacts (bench/movers.h) as v3's dynamic bodies, one shape each (an
// ellipse its inscribed 8-gon, bench/box2d_v3/shapes.h), in a world with no gravity, sleep or
// continuous collision, on one worker. A frame sets every body's transform and zeroes its
// velocities, then steps the world; its time is the pose loop's plus the step's pair update and
// narrow phase (b2Profile::pairs and b2Profile::collide), which make the contacts collide2d's
// update() makes: the solver that follows is v3's own work and is not counted.
#include "bench/box2d_v3/shapes.h"
#include "bench/movers.h"

#include <box2d/box2d.h>

#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <random>
#include <type_traits>
#include <variant>
#include <vector>

namespace collide2d {
namespace {

using box2d_v3::posed;

b2BodyId add_body(b2WorldId world, const Shape& shape) {
  return std::visit(
      [&](const auto& s) {
        const auto p = posed(s);
        b2BodyDef body = b2DefaultBodyDef();
        body.type = b2_dynamicBody;
        body.position = p.transform.p;
        body.rotation = p.transform.q;
        const b2BodyId id = b2CreateBody(world, &body);
        const b2ShapeDef def = b2DefaultShapeDef();
        using S = std::decay_t<decltype(p.shape)>;
        if constexpr (std::is_same_v<S, b2Circle>) {
          b2CreateCircleShape(id, &def, &p.shape);
        } else if constexpr (std::is_same_v<S, b2Capsule>) {
          b2CreateCapsuleShape(id, &def, &p.shape);
        } else if constexpr (std::is_same_v<S, b2Segment>) {
          b2CreateSegmentShape(id, &def, &p.shape);
        } else {
          b2CreatePolygonShape(id, &def, &p.shape);
        }
        return id;
      },
      shape);
}

void box2d_v3_frame(benchmark::State& state) {
  std::mt19937_64 rng(11);
  bench::Movers movers(static_cast<int>(state.range(0)), Vec2::Zero(), rng);
  b2WorldDef def = b2DefaultWorldDef();
  def.gravity = b2Vec2{0.0f, 0.0f};
  def.enableSleep = false;
  def.enableContinuous = false;
  def.workerCount = 1;
  const b2WorldId world = b2CreateWorld(&def);
  std::vector<b2BodyId> bodies;
  for (const Shape& shape : movers.shapes) bodies.push_back(add_body(world, shape));
  const auto pose = [&] {
    movers.step(rng);
    for (std::size_t k = 0; k < bodies.size(); ++k) {
      const b2Transform t = box2d_v3::transform_of(movers.centre[k], movers.angle[k]);
      b2Body_SetTransform(bodies[k], t.p, t.q);
      b2Body_SetLinearVelocity(bodies[k], b2Vec2{0.0f, 0.0f});
      b2Body_SetAngularVelocity(bodies[k], 0.0f);
    }
  };
  // The frame's three timed parts, in seconds.
  const auto frame = [&] {
    const auto start = std::chrono::steady_clock::now();
    pose();
    const double posed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    b2World_Step(world, 1.0f / 60.0f, 1);
    const b2Profile profile = b2World_GetProfile(world);
    return std::array<double, 3>{posed, 1e-3 * profile.pairs, 1e-3 * profile.collide};
  };
  // Steady state, as collide2d's frames: the contacts exist.
  for (int k = 0; k < 20; ++k) frame();
  std::array<double, 3> total{};
  double contacts = 0.0;
  for (auto _ : state) {
    const std::array<double, 3> parts = frame();
    state.SetIterationTime(parts[0] + parts[1] + parts[2]);
    for (int k = 0; k < 3; ++k) total[k] += parts[k];
    contacts += b2World_GetCounters(world).contactCount;
  }
  const double frames = static_cast<double>(state.iterations());
  state.counters["pose_ms"] = 1e3 * total[0] / frames;
  state.counters["pairs_ms"] = 1e3 * total[1] / frames;
  state.counters["collide_ms"] = 1e3 * total[2] / frames;
  state.counters["contacts"] = contacts / frames;
  b2DestroyWorld(world);
}

BENCHMARK(box2d_v3_frame)
    ->Name("box2d_v3_frame/alone_contacts")
    ->Arg(1000)
    ->Arg(10000)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace collide2d
