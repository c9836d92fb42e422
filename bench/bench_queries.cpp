// Queries through a box tree: the boxes within a query box, and the boxes along a ray, over n boxes
// in a uniform scene (the broad-phase benchmark's: 8% of the arena covered, half sides 0.3 to 2),
// against Box2D 2.4.1's b2DynamicTree::Query and RayCast on the same boxes. Box2D's CreateProxy
// grows each box by b2_aabbMargin = 0.1, so ours are grown by 0.1 too. Query boxes have half side 4;
// rays start anywhere in the arena, in any direction, 30 long. Both report every box they meet (the
// box part of a World query; World queries then test the exact shapes, timed in bench_world).
//
// Our tree is timed as insert() leaves it (the order of insertion, as Box2D's) and after rebuild()
// (what the World does for static bodies).
#include "bench/box2d_baseline.h"
#include "broadphase/aabb_tree.h"

#include <benchmark/benchmark.h>
#include <box2d/b2_dynamic_tree.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <vector>

namespace collide2d {
namespace {

constexpr int kQueries = 1024;

struct Scene {
  std::vector<Aabb> boxes;
  std::vector<Aabb> queries;
  std::vector<std::pair<Vec2, Vec2>> rays;  // origin, unit direction

  explicit Scene(int n) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double side = std::sqrt(28.0 * n);
    for (int k = 0; k < n; ++k) {
      const Vec2 c(u(rng) * side, u(rng) * side);
      const double half = 0.3 + 1.7 * u(rng) + 0.1;
      boxes.push_back({c.array() - half, c.array() + half});
    }
    for (int k = 0; k < kQueries; ++k) {
      const Vec2 c(u(rng) * side, u(rng) * side);
      queries.push_back({c.array() - 4.0, c.array() + 4.0});
      const double a = 2 * M_PI * u(rng);
      rays.emplace_back(Vec2(u(rng) * side, u(rng) * side), Vec2(std::cos(a), std::sin(a)));
    }
  }
};
constexpr double kRayLength = 30.0;

const Scene& scene(int n) {
  static std::map<int, std::unique_ptr<Scene>> cache;
  auto& s = cache[n];
  if (!s) s = std::make_unique<Scene>(n);
  return *s;
}

struct Ours {
  AabbTree tree;
  Ours(const Scene& s, bool rebuilt) {
    for (std::size_t k = 0; k < s.boxes.size(); ++k) tree.insert(s.boxes[k], static_cast<std::uint32_t>(k));
    if (rebuilt) tree.rebuild();
  }
  std::size_t query(const Aabb& box) const {
    std::size_t hits = 0;
    tree.query(box, [&hits](std::uint32_t) { ++hits; });
    return hits;
  }
  std::size_t ray(const Vec2& o, const Vec2& d) const {
    std::size_t hits = 0;
    tree.ray_cast(o, d, kRayLength, [&hits](std::uint32_t, double reach) {
      ++hits;
      return reach;
    });
    return hits;
  }
};

struct Box2d {
  b2DynamicTree tree;
  mutable std::size_t hits = 0;
  Box2d(const Scene& s, bool) {
    for (const Aabb& box : s.boxes) {  // CreateProxy grows it by 0.1 again
      tree.CreateProxy(baseline::to_box2d({box.min.array() + 0.1, box.max.array() - 0.1}), nullptr);
    }
  }
  bool QueryCallback(int32) {
    ++hits;
    return true;
  }
  float RayCastCallback(const b2RayCastInput& input, int32) {
    ++hits;
    return input.maxFraction;
  }
  std::size_t query(const Aabb& box) const {
    hits = 0;
    tree.Query(const_cast<Box2d*>(this), baseline::to_box2d(box));
    return hits;
  }
  std::size_t ray(const Vec2& o, const Vec2& d) const {
    hits = 0;
    b2RayCastInput input;
    input.p1.Set(static_cast<float>(o.x()), static_cast<float>(o.y()));
    input.p2.Set(static_cast<float>(o.x() + kRayLength * d.x()), static_cast<float>(o.y() + kRayLength * d.y()));
    input.maxFraction = 1.0f;
    tree.RayCast(const_cast<Box2d*>(this), input);
    return hits;
  }
};

template <class Tree, bool rebuilt>
const Tree& tree_of(int n) {
  static std::map<int, std::unique_ptr<Tree>> cache;
  auto& t = cache[n];
  if (!t) t = std::make_unique<Tree>(scene(n), rebuilt);
  return *t;
}

template <class Tree, bool rebuilt, bool ray>
void run(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Scene& s = scene(n);
  const Tree& tree = tree_of<Tree, rebuilt>(n);
  std::size_t k = 0, hits = 0;
  for (auto _ : state) {
    const std::size_t q = k++ % kQueries;
    hits += ray ? tree.ray(s.rays[q].first, s.rays[q].second) : tree.query(s.queries[q]);
  }
  state.counters["hits"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
}
template <class Tree, bool rebuilt>
void box_query(benchmark::State& state) { run<Tree, rebuilt, false>(state); }
template <class Tree, bool rebuilt>
void ray_query(benchmark::State& state) { run<Tree, rebuilt, true>(state); }

#define SIZES ->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000)
BENCHMARK(box_query<Ours, false>) SIZES;
BENCHMARK(box_query<Ours, true>) SIZES;
BENCHMARK(box_query<Box2d, false>) SIZES;
BENCHMARK(ray_query<Ours, false>) SIZES;
BENCHMARK(ray_query<Ours, true>) SIZES;
BENCHMARK(ray_query<Box2d, false>) SIZES;

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
