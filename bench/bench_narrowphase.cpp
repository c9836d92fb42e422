// Narrow-phase kernels on fixed, seeded workloads (pre-generated, cycled so that no input stays in a
// register). Each benchmark runs twice, named by its first argument: candidates:0 on random pairs
// (centres in a 4 x 4 square, most of them far apart: the kernels' first early-out answers them),
// candidates:1 on candidate pairs (the same generator, only the pairs whose boxes overlap: what a
// broad phase hands over, and where a World spends its narrow phase; bench/shape_pairs.h).
#include <collide2d/batch.h>
#include <collide2d/kernels.h>
#include <collide2d/query.h>

#include "narrowphase/baselines/baselines.h"
#include "narrowphase/internal.h"

#include "bench/box2d_baseline.h"
#include "bench/scene_workload.h"
#include "bench/workload.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace collide2d {
namespace {

using bench::kPairs;
using bench::Workload;

// Times one typed kernel; kernels live in the library, so the call is out of line either way.
template <class A, class B, class Result>
void kernel(benchmark::State& state, Result (*fn)(const A&, const B&)) {
  const Workload<A, B>& w = bench::pairs<A, B>(state);
  bench::time_queries(state, [&](std::size_t k) { return fn(w.a[k], w.b[k]); });
}

bool minkowski(const Rect& r, const Ellipse& e) { return overlap_rect_ellipse(r, e); }
bool closest_features(const Rect& r, const Ellipse& e) {
  return baselines::overlap_rect_ellipse(r, e, baselines::RectEllipseTest::closest_features);
}
bool all_features(const Rect& r, const Ellipse& e) {
  return baselines::overlap_rect_ellipse(r, e, baselines::RectEllipseTest::all_features);
}
// The user-facing dispatch: validation and std::visit on top of the kernel.
bool dispatch(const Rect& r, const Ellipse& e) { return overlaps(Shape(r), Shape(e)); }

// Ellipse pairs: the kernels, and one function per baseline solver so that it is fixed at compile
// time.
DistanceResult robust_distance(const Ellipse& a, const Ellipse& b) { return distance_ellipse_ellipse(a, b); }
DistanceResult robust_boundary(const Ellipse& a, const Ellipse& b) { return boundary_distance_ellipse_ellipse(a, b); }
template <baselines::EllipseSolver S>
DistanceResult baseline_distance(const Ellipse& a, const Ellipse& b) {
  return baselines::distance_ellipse_ellipse(a, b, S).result;
}
template <baselines::EllipseSolver S>
DistanceResult baseline_boundary(const Ellipse& a, const Ellipse& b) {
  return baselines::curve_distance(a, b, S).result;
}
constexpr auto kGradient = baselines::EllipseSolver::gradient;
constexpr auto kPolynomial = baselines::EllipseSolver::polynomial;

// Nested pairs: B inside A (within A's inscribed circle), where the boundary distance searches the
// directions for the least gap instead of running the separated pair's Newton iteration.
void boundary_ellipse_ellipse_nested(benchmark::State& state) {
  static const Workload<Ellipse, Ellipse> w = [] {
    bench::Generator g;
    Workload<Ellipse, Ellipse> out{std::vector<Ellipse>(kPairs), std::vector<Ellipse>(kPairs)};
    for (std::size_t k = 0; k < kPairs; ++k) {
      g.make(out.a[k]);
      const double room = std::min(out.a[k].a, out.a[k].b);
      const double turn = g.uniform(0, 6.3);
      const Vec2 offset = g.uniform(0, 0.4 * room) * Vec2(std::cos(turn), std::sin(turn));
      out.b[k] = Ellipse{out.a[k].center + offset, g.uniform(0.05, 0.3) * room, g.uniform(0.05, 0.3) * room,
                         g.uniform(0, 6.3)};
    }
    return out;
  }();
  bench::time_queries(state, [&](std::size_t k) { return boundary_distance_ellipse_ellipse(w.a[k], w.b[k]); });
}
BENCHMARK(boundary_ellipse_ellipse_nested);

BENCHMARK_CAPTURE(kernel, overlap_rect_ellipse_minkowski, &minkowski)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, overlap_rect_ellipse_closest_features, &closest_features)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, overlap_rect_ellipse_all_features, &all_features)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, distance_rect_ellipse, &distance_rect_ellipse)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, overlap_rect_rect, &overlap_rect_rect)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, distance_rect_rect, &distance_rect_rect)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, overlap_circle_ellipse, &overlap_circle_ellipse)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, distance_circle_ellipse, &distance_circle_ellipse)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, dispatch_overlaps_rect_ellipse, &dispatch)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, overlap_ellipse_ellipse, &overlap_ellipse_ellipse)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, distance_ellipse_ellipse_robust, &robust_distance)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, distance_ellipse_ellipse_gradient, &baseline_distance<kGradient>)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, distance_ellipse_ellipse_polynomial, &baseline_distance<kPolynomial>)
    ->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, boundary_ellipse_ellipse_robust, &robust_boundary)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, boundary_ellipse_ellipse_gradient, &baseline_boundary<kGradient>)->Apply(bench::workloads);
BENCHMARK_CAPTURE(kernel, boundary_ellipse_ellipse_polynomial, &baseline_boundary<kPolynomial>)
    ->Apply(bench::workloads);

// Box2D on the same pairs, converted beforehand (the conversion is not timed, and each pair's
// transforms are the identity: its coordinates are taken from A's centre): b2TestOverlap on
// radius-0 b2PolygonShapes (a rectangle its 4-gon, an ellipse its inscribed 8-gon, a circle a
// b2CircleShape), and b2Distance on inscribed N-gons.
template <class A, class B>
std::vector<baseline::Polygon> polygons(const Workload<A, B>& w, int sides, bool first) {
  std::vector<baseline::Polygon> out;
  for (std::size_t k = 0; k < kPairs; ++k) {
    const Vec2 origin = center_of(w.a[k]);
    out.push_back(first ? baseline::to_box2d(w.a[k], sides, baseline::Fit::inscribed, origin)
                        : baseline::to_box2d(w.b[k], sides, baseline::Fit::inscribed, origin));
  }
  return out;
}

template <class A, class B>
std::vector<baseline::ShapePair> box2d_pairs(const Workload<A, B>& w) {
  const auto a = polygons(w, 8, true);
  const auto b = polygons(w, 8, false);
  std::vector<baseline::ShapePair> shapes;
  for (std::size_t k = 0; k < kPairs; ++k) shapes.push_back(baseline::to_box2d_shapes(a[k], b[k]));
  return shapes;
}

// One pair per call, as the one-off kernels run.
template <class A, class B>
void box2d_overlap(benchmark::State& state) {
  const std::vector<baseline::ShapePair> shapes = box2d_pairs(bench::pairs<A, B>(state));
  bench::time_queries(state, [&](std::size_t k) { return baseline::box2d_overlap(shapes[k]); });
}

// The whole list per iteration in one loop, as the batches run.
template <class A, class B>
void box2d_batch_overlap(benchmark::State& state) {
  const std::vector<baseline::ShapePair> shapes = box2d_pairs(bench::pairs<A, B>(state));
  std::vector<std::uint8_t> out(kPairs);
  bench::time_batches(state, [&] { baseline::box2d_overlaps(shapes, out); });
}

void box2d_distance_ellipse_ellipse(benchmark::State& state) {
  const Workload<Ellipse, Ellipse>& w = bench::pairs<Ellipse, Ellipse>(state);
  const int sides = static_cast<int>(state.range(1));
  const auto a = polygons(w, sides, true);
  const auto b = polygons(w, sides, false);
  bench::time_queries(state, [&](std::size_t k) { return baseline::box2d_distance(a[k], b[k]); });
}

// The World's overlap test: each shape's orientation kept, no validation.
template <class A, class B>
void posed_overlap(benchmark::State& state) {
  const Workload<A, B>& w = bench::pairs<A, B>(state);
  const std::vector<Shape> a(w.a.begin(), w.a.end()), b(w.b.begin(), w.b.end());
  const std::vector<Orientation> oa = bench::orientations(w.a), ob = bench::orientations(w.b);
  bench::time_queries(state, [&](std::size_t k) { return overlaps(a[k], oa[k], b[k], ob[k]); });
}

// The batched tests (batch.h) on the whole workload per iteration.
template <class A, class B>
void batch_overlap(benchmark::State& state) {
  const Workload<A, B>& w = bench::pairs<A, B>(state);
  const std::vector<Orientation> oa = bench::orientations(w.a), ob = bench::orientations(w.b);
  std::vector<std::uint8_t> out(kPairs);
  bench::time_batches(state, [&] { detail::overlap_batch<A, B>(w.a, oa, w.b, ob, out); });
}

BENCHMARK(posed_overlap<Rect, Ellipse>)->Name("posed_overlap/rect_ellipse")->Apply(bench::workloads);
BENCHMARK(batch_overlap<Rect, Ellipse>)->Name("batch_overlap/rect_ellipse")->Apply(bench::workloads);
BENCHMARK(box2d_overlap<Rect, Ellipse>)->Name("box2d_overlap/rect_ellipse_8gon")->Apply(bench::workloads);
BENCHMARK(box2d_batch_overlap<Rect, Ellipse>)->Name("box2d_batch_overlap/rect_ellipse_8gon")->Apply(bench::workloads);
BENCHMARK(posed_overlap<Ellipse, Ellipse>)->Name("posed_overlap/ellipse_ellipse")->Apply(bench::workloads);
BENCHMARK(batch_overlap<Ellipse, Ellipse>)->Name("batch_overlap/ellipse_ellipse")->Apply(bench::workloads);
BENCHMARK(box2d_overlap<Ellipse, Ellipse>)->Name("box2d_overlap/ellipse_ellipse_8gons")->Apply(bench::workloads);
BENCHMARK(box2d_batch_overlap<Ellipse, Ellipse>)
    ->Name("box2d_batch_overlap/ellipse_ellipse_8gons")
    ->Apply(bench::workloads);
BENCHMARK(posed_overlap<Rect, Rect>)->Name("posed_overlap/rect_rect")->Apply(bench::workloads);
BENCHMARK(batch_overlap<Rect, Rect>)->Name("batch_overlap/rect_rect")->Apply(bench::workloads);
BENCHMARK(box2d_overlap<Rect, Rect>)->Name("box2d_overlap/rect_rect_4gons")->Apply(bench::workloads);
BENCHMARK(box2d_batch_overlap<Rect, Rect>)->Name("box2d_batch_overlap/rect_rect_4gons")->Apply(bench::workloads);
BENCHMARK(posed_overlap<Circle, Ellipse>)->Name("posed_overlap/circle_ellipse")->Apply(bench::workloads);
BENCHMARK(batch_overlap<Circle, Ellipse>)->Name("batch_overlap/circle_ellipse")->Apply(bench::workloads);
BENCHMARK(box2d_overlap<Circle, Ellipse>)->Name("box2d_overlap/circle_ellipse_8gon")->Apply(bench::workloads);
BENCHMARK(box2d_batch_overlap<Circle, Ellipse>)
    ->Name("box2d_batch_overlap/circle_ellipse_8gon")
    ->Apply(bench::workloads);
BENCHMARK(posed_overlap<ConvexPolygon, ConvexPolygon>)
    ->Name("posed_overlap/polygon_polygon")
    ->Apply(bench::polygon_workloads);
BENCHMARK(box2d_overlap<ConvexPolygon, ConvexPolygon>)
    ->Name("box2d_overlap/polygon_polygon_8gons")
    ->Apply(bench::polygon_workloads);
BENCHMARK(posed_overlap<ConvexPolygon, Circle>)->Name("posed_overlap/polygon_circle")->Apply(bench::polygon_workloads);
BENCHMARK(box2d_overlap<ConvexPolygon, Circle>)->Name("box2d_overlap/polygon_circle")->Apply(bench::polygon_workloads);
BENCHMARK(posed_overlap<ConvexPolygon, Ellipse>)
    ->Name("posed_overlap/polygon_ellipse")
    ->Apply(bench::polygon_workloads);
BENCHMARK(box2d_overlap<ConvexPolygon, Ellipse>)
    ->Name("box2d_overlap/polygon_ellipse_8gon")
    ->Apply(bench::polygon_workloads);
BENCHMARK(batch_overlap<ConvexPolygon, Ellipse>)
    ->Name("batch_overlap/polygon_ellipse")
    ->Apply(bench::polygon_workloads);
BENCHMARK(box2d_batch_overlap<ConvexPolygon, Ellipse>)
    ->Name("box2d_batch_overlap/polygon_ellipse_8gon")
    ->Apply(bench::polygon_workloads);
BENCHMARK(batch_overlap<ConvexPolygon, ConvexPolygon>)
    ->Name("batch_overlap/polygon_polygon")
    ->Apply(bench::polygon_workloads);
BENCHMARK(box2d_batch_overlap<ConvexPolygon, ConvexPolygon>)
    ->Name("box2d_batch_overlap/polygon_polygon_8gons")
    ->Apply(bench::polygon_workloads);
BENCHMARK(batch_overlap<ConvexPolygon, Circle>)->Name("batch_overlap/polygon_circle")->Apply(bench::polygon_workloads);
BENCHMARK(box2d_batch_overlap<ConvexPolygon, Circle>)
    ->Name("box2d_batch_overlap/polygon_circle")
    ->Apply(bench::polygon_workloads);
BENCHMARK(posed_overlap<Capsule, Ellipse>)->Name("posed_overlap/capsule_ellipse")->Apply(bench::polygon_workloads);
BENCHMARK(box2d_overlap<Capsule, Ellipse>)->Name("box2d_overlap/capsule_ellipse_8gon")->Apply(bench::polygon_workloads);
BENCHMARK(batch_overlap<Capsule, Ellipse>)->Name("batch_overlap/capsule_ellipse")->Apply(bench::polygon_workloads);
BENCHMARK(box2d_batch_overlap<Capsule, Ellipse>)
    ->Name("box2d_batch_overlap/capsule_ellipse_8gon")
    ->Apply(bench::polygon_workloads);
BENCHMARK(posed_overlap<Segment, ConvexPolygon>)
    ->Name("posed_overlap/segment_polygon")
    ->Apply(bench::polygon_workloads);
BENCHMARK(box2d_overlap<Segment, ConvexPolygon>)
    ->Name("box2d_overlap/segment_polygon")
    ->Apply(bench::polygon_workloads);
BENCHMARK(posed_overlap<Segment, Ellipse>)->Name("posed_overlap/segment_ellipse")->Apply(bench::polygon_workloads);
BENCHMARK(box2d_overlap<Segment, Ellipse>)->Name("box2d_overlap/segment_ellipse_8gon")->Apply(bench::polygon_workloads);
BENCHMARK(posed_overlap<Capsule, Circle>)->Name("posed_overlap/capsule_circle")->Apply(bench::polygon_workloads);
BENCHMARK(box2d_overlap<Capsule, Circle>)->Name("box2d_overlap/capsule_circle")->Apply(bench::polygon_workloads);
BENCHMARK(batch_overlap<Capsule, Circle>)->Name("batch_overlap/capsule_circle")->Apply(bench::polygon_workloads);
BENCHMARK(box2d_batch_overlap<Capsule, Circle>)
    ->Name("box2d_batch_overlap/capsule_circle")
    ->Apply(bench::polygon_workloads);
// The robust ellipse distance with the orientations kept, against b2Distance with its transforms
// prepared (box2d_distance_ellipse_ellipse).
void posed_distance_ellipse_ellipse(benchmark::State& state) {
  const Workload<Ellipse, Ellipse>& w = bench::pairs<Ellipse, Ellipse>(state);
  const std::vector<Orientation> oa = bench::orientations(w.a), ob = bench::orientations(w.b);
  bench::time_queries(state, [&](std::size_t k) { return distance_ellipse_ellipse(w.a[k], oa[k], w.b[k], ob[k]); });
}
BENCHMARK(posed_distance_ellipse_ellipse)->Apply(bench::workloads);
BENCHMARK(box2d_distance_ellipse_ellipse)
    ->ArgNames({"candidates", "sides"})
    ->ArgsProduct({{0, 1, 2}, benchmark::CreateRange(8, 256, 2)});

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
