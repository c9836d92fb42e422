// Contact kernels against Box2D 2.4.1's manifold functions on candidate pairs (boxes overlap, as a
// broad phase hands them over; bench/workload.h): b2CollidePolygons on the rectangles' 4-gons and on
// the ellipses' inscribed 8-gons, b2CollidePolygonAndCircle, b2CollideCircles. Debian's Box2D caps
// polygons at 8 vertices (b2_maxPolygonVertices); built as bench_contact16, against Box2D rebuilt
// with a cap of 16, this also races the ellipses' 16-gons. Box2D's shapes are built beforehand (not timed), with
// radius 0, so its manifold is empty for pairs apart while ours carries their exact distance.
#include "narrowphase/contact.h"

#include "bench/box2d_baseline.h"
#include "bench/workload.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace collide2d {
namespace {

using bench::kPairs;

template <class A, class B>
void ours(benchmark::State& state, Contact (*fn)(const A&, const B&)) {
  const auto& w = bench::candidate_workload<A, B>();
  bench::time_queries(state, [&](std::size_t k) { return fn(w.a[k], w.b[k]); });
}

Contact rect_rect(const Rect& a, const Rect& b) { return contact_rect_rect(a, b); }

// With the orientations kept, as Box2D keeps its transforms.
void rect_rect_oriented(benchmark::State& state) {
  const auto& w = bench::candidate_workload<Rect, Rect>();
  std::vector<Orientation> oa, ob;
  for (std::size_t k = 0; k < kPairs; ++k) {
    oa.push_back(Orientation::of(w.a[k].angle));
    ob.push_back(Orientation::of(w.b[k].angle));
  }
  bench::time_queries(state, [&](std::size_t k) { return contact_rect_rect(w.a[k], oa[k], w.b[k], ob[k]); });
}

template <class A, class B, int Sides = 8>
void box2d(benchmark::State& state) {
  const auto& w = bench::candidate_workload<A, B>();
  std::vector<baseline::ShapePair> pairs;
  for (std::size_t k = 0; k < kPairs; ++k) {
    const Vec2 origin = w.a[k].center;
    pairs.push_back(baseline::to_box2d_shapes(baseline::to_box2d(w.a[k], Sides, baseline::Fit::inscribed, origin),
                                              baseline::to_box2d(w.b[k], Sides, baseline::Fit::inscribed, origin)));
  }
  b2Manifold manifold;
  // box2d_manifold is compiled apart (the baseline library): the call cannot be optimised away.
  bench::time_queries(state, [&](std::size_t k) {
    baseline::box2d_manifold(pairs[k], &manifold);
    return manifold.pointCount;
  });
}

BENCHMARK_CAPTURE(ours, rect_rect, &rect_rect);
BENCHMARK(rect_rect_oriented)->Name("ours/rect_rect_oriented");
BENCHMARK(box2d<Rect, Rect>)->Name("box2d_collide_polygons/rect_rect_4gons");
BENCHMARK_CAPTURE(ours, rect_circle, &contact_rect_circle);
BENCHMARK(box2d<Rect, Circle>)->Name("box2d_collide_polygon_and_circle/rect_circle");
BENCHMARK_CAPTURE(ours, circle_circle, &contact_circle_circle);
BENCHMARK(box2d<Circle, Circle>)->Name("box2d_collide_circles/circle_circle");
BENCHMARK_CAPTURE(ours, rect_ellipse, &contact_rect_ellipse);
BENCHMARK(box2d<Rect, Ellipse>)->Name("box2d_collide_polygons/rect_ellipse_8gon");
BENCHMARK_CAPTURE(ours, circle_ellipse, &contact_circle_ellipse);
BENCHMARK(box2d<Circle, Ellipse>)->Name("box2d_collide_polygon_and_circle/circle_ellipse_8gon");
BENCHMARK_CAPTURE(ours, ellipse_ellipse, &contact_ellipse_ellipse);
BENCHMARK(box2d<Ellipse, Ellipse>)->Name("box2d_collide_polygons/ellipse_ellipse_8gons");
#if b2_maxPolygonVertices >= 16
BENCHMARK(box2d<Rect, Ellipse, 16>)->Name("box2d_collide_polygons/rect_ellipse_16gon");
BENCHMARK(box2d<Circle, Ellipse, 16>)->Name("box2d_collide_polygon_and_circle/circle_ellipse_16gon");
BENCHMARK(box2d<Ellipse, Ellipse, 16>)->Name("box2d_collide_polygons/ellipse_ellipse_16gons");
#endif

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
