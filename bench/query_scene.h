// The scene of the query benchmarks (bench/bench_queries.cpp, and bench/box2d_v3/queries.cpp for
// Box2D v3): n bodies in a uniform arena, 8% of it covered; circles, ellipses and rectangles at any
// angle, 0.3 to 2 across half; each shape's box grown by 0.1 (Box2D's margin); 1,024 query boxes of
// half side 4 and rays 30 long from anywhere in the arena, any direction. And the timing loop over
// them for any tree or World that answers run(box) and run(origin, direction, query).
#pragma once

#include <collide2d/shapes.h>

#include "tools/random.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <utility>
#include <vector>

namespace collide2d::bench {

constexpr int kQueries = 1024;
constexpr double kRayLength = 30.0;

struct Scene {
  std::vector<Shape> shapes;
  std::vector<Aabb> boxes;  // grown by 0.1
  std::vector<Aabb> queries;
  std::vector<std::pair<Vec2, Vec2>> rays;  // origin, unit direction

  explicit Scene(int n) {
    std::mt19937_64 rng(7);
    const auto u = [&rng] { return tool::uniform(rng, 0.0, 1.0); };
    const double side = std::sqrt(28.0 * n);
    for (int k = 0; k < n; ++k) {
      // One draw a statement, y before x: a call's arguments are evaluated in an order the compiler picks.
      const double y = u() * side;
      const double x = u() * side;
      const Vec2 c(x, y);
      const double half = 0.3 + 1.7 * u(), angle = 2 * M_PI * u();
      switch (k % 3) {
        case 0:
          shapes.push_back(Circle{c, half});
          break;
        case 1:
          shapes.push_back(Ellipse{c, half, half * (0.2 + 0.8 * u()), angle});
          break;
        default:
          shapes.push_back(Rect{c, Vec2(half, half * (0.2 + 0.8 * u())), angle});
      }
      const Aabb box = aabb(shapes.back());
      boxes.push_back({box.min.array() - 0.1, box.max.array() + 0.1});
    }
    for (int k = 0; k < kQueries; ++k) {
      const double y = u() * side;
      const double x = u() * side;
      queries.push_back({Vec2(x, y).array() - 4.0, Vec2(x, y).array() + 4.0});
      const double a = 2 * M_PI * u();
      const double oy = u() * side;
      const double ox = u() * side;
      rays.emplace_back(Vec2(ox, oy), Vec2(std::cos(a), std::sin(a)));
    }
  }
};

inline const Scene& scene(int n) {
  static std::map<int, std::unique_ptr<Scene>> cache;
  auto& s = cache[n];
  if (!s) s = std::make_unique<Scene>(n);
  return *s;
}

enum class Query { box, ray_all, ray_first };

// A target (a tree, a World) of the scene of n bodies, made once for each n and kind.
template <class Target, class Kind>
const Target& target(int n, Kind kind) {
  static std::map<std::pair<int, Kind>, std::unique_ptr<Target>> cache;
  auto& t = cache[{n, kind}];
  if (!t) t = std::make_unique<Target>(scene(n), kind);
  return *t;
}

template <class Target, auto kind, Query query>
void run(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Scene& s = scene(n);
  const Target& t = target<Target>(n, kind);
  std::size_t k = 0, hits = 0;
  for (auto _ : state) {
    const std::size_t q = k++ % kQueries;
    hits += query == Query::box ? t.run(s.queries[q]) : t.run(s.rays[q].first, s.rays[q].second, query);
  }
  state.counters["hits"] = static_cast<double>(hits) / static_cast<double>(state.iterations());
}

// Registers a benchmark on scenes of 1,000 to 1,000,000 bodies (->Apply(...)).
inline void sizes(benchmark::internal::Benchmark* b) { b->Arg(1000)->Arg(10000)->Arg(100000)->Arg(1000000); }

}  // namespace collide2d::bench
