// World frames against Box2D v3's World (linked into bench_world when a Box2D v3 source is given):
// the moving bodies of frame/alone_contacts (bench/movers.h) and the built-in scene of
// frame/scene_contacts as v3's bodies, one shape each (an ellipse its inscribed 8-gon,
// bench/box2d_v3/shapes.h), in a world with no gravity, sleep or continuous collision, on one
// worker. A frame sets every moving body's transform and zeroes its velocities, then steps the
// world; its time is the pose loop's plus the step's pair update and narrow phase (b2Profile::pairs
// and b2Profile::collide), which make the contacts collide2d's update() makes: the solver that
// follows is v3's own work and is not counted.
#include "bench/box2d_v3/bodies.h"
#include "bench/box2d_v3/shapes.h"
#include "bench/movers.h"
#include "tools/scene/scene.h"

#include <box2d/box2d.h>

#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <random>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace collide2d {
namespace {

using box2d_v3::add_body;
using box2d_v3::filter_of;

// A static chain of b2ChainShape's segments.
void add_chain(b2WorldId world, const tool::SceneBody& b) {
  const b2BodyDef body = b2DefaultBodyDef();
  const b2BodyId id = b2CreateBody(world, &body);
  std::vector<b2Vec2> points;
  for (const Vec2& p : b.chain) points.push_back(box2d_v3::to_float(p));
  b2ChainDef def = b2DefaultChainDef();
  def.points = points.data();
  def.count = static_cast<int>(points.size());
  def.isLoop = b.loop;
  def.filter = filter_of(b.filter);
  b2CreateChain(id, &def);
}

b2WorldId make_world() {
  b2WorldDef def = b2DefaultWorldDef();
  def.gravity = b2Vec2{0.0f, 0.0f};
  def.enableSleep = false;
  def.enableContinuous = false;
  def.workerCount = 1;
  return b2CreateWorld(&def);
}

void set_pose(b2BodyId body, const Vec2& centre, double angle) {
  const b2Transform t = box2d_v3::transform_of(centre, angle);
  b2Body_SetTransform(body, t.p, t.q);
  b2Body_SetLinearVelocity(body, b2Vec2{0.0f, 0.0f});
  b2Body_SetAngularVelocity(body, 0.0f);
}

// The frames of a world whose `pose` moves its bodies, after 20 of warm-up (the contacts exist, as
// in collide2d's frames): each timed as its pose loop plus the step's pairs and collide.
template <class Pose>
void time_frames(benchmark::State& state, b2WorldId world, Pose pose) {
  const auto frame = [&] {
    const auto start = std::chrono::steady_clock::now();
    pose();
    const double posed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    b2World_Step(world, 1.0f / 60.0f, 1);
    const b2Profile profile = b2World_GetProfile(world);
    return std::array<double, 3>{posed, 1e-3 * profile.pairs, 1e-3 * profile.collide};
  };
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
}

void box2d_v3_frame(benchmark::State& state) {
  std::mt19937_64 rng(11);
  bench::Movers movers(static_cast<int>(state.range(0)), Vec2::Zero(), rng);
  const b2WorldId world = make_world();
  std::vector<b2BodyId> bodies;
  for (const Shape& shape : movers.shapes) bodies.push_back(add_body(world, shape));
  time_frames(state, world, [&] {
    movers.step(rng);
    for (std::size_t k = 0; k < bodies.size(); ++k) set_pose(bodies[k], movers.centre[k], movers.angle[k]);
  });
  b2DestroyWorld(world);
}

// The built-in scene of frame/scene_contacts (tool::default_scene): its moving bodies and bullets
// dynamic, its level static (the cave a b2ChainShape loop), its sensors sensor shapes, the layers'
// filters as b2Filter; the same kinematics (tool::step). Bullets are ordinary bodies here, where
// the World also finds their first contacts in the frame.
void box2d_v3_scene_frame(benchmark::State& state) {
  tool::Scene scene = tool::default_scene(static_cast<int>(state.range(0)), 1);
  const b2WorldId world = make_world();
  std::vector<std::pair<const tool::SceneBody*, b2BodyId>> moving;
  for (const tool::SceneBody& b : scene.bodies) {
    if (!b.chain.empty()) {
      add_chain(world, b);
      continue;
    }
    const b2BodyId id =
        add_body(world, tool::placed_first(b), b.is_static ? b2_staticBody : b2_dynamicBody, b.filter, b.sensor);
    if (!b.is_static) moving.emplace_back(&b, id);
  }
  time_frames(state, world, [&] {
    tool::step(scene);
    for (const auto& [b, id] : moving) set_pose(id, b->pose.position, b->pose.angle);
  });
  b2DestroyWorld(world);
}

BENCHMARK(box2d_v3_frame)
    ->Name("box2d_v3_frame/alone_contacts")
    ->Arg(1000)
    ->Arg(10000)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(box2d_v3_scene_frame)
    ->Name("box2d_v3_frame/scene_contacts")
    ->Arg(4000)
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace collide2d
