// Contacts against Box2D v3's manifold functions, one pair at a time, on the workloads of
// bench/shape_pairs.h (linked into bench_contact when a Box2D v3 source is given). Equal outputs:
// v3's timed call forms B's transform relative to A's, calls the manifold function of the pair
// (b2CollideCapsules, b2CollidePolygons, ...; the shapes in the order it takes them, as its World
// orders a contact's shapes) and maps the manifold's normal and points to world coordinates;
// collide2d's is contact() on the shapes with their orientations kept (the World's call), asked
// for no contact beyond v3's speculative distance, beyond which v3 returns no manifold. A chain
// segment's simplex cache starts empty on every call, as for a new contact. An ellipse is v3's
// polygon inscribed in it (bench/box2d_v3/shapes.h), so v3's answers carry that polygon's error.
#include <collide2d/chain.h>
#include <collide2d/kernels.h>

#include "bench/box2d_v3/manifold.h"
#include "bench/scene_workload.h"
#include "bench/workload.h"

#include <box2d/constants.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <type_traits>
#include <vector>

namespace collide2d {
namespace {

using bench::RoundedPolygon;
using box2d_v3::posed_shapes;

// The pair's A side: chain segments stand in for the workload's segments (bench/shape_pairs.h).
template <class A, bool chain>
auto side_a(const std::vector<A>& a) {
  if constexpr (chain) {
    return bench::chain_segments_of(a);
  } else {
    return a;
  }
}

// The share of the workload's pairs whose manifold has points, as the counter `manifolds`: both
// libraries' figures side by side show that they answer the same question.
template <class HasPoints>
void count_manifolds(benchmark::State& state, HasPoints has_points) {
  std::size_t count = 0;
  for (std::size_t k = 0; k < bench::kPairs; ++k) count += has_points(k);
  state.counters["manifolds"] = static_cast<double>(count) / bench::kPairs;
}

template <class A, class B, bool chain = false>
void box2d_v3(benchmark::State& state, int sides = 8) {
  const auto& w = bench::pairs<A, B>(state);
  const auto a = posed_shapes(side_a<A, chain>(w.a), sides);
  const auto b = posed_shapes(w.b, sides);
  const auto query = [&](std::size_t k) { return box2d_v3::manifold(a[k], b[k]); };
  bench::time_queries(state, query);
  count_manifolds(state, [&](std::size_t k) { return query(k).count > 0; });
}

// `tolerance`: ContactOptions::tolerance as a fraction of each pair's size (its larger shape's
// reach_of), set beforehand (not timed).
template <class A, class B, bool chain = false>
void ours(benchmark::State& state, double tolerance = 0) {
  const auto& w = bench::pairs<A, B>(state);
  const std::vector<Orientation> oa = bench::orientations(w.a), ob = bench::orientations(w.b);
  const auto a = side_a<A, chain>(w.a);
  const std::vector<Shape> b(w.b.begin(), w.b.end());
  std::vector<ContactOptions> options(bench::kPairs, {.max_separation = B2_SPECULATIVE_DISTANCE});
  for (std::size_t k = 0; k < bench::kPairs; ++k)
    options[k].tolerance = tolerance * std::max(reach_of(Shape(w.a[k])), reach_of(b[k]));
  const auto time = [&](const auto& sa) {
    const auto query = [&](std::size_t k) { return contact(sa[k], oa[k], b[k], ob[k], options[k]); };
    bench::time_queries(state, query);
    count_manifolds(state, [&](std::size_t k) { return !query(k).empty(); });
  };
  if constexpr (chain) {
    time(a);
  } else {
    time(std::vector<Shape>(a.begin(), a.end()));
  }
}

// Pairs of the kinds the built-in scene has (rectangles, circles, ellipses) run on its pairs too.
template <class S>
constexpr bool kInScene = std::is_same_v<S, Rect> || std::is_same_v<S, Circle> || std::is_same_v<S, Ellipse>;

// Registers collide2d's and v3's benchmarks of the pair under `name` (v3's with the polygons it
// stands an ellipse by).
template <class A, class B, bool chain = false>
void race(const std::string& name) {
  const auto apply = kInScene<A> && kInScene<B> ? bench::contact_workloads : bench::polygon_workloads;
  const int ellipses = std::is_same_v<A, Ellipse> + std::is_same_v<B, Ellipse>;
  const std::string rival = name + (ellipses == 2 ? "_8gons" : ellipses == 1 ? "_8gon" : "");
  benchmark::RegisterBenchmark(("ours/" + name + "_speculative").c_str(), ours<A, B, chain>, 0.0)->Apply(apply);
  benchmark::RegisterBenchmark(("box2d_v3/" + rival).c_str(), box2d_v3<A, B, chain>, 8)->Apply(apply);
}

// A pair with an ellipse also at the contact tolerances 1e-2 ... 1e-6 of the size, against v3 on
// the ellipses' inscribed 5-, 6- and 7-gons beside the 8-gons.
template <class A, class B, bool chain = false>
void race_tolerances(const std::string& name) {
  const auto apply = kInScene<A> && kInScene<B> ? bench::contact_workloads : bench::polygon_workloads;
  const bool two = std::is_same_v<A, Ellipse> && std::is_same_v<B, Ellipse>;
  for (const int exponent : {2, 3, 4, 6}) {
    const std::string label = "ours/" + name + "_speculative_tolerance_1e-" + std::to_string(exponent);
    benchmark::RegisterBenchmark(label.c_str(), ours<A, B, chain>, std::pow(10.0, -exponent))->Apply(apply);
  }
  for (const int sides : {5, 6, 7}) {
    const std::string label = "box2d_v3/" + name + "_" + std::to_string(sides) + (two ? "gons" : "gon");
    benchmark::RegisterBenchmark(label.c_str(), box2d_v3<A, B, chain>, sides)->Apply(apply);
  }
}

// Segments and chain segments against each kind.
template <class B>
void race_level(const std::string& kind) {
  race<Segment, B>("segment_" + kind);
  race<Segment, B, true>("chain_" + kind);
  if constexpr (std::is_same_v<B, Ellipse>) {
    race_tolerances<Segment, B>("segment_" + kind);
    race_tolerances<Segment, B, true>("chain_" + kind);
  }
}

[[maybe_unused]] const bool registered = [] {
  race<Circle, Circle>("circle_circle");
  race<Capsule, Circle>("capsule_circle");
  race<Rect, Circle>("rect_circle");
  race<ConvexPolygon, Circle>("polygon_circle");
  race<Capsule, Capsule>("capsule_capsule");
  race<Rect, Capsule>("rect_capsule");
  race<ConvexPolygon, Capsule>("polygon_capsule");
  race<Rect, Rect>("rect_rect");
  race<Rect, ConvexPolygon>("rect_polygon");
  race<ConvexPolygon, ConvexPolygon>("polygon_polygon");
  race<RoundedPolygon, Circle>("rounded_circle");
  race<RoundedPolygon, Capsule>("rounded_capsule");
  race<Rect, RoundedPolygon>("rect_rounded");
  race<ConvexPolygon, RoundedPolygon>("polygon_rounded");
  race<RoundedPolygon, RoundedPolygon>("rounded_rounded");
  race_level<Circle>("circle");
  race_level<Capsule>("capsule");
  race_level<Rect>("rect");
  race_level<ConvexPolygon>("polygon");
  race_level<RoundedPolygon>("rounded");
  race_level<Ellipse>("ellipse");
  race<Circle, Ellipse>("circle_ellipse");
  race_tolerances<Circle, Ellipse>("circle_ellipse");
  race_tolerances<Ellipse, Ellipse>("ellipse_ellipse");
  race<Capsule, Ellipse>("capsule_ellipse");
  race_tolerances<Capsule, Ellipse>("capsule_ellipse");
  race<Rect, Ellipse>("rect_ellipse");
  race_tolerances<Rect, Ellipse>("rect_ellipse");
  race<ConvexPolygon, Ellipse>("polygon_ellipse");
  race_tolerances<ConvexPolygon, Ellipse>("polygon_ellipse");
  race<RoundedPolygon, Ellipse>("rounded_ellipse");
  race_tolerances<RoundedPolygon, Ellipse>("rounded_ellipse");
  race<Ellipse, Ellipse>("ellipse_ellipse");
  return true;
}();

}  // namespace
}  // namespace collide2d
