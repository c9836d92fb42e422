// Broad phase: one frame, every box moved and then one update, for n boxes in a uniform scene (8% of
// the arena covered, speeds up to 0.2 box sizes per frame, boxes bouncing off the walls).
#include <collide2d/broad_phase.h>
#include "bench/box2d_baseline.h"
#include "tools/random.h"

#include <benchmark/benchmark.h>

#include <malloc.h>

#include <cmath>
#include <random>
#include <vector>

namespace collide2d {
namespace {

struct MovingBoxes {
  std::vector<Vec2> centre;
  std::vector<Vec2> velocity;
  std::vector<double> half;
  double side = 0.0;

  explicit MovingBoxes(int n) {
    std::mt19937_64 rng(7);
    const auto u = [&rng] { return tool::uniform(rng, 0.0, 1.0); };
    side = std::sqrt(28.0 * n);
    for (int k = 0; k < n; ++k) {
      // One draw a statement, y before x: a call's arguments are evaluated in an order the compiler picks.
      const double y = u() * side;
      const double x = u() * side;
      centre.emplace_back(x, y);
      const double vy = 0.2 * (u() - 0.5);
      const double vx = 0.2 * (u() - 0.5);
      velocity.emplace_back(vx, vy);
      half.push_back(0.3 + 1.7 * u());
    }
  }
  Aabb box(std::size_t k) const { return {centre[k] - Vec2::Constant(half[k]), centre[k] + Vec2::Constant(half[k])}; }
  std::vector<Aabb> boxes() const {
    std::vector<Aabb> out;
    for (std::size_t k = 0; k < centre.size(); ++k) out.push_back(box(k));
    return out;
  }
  void step() {
    for (std::size_t k = 0; k < centre.size(); ++k) {
      centre[k] += velocity[k];
      for (int a = 0; a < 2; ++a) {
        if ((centre[k][a] < 0 && velocity[k][a] < 0) || (centre[k][a] > side && velocity[k][a] > 0))
          velocity[k][a] *= -1;
      }
    }
  }
};

using baseline::Box2dBroadPhase;

std::size_t pair_count(const BroadPhaseBase& b) { return b.pairs().size(); }
std::size_t pair_count(const Box2dBroadPhase& b) { return b.pair_count(); }

// Heap in use, counting the large blocks malloc maps directly (hblkhd) as well as the arena.
std::size_t heap_in_use() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;
}

template <class BroadPhase>
void moving_boxes(benchmark::State& state) {
  MovingBoxes scene(static_cast<int>(state.range(0)));
  const std::size_t heap_before = heap_in_use();
  BroadPhase broad(0.1);
  const std::vector<ProxyId> ids = broad.insert_batch(scene.boxes());
  broad.update();
  state.counters["heap_MB"] = static_cast<double>(heap_in_use() - heap_before - ids.capacity() * sizeof(ProxyId)) / 1e6;
  // Timed: every move and the update. The moves are where a dynamic tree does its work (Box2D's
  // MoveProxy reinserts each box that left its fat box), so leaving them out would time only half
  // of Box2D's frame; only the scene's own stepping is excluded.
  for (auto _ : state) {
    state.PauseTiming();
    scene.step();
    state.ResumeTiming();
    for (std::size_t k = 0; k < ids.size(); ++k) broad.move(ids[k], scene.box(k));
    broad.update();
    benchmark::ClobberMemory();
  }
  state.counters["pairs"] = static_cast<double>(pair_count(broad));
}

BENCHMARK(moving_boxes<SweepAndPrune>)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(moving_boxes<Box2dBroadPhase>)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(moving_boxes<SweepAndPrune>)->Arg(1000000)->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK(moving_boxes<Box2dBroadPhase>)->Arg(1000000)->Iterations(3)->Unit(benchmark::kMillisecond);
BENCHMARK(moving_boxes<BruteForceBroadPhase>)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
