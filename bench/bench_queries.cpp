// Queries over the scene of bench/query_scene.h: the bodies within a query box and along a ray.
//
// The box part, against Box2D 2.4.1's b2DynamicTree::Query and RayCast on the same boxes: each
// shape's box grown by 0.1 (Box2D's CreateProxy grows by b2_aabbMargin = 0.1, so ours are given
// grown), every box met reported. Our tree is timed as insert() leaves it (in order of insertion,
// as Box2D's) and after rebuild().
//
// The World's queries, box part and exact shapes together: overlapping(box) and ray_cast_all() (every
// body the ray meets, exact), and ray_cast() (the first hit, where a near hit prunes the rest), in a
// World whose bodies are all static (their tree rebuilt, boxes not fattened) or all moving (fat
// margin 0.1, the tree as motion leaves it, below).
#include <collide2d/aabb_tree.h>
#include <collide2d/world.h>
#include "bench/box2d_baseline.h"
#include "bench/query_scene.h"
#include "tools/random.h"

#include <benchmark/benchmark.h>
#include <box2d/b2_dynamic_tree.h>

#include <algorithm>
#include <random>
#include <vector>

namespace collide2d {
namespace {

using bench::kRayLength;
using bench::Query;
using bench::run;
using bench::Scene;

enum class Kind { tree, tree_rebuilt, box2d, static_world, moving_world };

struct Ours {
  AabbTree tree;
  Ours(const Scene& s, Kind kind) {
    for (std::size_t k = 0; k < s.boxes.size(); ++k) tree.insert(s.boxes[k], static_cast<std::uint32_t>(k));
    if (kind == Kind::tree_rebuilt) tree.rebuild();
  }
  std::size_t run(const Aabb& box) const {
    std::size_t hits = 0;
    tree.query(box, [&hits](std::uint32_t) { ++hits; });
    return hits;
  }
  std::size_t run(const Vec2& o, const Vec2& d, Query) const {
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
  Box2d(const Scene& s, Kind) {
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
  std::size_t run(const Aabb& box) const {
    hits = 0;
    tree.Query(const_cast<Box2d*>(this), baseline::to_box2d(box));
    return hits;
  }
  std::size_t run(const Vec2& o, const Vec2& d, Query) const {
    hits = 0;
    b2RayCastInput input;
    input.p1.Set(static_cast<float>(o.x()), static_cast<float>(o.y()));
    input.p2.Set(static_cast<float>(o.x() + kRayLength * d.x()), static_cast<float>(o.y() + kRayLength * d.y()));
    input.maxFraction = 1.0f;
    tree.RayCast(const_cast<Box2d*>(this), input);
    return hits;
  }
};

struct Bodies {
  World world;
  // Moving bodies are then moved for some frames (up to 0.1 a frame and 0.05 rad), so that their
  // tree is timed as motion leaves it: nearly every box has left its fat box and been re-inserted.
  Bodies(const Scene& s, Kind kind) : world({.fat_margin = 0.1}) {
    BodyDef def;
    def.is_static = kind == Kind::static_world;
    for (const Shape& shape : s.shapes) world.add(shape, def);
    world.update();  // where a tree of newly added bodies is rebuilt
    if (def.is_static) return;
    // The first query builds the moving shapes' tree: one before the motion, as a game that queries
    // every frame makes, so that the motion below shapes that tree.
    world.overlapping(Aabb{Vec2::Zero(), Vec2::Zero()});
    std::mt19937_64 rng(3);
    const auto u = [&rng] { return tool::uniform(rng, -1.0, 1.0); };
    const std::vector<BodyId> ids = world.bodies();
    for (std::size_t frame = 0; frame < std::clamp<std::size_t>(3000000 / ids.size(), 3, 60); ++frame) {
      for (const BodyId id : ids) {
        const double turn = 0.05 * u();  // one draw a statement: a call orders its arguments as it picks
        const double dy = 0.1 * u();
        const double dx = 0.1 * u();
        world.move_by(id, Vec2(dx, dy), turn);
      }
      world.update();
    }
  }
  std::size_t run(const Aabb& box) const { return world.overlapping(box).size(); }
  std::size_t run(const Vec2& o, const Vec2& d, Query q) const {
    if (q == Query::ray_first) return world.ray_cast(o, d, kRayLength) ? 1 : 0;
    return world.ray_cast_all(o, d, kRayLength).size();
  }
};

BENCHMARK(run<Ours, Kind::tree, Query::box>)->Name("box/tree")->Apply(bench::sizes);
BENCHMARK(run<Ours, Kind::tree_rebuilt, Query::box>)->Name("box/tree_rebuilt")->Apply(bench::sizes);
BENCHMARK(run<Box2d, Kind::box2d, Query::box>)->Name("box/box2d")->Apply(bench::sizes);
BENCHMARK(run<Bodies, Kind::static_world, Query::box>)->Name("box/world_static")->Apply(bench::sizes);
BENCHMARK(run<Bodies, Kind::moving_world, Query::box>)->Name("box/world_moving")->Apply(bench::sizes);
BENCHMARK(run<Ours, Kind::tree, Query::ray_all>)->Name("ray/tree")->Apply(bench::sizes);
BENCHMARK(run<Ours, Kind::tree_rebuilt, Query::ray_all>)->Name("ray/tree_rebuilt")->Apply(bench::sizes);
BENCHMARK(run<Box2d, Kind::box2d, Query::ray_all>)->Name("ray/box2d")->Apply(bench::sizes);
BENCHMARK(run<Bodies, Kind::static_world, Query::ray_all>)->Name("ray/world_static_all")->Apply(bench::sizes);
BENCHMARK(run<Bodies, Kind::moving_world, Query::ray_all>)->Name("ray/world_moving_all")->Apply(bench::sizes);
BENCHMARK(run<Bodies, Kind::static_world, Query::ray_first>)->Name("ray/world_static_first")->Apply(bench::sizes);
BENCHMARK(run<Bodies, Kind::moving_world, Query::ray_first>)->Name("ray/world_moving_first")->Apply(bench::sizes);

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
