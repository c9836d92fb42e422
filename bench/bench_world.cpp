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
//
// Counters: the frame's broad and narrow phase milliseconds (FrameStats), candidate pairs,
// overlapping pairs, heap allocations per frame after 20 frames of warm-up (this binary counts every
// operator new) and the heap in use per body by the World once built (malloc's count, mallinfo2).
#include "engine/world.h"

#include "tests/allocation_counter.h"

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <cmath>
#include <random>
#include <vector>

namespace collide2d {
namespace {

Shape random_shape(std::mt19937_64& rng, const Vec2& c) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double half = 0.3 + 1.7 * u(rng), angle = 2 * M_PI * u(rng);
  switch (rng() % 3) {
    case 0: return Circle{c, half};
    case 1: return Ellipse{c, half, half * (0.2 + 0.8 * u(rng)), angle};
    default: return Rect{c, Vec2(half, half * (0.2 + 0.8 * u(rng))), angle};
  }
}

// Heap in use, counting the large blocks malloc maps directly (hblkhd) as well as the arena.
std::size_t heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

enum class Level { none, static_bodies, static_apart, moving_bodies };

template <Level level>
void frame(benchmark::State& state) {
  const int moving = level == Level::none ? static_cast<int>(state.range(0)) : 1000;
  const int statics = level == Level::none ? 0 : static_cast<int>(state.range(0));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t heap_before = heap_in_use();
  World world({.fat_margin = 0.1, .threads = static_cast<unsigned>(state.range(1))});
  const double level_side = std::sqrt(28.0 * statics), side = std::sqrt(28.0 * moving);
  const Vec2 corner = Vec2::Constant(0.5 * (level_side - side));  // the moving bodies' square, mid-level
  BodyDef def;
  def.is_static = level != Level::moving_bodies;
  for (int added = 0; added < statics;) {
    const Vec2 at(u(rng) * level_side, u(rng) * level_side);
    const bool clear = level == Level::static_apart && ((at - corner).array() > -3.0).all() &&
                       ((at - corner).array() < side + 3.0).all();
    if (clear) continue;
    world.add(random_shape(rng, at), def);
    ++added;
  }
  std::vector<BodyId> ids;
  std::vector<Vec2> velocity;
  for (int k = 0; k < moving; ++k) {
    ids.push_back(world.add(random_shape(rng, corner + Vec2(u(rng) * side, u(rng) * side))));
    velocity.emplace_back(0.2 * (u(rng) - 0.5), 0.2 * (u(rng) - 0.5));
  }
  world.update();
  const std::size_t bench_lists = ids.capacity() * sizeof(BodyId) + velocity.capacity() * sizeof(Vec2);
  state.counters["heap_B_per_body"] = static_cast<double>(heap_in_use() - heap_before - bench_lists) / (moving + statics);
  const auto step = [&] {
    for (int k = 0; k < moving; ++k) {
      const Vec2 at = center_of(world.shape(ids[k])) - corner;
      for (int a = 0; a < 2; ++a) {
        if ((at[a] < 0 && velocity[k][a] < 0) || (at[a] > side && velocity[k][a] > 0)) velocity[k][a] *= -1;
      }
      world.move_by(ids[k], velocity[k], 0.05 * (u(rng) - 0.5));
    }
    world.update();
  };
  // Steady state: the lists have grown to what the scene needs.
  for (int k = 0; k < 20; ++k) step();
  double broad = 0.0, narrow = 0.0, candidates = 0.0, overlapping = 0.0;
  const long allocations_before = testing::allocation_count.load();
  for (auto _ : state) {
    step();
    const FrameStats& f = world.last_frame();
    broad += f.broad_seconds;
    narrow += f.narrow_seconds;
    candidates += static_cast<double>(f.candidates);
    overlapping += static_cast<double>(f.overlapping);
  }
  const double frames = static_cast<double>(state.iterations());
  state.counters["allocs_per_frame"] = static_cast<double>(testing::allocation_count.load() - allocations_before) / frames;
  state.counters["broad_ms"] = 1e3 * broad / frames;
  state.counters["narrow_ms"] = 1e3 * narrow / frames;
  state.counters["candidates"] = candidates / frames;
  state.counters["overlapping"] = overlapping / frames;
}

// Args: the level's size (for "alone", the number of moving bodies), then the World's threads.
BENCHMARK(frame<Level::none>)->Name("frame/alone")->Args({1000, 0})->Unit(benchmark::kMicrosecond);
BENCHMARK(frame<Level::static_bodies>)->Name("frame/level")->Args({10000, 0})->Args({100000, 0})->Unit(benchmark::kMicrosecond);
BENCHMARK(frame<Level::static_apart>)->Name("frame/level_apart")->Args({10000, 0})->Args({100000, 0})->Unit(benchmark::kMicrosecond);
BENCHMARK(frame<Level::moving_bodies>)->Name("frame/level_moving")->Args({10000, 0})->Args({100000, 0})->Unit(benchmark::kMicrosecond);
// The narrow phase on 1 and 2 threads: 100,000 moving bodies (their square 8% covered).
BENCHMARK(frame<Level::none>)->Name("frame/crowd")->Args({100000, 1})->Args({100000, 2})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
