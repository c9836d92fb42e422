// Narrow-phase kernels on fixed, seeded workloads (pre-generated, cycled so that no input stays in a
// register).
#include "narrowphase/distance_ellipse_ellipse.h"
#include "narrowphase/distance_rect_ellipse.h"
#include "narrowphase/distance_rect_rect.h"
#include "narrowphase/overlap_circle_ellipse.h"
#include "narrowphase/overlap_ellipse_ellipse.h"
#include "narrowphase/overlap_rect_ellipse.h"
#include "narrowphase/overlap_rect_rect.h"
#include "narrowphase/query.h"

#include "bench/box2d_baseline.h"
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
using bench::workload;

// Times one typed kernel; kernels live in the library, so the call is out of line either way.
template <class A, class B, class Result>
void kernel(benchmark::State& state, Result (*fn)(const A&, const B&)) {
  const Workload<A, B>& w = workload<A, B>();
  bench::time_queries(state, [&](std::size_t k) { return fn(w.a[k], w.b[k]); });
}

bool minkowski(const Rect& r, const Ellipse& e) { return overlap_rect_ellipse(r, e, RectEllipseMethod::minkowski); }
bool closest_features(const Rect& r, const Ellipse& e) {
  return overlap_rect_ellipse(r, e, RectEllipseMethod::closest_features);
}
bool all_features(const Rect& r, const Ellipse& e) { return overlap_rect_ellipse(r, e, RectEllipseMethod::all_features); }
// The user-facing dispatch: validation and std::visit on top of the kernel.
bool dispatch(const Rect& r, const Ellipse& e) { return overlaps(Shape(r), Shape(e)); }

// Ellipse pairs: one function per solver so that the method is fixed at compile time.
template <EllipseDistanceMethod M>
DistanceResult ellipse_distance(const Ellipse& a, const Ellipse& b) {
  return distance_ellipse_ellipse(a, b, M).result;
}
template <EllipseDistanceMethod M>
DistanceResult ellipse_boundary(const Ellipse& a, const Ellipse& b) {
  return boundary_distance_ellipse_ellipse(a, b, M).result;
}
constexpr auto kRobust = EllipseDistanceMethod::robust;
constexpr auto kGradient = EllipseDistanceMethod::gradient;
constexpr auto kPolynomial = EllipseDistanceMethod::polynomial;

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

BENCHMARK_CAPTURE(kernel, overlap_rect_ellipse_minkowski, &minkowski);
BENCHMARK_CAPTURE(kernel, overlap_rect_ellipse_closest_features, &closest_features);
BENCHMARK_CAPTURE(kernel, overlap_rect_ellipse_all_features, &all_features);
BENCHMARK_CAPTURE(kernel, distance_rect_ellipse, &distance_rect_ellipse);
BENCHMARK_CAPTURE(kernel, overlap_rect_rect, &overlap_rect_rect);
BENCHMARK_CAPTURE(kernel, distance_rect_rect, &distance_rect_rect);
BENCHMARK_CAPTURE(kernel, overlap_circle_ellipse, &overlap_circle_ellipse);
BENCHMARK_CAPTURE(kernel, distance_circle_ellipse, &distance_circle_ellipse);
BENCHMARK_CAPTURE(kernel, dispatch_overlaps_rect_ellipse, &dispatch);
BENCHMARK_CAPTURE(kernel, overlap_ellipse_ellipse, &overlap_ellipse_ellipse);
BENCHMARK_CAPTURE(kernel, distance_ellipse_ellipse_robust, &ellipse_distance<kRobust>);
BENCHMARK_CAPTURE(kernel, distance_ellipse_ellipse_gradient, &ellipse_distance<kGradient>);
BENCHMARK_CAPTURE(kernel, distance_ellipse_ellipse_polynomial, &ellipse_distance<kPolynomial>);
BENCHMARK_CAPTURE(kernel, boundary_ellipse_ellipse_robust, &ellipse_boundary<kRobust>);
BENCHMARK_CAPTURE(kernel, boundary_ellipse_ellipse_gradient, &ellipse_boundary<kGradient>);
BENCHMARK_CAPTURE(kernel, boundary_ellipse_ellipse_polynomial, &ellipse_boundary<kPolynomial>);

// Box2D on the same pairs, converted beforehand (the conversion is not timed): b2TestOverlap on
// radius-0 b2PolygonShapes (the rectangle, and the ellipse as its inscribed 8-gon), and b2Distance
// on inscribed N-gons.
Vec2 centre_of(const Rect& r) { return r.center; }
Vec2 centre_of(const Ellipse& e) { return e.center; }

template <class A, class B>
std::vector<baseline::Polygon> polygons(int sides, bool first) {
  const Workload<A, B>& w = workload<A, B>();
  std::vector<baseline::Polygon> out;
  for (std::size_t k = 0; k < kPairs; ++k) {
    const Vec2 origin = centre_of(w.a[k]);
    out.push_back(first ? baseline::to_box2d(w.a[k], sides, baseline::Fit::inscribed, origin)
                        : baseline::to_box2d(w.b[k], sides, baseline::Fit::inscribed, origin));
  }
  return out;
}

void box2d_overlap_rect_ellipse_8gon(benchmark::State& state) {
  const auto a = polygons<Rect, Ellipse>(8, true);
  const auto b = polygons<Rect, Ellipse>(8, false);
  std::vector<baseline::ShapePair> pairs;
  for (std::size_t k = 0; k < kPairs; ++k) pairs.push_back(baseline::to_box2d_shapes(a[k], b[k]));
  bench::time_queries(state, [&](std::size_t k) { return baseline::box2d_overlap(pairs[k]); });
}

void box2d_distance_ellipse_ellipse(benchmark::State& state) {
  const int sides = static_cast<int>(state.range(0));
  const auto a = polygons<Ellipse, Ellipse>(sides, true);
  const auto b = polygons<Ellipse, Ellipse>(sides, false);
  bench::time_queries(state, [&](std::size_t k) { return baseline::box2d_distance(a[k], b[k]); });
}

// The Minkowski test with each shape's orientation kept, as Box2D keeps its polygons' transforms.
void overlap_rect_ellipse_minkowski_oriented(benchmark::State& state) {
  const Workload<Rect, Ellipse>& w = workload<Rect, Ellipse>();
  std::vector<Orientation> ro, eo;
  for (std::size_t k = 0; k < kPairs; ++k) {
    ro.push_back(Orientation::of(w.a[k].angle));
    eo.push_back(Orientation::of(w.b[k].angle));
  }
  bench::time_queries(state, [&](std::size_t k) { return overlap_rect_ellipse(w.a[k], ro[k], w.b[k], eo[k]); });
}

BENCHMARK(overlap_rect_ellipse_minkowski_oriented);
BENCHMARK(box2d_overlap_rect_ellipse_8gon);
BENCHMARK(box2d_distance_ellipse_ellipse)->RangeMultiplier(2)->Range(8, 256);

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
