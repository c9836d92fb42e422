// Queries through Box2D v3's b2DynamicTree on the scene of the query benchmarks (bench/query_scene.h,
// linked into bench_queries when a Box2D v3 source is given), against collide2d's box tree there:
// the same boxes (each shape's box grown by 0.1, in float, rounded to nearest; v3's tree grows
// nothing, its broad phase does), every box a query box meets (b2DynamicTree_QueryAll, which filters
// nothing, as the box tree does not) and every box a ray meets (b2DynamicTree_RayCast, its callback
// keeping the ray whole). The tree as insertion leaves it, and after b2DynamicTree_Rebuild's full
// rebuild.
#include "bench/box2d_v3/shapes.h"
#include "bench/query_scene.h"

#include <box2d/collision.h>
#include <box2d/types.h>

#include <benchmark/benchmark.h>

namespace collide2d {
namespace {

using bench::Query;

enum class Build { inserted, rebuilt };

b2AABB to_float(const Aabb& box) { return {box2d_v3::to_float(box.min), box2d_v3::to_float(box.max)}; }

bool count_box(int, uint64_t, void* hits) {
  ++*static_cast<std::size_t*>(hits);
  return true;
}

float count_ray(const b2RayCastInput* input, int, uint64_t, void* hits) {
  ++*static_cast<std::size_t*>(hits);
  return input->maxFraction;
}

struct DynamicTree {
  b2DynamicTree tree;
  DynamicTree(const bench::Scene& s, Build build) : tree(b2DynamicTree_Create(static_cast<int>(s.boxes.size()))) {
    for (std::size_t k = 0; k < s.boxes.size(); ++k) {
      b2DynamicTree_CreateProxy(&tree, to_float(s.boxes[k]), B2_DEFAULT_CATEGORY_BITS, k);
    }
    if (build == Build::rebuilt) b2DynamicTree_Rebuild(&tree, true);
  }
  ~DynamicTree() { b2DynamicTree_Destroy(&tree); }
  DynamicTree(const DynamicTree&) = delete;
  DynamicTree& operator=(const DynamicTree&) = delete;

  std::size_t run(const Aabb& box) const {
    std::size_t hits = 0;
    b2DynamicTree_QueryAll(&tree, to_float(box), count_box, &hits);
    return hits;
  }
  std::size_t run(const Vec2& o, const Vec2& d, Query) const {
    std::size_t hits = 0;
    const b2RayCastInput input{box2d_v3::to_float(o), box2d_v3::to_float(bench::kRayLength * d), 1.0f};
    b2DynamicTree_RayCast(&tree, &input, B2_DEFAULT_MASK_BITS, count_ray, &hits);
    return hits;
  }
};

BENCHMARK(bench::run<DynamicTree, Build::inserted, Query::box>)->Name("box/box2d_v3")->Apply(bench::sizes);
BENCHMARK(bench::run<DynamicTree, Build::rebuilt, Query::box>)->Name("box/box2d_v3_rebuilt")->Apply(bench::sizes);
BENCHMARK(bench::run<DynamicTree, Build::inserted, Query::ray_all>)->Name("ray/box2d_v3")->Apply(bench::sizes);
BENCHMARK(bench::run<DynamicTree, Build::rebuilt, Query::ray_all>)->Name("ray/box2d_v3_rebuilt")->Apply(bench::sizes);

}  // namespace
}  // namespace collide2d
