// Box2D v3's character mover on the movers' benchmark level (bench/mover_level.h; linked into
// bench_movers when a Box2D v3 source is given): the level's shapes as static bodies, and for each
// of the 1,000 capsule movers a frame of its mover sample's loop (bench/box2d_v3/mover_loop.h),
// then b2ClipVector; on the ground where a plane's normal lies within 45 degrees of up, as move()
// decides with its default max_slope.
#include "bench/box2d_v3/bodies.h"
#include "bench/box2d_v3/mover_loop.h"
#include "bench/mover_level.h"

#include <box2d/box2d.h>
#include <box2d/collision.h>

#include <benchmark/benchmark.h>

#include <cfloat>
#include <vector>

namespace collide2d {
namespace {

using namespace bench;

constexpr float kRadius = 0.3f, kHalf = 0.3f;

bool keep_plane(b2ShapeId, const b2PlaneResult* result, void* context) {
  if (result->hit) static_cast<box2d_v3::MoverPlanes*>(context)->add({result->plane, FLT_MAX, 0.0f, true});
  return true;
}

struct Crowd {
  b2WorldId world;
  std::vector<b2Vec2> position, velocity;
  std::vector<bool> on_ground;
  std::vector<MoverInput> input;
  int iterations = 0;

  Crowd() {
    b2WorldDef def = b2DefaultWorldDef();
    def.gravity = b2Vec2{0.0f, 0.0f};
    def.workerCount = 1;
    world = b2CreateWorld(&def);
    const std::vector<Shape> level = mover_level();
    for (const Shape& s : level) box2d_v3::add_body(world, s, b2_staticBody);
    b2World_Step(world, static_cast<float>(kFrame), 1);
    for (const Vec2& c : mover_starts(level)) {
      position.push_back(box2d_v3::to_float(c));
      input.emplace_back(static_cast<int>(input.size()));
    }
    velocity.assign(position.size(), b2Vec2{0.0f, 0.0f});
    on_ground.assign(position.size(), false);
  }
  ~Crowd() { b2DestroyWorld(world); }
  Crowd(const Crowd&) = delete;
  Crowd& operator=(const Crowd&) = delete;

  void move(std::size_t k) {
    const Vec2 v = input[k].velocity(Vec2(velocity[k].x, velocity[k].y), on_ground[k]);
    const b2Vec2 wanted{static_cast<float>(v.x()), static_cast<float>(v.y())};
    const b2Vec2 target = b2MulAdd(position[k], static_cast<float>(kFrame), wanted);
    const b2QueryFilter filter = b2DefaultQueryFilter();
    box2d_v3::MoverPlanes p;
    iterations +=
        box2d_v3::mover_loop(world, position[k], target, kHalf, kRadius, filter, filter, keep_plane, &p, p, kIterations)
            .iterations;
    velocity[k] = b2ClipVector(wanted, p.planes.data(), p.count);
    bool ground = false;
    for (int i = 0; i < p.count; ++i) ground = ground || p.planes[i].plane.normal.y >= 0.70710678f;
    on_ground[k] = ground;
  }
  void frame() {
    for (std::size_t k = 0; k < position.size(); ++k) move(k);
  }
};

void box2d_v3_capsules(benchmark::State& state) {
  Crowd crowd;
  for (int k = 0; k < 60; ++k) crowd.frame();
  crowd.iterations = 0;
  double on_ground = 0.0;
  for (auto _ : state) {
    crowd.frame();
    for (const bool g : crowd.on_ground) on_ground += g;
  }
  const double moves = static_cast<double>(state.iterations()) * kMovers;
  state.counters["iterations_per_move"] = crowd.iterations / moves;
  state.counters["on_ground"] = on_ground / moves;
}

BENCHMARK(box2d_v3_capsules)->Name("movers/capsule/box2d_v3")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace collide2d
