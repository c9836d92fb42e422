// A World frame with a static level: 1,000 moving bodies (circles, ellipses, rectangles; up to 0.1 a
// frame and 0.05 rad, bouncing in a square of side 167, 8% covered) among n static bodies spread at
// the same density over a square as large as they need (n = 100,000: side 1,673), fat margin 0.1.
// One iteration is one frame: every moving body posed, then update(). Every hardware thread unless
// the second argument says otherwise.
//
//   alone:         the 1,000 moving bodies and no level
//   level:         with the n static bodies (BodyDef::is_static)
//   level_apart:   with the n static bodies kept 3 away from the moving bodies' square: what the
//                  level costs when it is not touched
//   level_moving:  with the n level bodies added as moving bodies that never move (a World without
//                  static bodies)
//   alone_contacts: the moving bodies alone (1,000 or 10,000) with contacts on, one thread (Box2D
//                  v3's World on the same bodies: bench/box2d_v3/world.cpp)
//   compound:      n ships of four shapes each (a hull, two wings, a nose), one body each, posed
//                  once a frame (the moving bodies' motion), one thread
//   lockstep:      the same ships as 4 n bodies of one shape, each posed by hand every frame where
//                  its ship puts it, the four of a ship in one negative filter group so that they do
//                  not pair: what a game without bodies of several shapes does
//
// Counters: the frame's broad and narrow phase milliseconds (FrameStats), candidate pairs,
// overlapping pairs, heap allocations per frame after 20 frames of warm-up (this binary counts every
// operator new) and the heap in use per body by the World once built (malloc's count, mallinfo2).
#include <collide2d/world.h>
#include "tools/random.h"
#include "tools/scene/scene.h"
#include "tools/scene/scene_run.h"

#include "bench/box2d_baseline.h"
#include "bench/movers.h"
#include "tests/support/allocation_counter.h"

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <random>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace collide2d {
namespace {

using bench::Movers;
using bench::point_in;
using bench::random_shape;

// Heap in use, counting the large blocks malloc maps directly (hblkhd) as well as the arena.
std::size_t heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

// Per-frame means, as counters, of what a frame benchmark adds up: phase times in seconds, pairs.
struct FrameTotals {
  double broad = 0.0, narrow = 0.0, candidates = 0.0, overlapping = 0.0;

  void add(const FrameStats& f) {
    broad += f.broad_seconds;
    narrow += f.narrow_seconds;
    candidates += static_cast<double>(f.candidates);
    overlapping += static_cast<double>(f.overlapping);
  }
  void report(benchmark::State& state) const {
    const double frames = static_cast<double>(state.iterations());
    state.counters["broad_ms"] = 1e3 * broad / frames;
    state.counters["narrow_ms"] = 1e3 * narrow / frames;
    state.counters["candidates"] = candidates / frames;
    state.counters["overlapping"] = overlapping / frames;
  }
};

enum class Level { none, static_bodies, static_apart, moving_bodies };

template <Level level, bool contacts = false>
void frame(benchmark::State& state) {
  const int moving = level == Level::none ? static_cast<int>(state.range(0)) : 1000;
  const int statics = level == Level::none ? 0 : static_cast<int>(state.range(0));
  std::mt19937_64 rng(11);
  const std::size_t heap_before = heap_in_use();
  World world({.fat_margin = 0.1, .contacts = contacts, .threads = static_cast<unsigned>(state.range(1))});
  const double level_side = std::sqrt(28.0 * statics), side = std::sqrt(28.0 * moving);  // Movers' side
  const Vec2 corner = Vec2::Constant(0.5 * (level_side - side));  // the moving bodies' square, mid-level
  BodyDef def;
  def.is_static = level != Level::moving_bodies;
  for (int added = 0; added < statics;) {
    const Vec2 at = point_in(rng, Vec2::Zero(), level_side);
    const bool clear = level == Level::static_apart && ((at - corner).array() > -3.0).all() &&
                       ((at - corner).array() < side + 3.0).all();
    if (clear) continue;
    world.add(random_shape(rng, at), def);
    ++added;
  }
  Movers movers(moving, corner, rng);
  std::vector<BodyId> ids;
  for (const Shape& shape : movers.shapes) ids.push_back(world.add(shape));
  world.update();
  const std::size_t bench_lists = movers.heap() + ids.capacity() * sizeof(BodyId);
  state.counters["heap_B_per_body"] =
      static_cast<double>(heap_in_use() - heap_before - bench_lists) / (moving + statics);
  const auto step = [&] {
    movers.step(rng);
    for (int k = 0; k < moving; ++k) world.set_pose(ids[k], movers.centre[k], movers.angle[k]);
    world.update();
  };
  // Steady state: the lists have grown to what the scene needs.
  for (int k = 0; k < 20; ++k) step();
  FrameTotals totals;
  const long allocations_before = testing::allocation_count.load();
  for (auto _ : state) {
    step();
    totals.add(world.last_frame());
  }
  const double frames = static_cast<double>(state.iterations());
  state.counters["allocs_per_frame"] =
      static_cast<double>(testing::allocation_count.load() - allocations_before) / frames;
  totals.report(state);
}

// A ship in its own frame: a hull, two wings and a nose.
const Shape kShip[] = {Ellipse{Vec2(0, 0), 0.8, 0.3, 0.0}, Rect{Vec2(0, 0.6), Vec2(0.25, 0.4), 0.0},
                       Rect{Vec2(0, -0.6), Vec2(0.25, 0.4), 0.0}, Circle{Vec2(0.9, 0), 0.25}};

// The ships' scene, one iteration a frame, in either form (the lockstep poses each shape with
// placed(), as the World does: test_world_shapes checks that both find the same pairs).
template <bool compound>
void ships(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::mt19937_64 rng(13);
  Movers movers(n, Vec2::Zero(), rng);
  World world({.fat_margin = 0.1, .threads = 1});
  std::vector<BodyId> ids;
  std::vector<ShapeDef> defs;
  for (const Shape& s : kShip) defs.push_back({.shape = s});
  for (int k = 0; k < n; ++k) {
    if (compound) {
      ids.push_back(world.add(Pose{movers.centre[k], movers.angle[k]}, defs));
      continue;
    }
    const Orientation turn = Orientation::of(movers.angle[k]);
    for (const Shape& s : kShip) {
      const BodyDef def{.filter = {.group = -(k + 1)}};
      ids.push_back(world.add(placed(s, {movers.centre[k], movers.angle[k]}, turn), def));
    }
  }
  const auto step = [&] {
    movers.step(rng);
    for (int k = 0; k < n; ++k) {
      if (compound) {
        world.move_to(ids[k], movers.centre[k], movers.angle[k]);
        continue;
      }
      const Orientation turn = Orientation::of(movers.angle[k]);
      for (int j = 0; j < 4; ++j) {
        const Shape s = placed(kShip[j], {movers.centre[k], movers.angle[k]}, turn);
        world.set_pose(ids[4 * k + j], center_of(s), angle_of(s));
      }
    }
    world.update();
  };
  for (int k = 0; k < 20; ++k) step();
  FrameTotals totals;
  for (auto _ : state) {
    step();
    totals.add(world.last_frame());
  }
  totals.report(state);
}

// Box2D 2.4.1's pipeline on the same moving bodies, the rival: each body a Box2D shape in its own
// frame (an ellipse its inscribed 8-gon, a rectangle its 4-gon, a circle exact) with a b2Transform.
// A frame poses every body (its transform, b2Shape::ComputeAABB, MoveProxy: b2Body's
// SynchronizeFixtures, with one box per pose where Box2D unites the step's two), updates the broad
// phase (baseline::Box2dBroadPhase), then runs b2TestOverlap on every current pair, as
// b2Contact::Update runs on every contact each step. Its pair set is a hash set where b2World keeps
// a contact list in a block allocator, so its allocations are not reported.
class Box2dWorld {
 public:
  // With filters, a pair passes them (should_pair, Box2D's b2ContactFilter rule) before its test,
  // as b2ContactManager::AddPair asks ShouldCollide before it makes a contact.
  explicit Box2dWorld(const std::vector<Shape>& shapes, std::vector<Filter> filters = {})
      : filters_(std::move(filters)) {
    std::vector<Aabb> boxes;
    for (const Shape& shape : shapes) {
      const Shape local = std::visit(
          [](auto s) -> Shape {
            s.center = Vec2::Zero();
            if constexpr (!std::is_same_v<decltype(s), Circle>) s.angle = 0.0;
            return s;
          },
          shape);
      shapes_.push_back(baseline::to_box2d_shape(baseline::to_box2d(local, 8, baseline::Fit::inscribed, Vec2::Zero())));
      transforms_.emplace_back();
      boxes.push_back(aabb(shape));
    }
    broad_.insert_batch(boxes);
  }
  void set_pose(std::size_t k, const Vec2& centre, double angle) {
    transforms_[k].Set(b2Vec2(static_cast<float>(centre.x()), static_cast<float>(centre.y())),
                       static_cast<float>(angle));
    b2AABB box;
    shapes_[k].shape()->ComputeAABB(&box, transforms_[k], 0);
    broad_.move(static_cast<std::uint32_t>(k), box);
  }
  void update_broad_phase() { broad_.update(); }
  std::size_t narrow_phase() const {
    std::size_t overlapping = 0;
    for (const std::uint64_t key : broad_.pairs()) {
      const std::size_t a = key >> 32, b = key & 0xffffffffu;
      if (!filters_.empty() && !should_pair(filters_[a], filters_[b])) continue;
      overlapping +=
          b2TestOverlap(shapes_[a].shape(), 0, shapes_[b].shape(), 0, transforms_[a], transforms_[b]) ? 1 : 0;
    }
    return overlapping;
  }
  std::size_t candidates() const { return broad_.pair_count(); }

 private:
  std::vector<baseline::Box2dShape> shapes_;
  std::vector<b2Transform> transforms_;
  std::vector<Filter> filters_;
  baseline::Box2dBroadPhase broad_;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Box2dWorld's frames after 20 of warm-up: pose() moves the bodies and updates the broad phase
// (timed as its broad phase), then every pair is tested.
template <class Pose>
void time_box2d_frames(benchmark::State& state, Box2dWorld& world, Pose pose) {
  for (int k = 0; k < 20; ++k) {
    pose();
    world.narrow_phase();
  }
  FrameTotals totals;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    pose();
    totals.broad += seconds_since(start);
    const auto narrow_start = std::chrono::steady_clock::now();
    totals.overlapping += static_cast<double>(world.narrow_phase());
    totals.narrow += seconds_since(narrow_start);
    totals.candidates += static_cast<double>(world.candidates());
  }
  totals.report(state);
}

// The "alone" and "crowd" scenes of frame<> through Box2dWorld: the same bodies, the same motion.
void box2d_frame(benchmark::State& state) {
  const int moving = static_cast<int>(state.range(0));
  std::mt19937_64 rng(11);
  const std::size_t heap_before = heap_in_use();
  Movers movers(moving, Vec2::Zero(), rng);
  Box2dWorld world(movers.shapes);
  const auto pose = [&] {
    movers.step(rng);
    for (std::size_t k = 0; k < movers.centre.size(); ++k) world.set_pose(k, movers.centre[k], movers.angle[k]);
    world.update_broad_phase();
  };
  pose();
  state.counters["heap_B_per_body"] = static_cast<double>(heap_in_use() - heap_before - movers.heap()) / moving;
  time_box2d_frames(state, world, pose);
}

// The built-in scene of `collide2d run` (tool::default_scene: n mixed bodies, a quarter of them on a
// second layer, one bullet per 500, a static level and four sensors), one frame per iteration: its
// kinematics, the poses and update() on the second argument's threads (0: every hardware thread, as
// the command runs it); with contacts, a contact for every overlapping pair.
template <bool contacts = false>
void scene_frame(benchmark::State& state) {
  tool::Scene scene = tool::default_scene(static_cast<int>(state.range(0)), 1);
  scene.contacts = contacts;
  tool::SceneRun run(std::move(scene), static_cast<unsigned>(state.range(1)));
  for (int k = 0; k < 20; ++k) run.frame();
  FrameTotals totals;
  for (auto _ : state) {
    run.frame();
    totals.add(run.world().last_frame());
  }
  totals.report(state);
}

// The built-in scene through Box2dWorld: every body (the static ones never posed, so that, as in
// Box2D, they pair only with bodies that move), the same kinematics, the layers' filters. Its
// bullets are tested for overlap only, where the World also finds their first contacts in the frame.
void box2d_scene_frame(benchmark::State& state) {
  tool::Scene scene = tool::default_scene(static_cast<int>(state.range(0)), 1);
  std::vector<Shape> shapes;
  std::vector<Filter> filters;
  // The built-in scene's bodies are of one shape but its cave, a chain: its first segment stands at
  // the cave's index and the others follow every body, each a proxy of its own, as b2ChainShape's
  // children are (never posed: static).
  for (const tool::SceneBody& b : scene.bodies) {
    shapes.push_back(tool::placed_first(b));
    filters.push_back(b.filter);
  }
  for (const tool::SceneBody& b : scene.bodies) {
    const std::vector<Shape> segments = b.chain.empty() ? std::vector<Shape>{} : tool::placed_shapes(b);
    for (std::size_t k = 1; k < segments.size(); ++k) {
      shapes.push_back(segments[k]);
      filters.push_back(b.filter);
    }
  }
  Box2dWorld world(shapes, filters);
  const auto pose = [&] {
    tool::step(scene);
    for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
      const tool::SceneBody& b = scene.bodies[k];
      if (!b.is_static) world.set_pose(k, b.pose.position, b.pose.angle);
    }
    world.update_broad_phase();
  };
  time_box2d_frames(state, world, pose);
}

// Args: the level's size (for "alone", the number of moving bodies), then the World's threads: one,
// as Box2D runs, wherever the two are compared.
BENCHMARK(frame<Level::none>)->Name("frame/alone")->Args({1000, 1})->Unit(benchmark::kMicrosecond);
BENCHMARK(ships<true>)->Name("frame/compound")->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(ships<false>)->Name("frame/lockstep")->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(frame<Level::none, true>)
    ->Name("frame/alone_contacts")
    ->Args({1000, 1})
    ->Args({10000, 1})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(frame<Level::static_bodies>)
    ->Name("frame/level")
    ->Args({10000, 1})
    ->Args({100000, 1})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(frame<Level::static_apart>)
    ->Name("frame/level_apart")
    ->Args({10000, 1})
    ->Args({100000, 1})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(frame<Level::moving_bodies>)
    ->Name("frame/level_moving")
    ->Args({10000, 1})
    ->Args({100000, 1})
    ->Unit(benchmark::kMicrosecond);
// The narrow phase on 1 and 2 threads: 100,000 moving bodies (their square 8% covered).
BENCHMARK(frame<Level::none>)->Name("frame/crowd")->Args({100000, 1})->Args({100000, 2})->Unit(benchmark::kMillisecond);
BENCHMARK(box2d_frame)->Name("box2d_frame/alone")->Arg(1000)->Unit(benchmark::kMicrosecond);
BENCHMARK(box2d_frame)->Name("box2d_frame/crowd")->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(scene_frame)->Name("frame/scene")->Args({4000, 1})->Args({4000, 2})->Unit(benchmark::kMicrosecond);
BENCHMARK(scene_frame<true>)->Name("frame/scene_contacts")->Args({4000, 1})->Unit(benchmark::kMicrosecond);
BENCHMARK(box2d_scene_frame)->Name("box2d_frame/scene")->Arg(4000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
