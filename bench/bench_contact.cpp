// Contact kernels against Box2D 2.4.1's manifold functions on the five workloads of bench/shape_pairs.h
// (candidates:0 random pairs, most far apart; 1 the generator's candidate pairs, whose boxes
// overlap; 2 the built-in scene's broad-phase pairs; 3 and 4 the overlapping pairs among 1 and 2):
// b2CollidePolygons on the rectangles' 4-gons and on the ellipses' inscribed 8- and 16-gons,
// b2CollidePolygonAndCircle, b2CollideCircles. Box2D is built here with polygons of up to 16
// vertices (its default cap is 8). Its shapes are built beforehand (not timed), with radius 0, so
// its manifold is empty for pairs apart; ours carries their exact distance, and the `_limited`
// runs (max_separation 0) are empty there too. Convex 8-gons (bench/shape_pairs.h's) against 8-gons,
// circles and ellipses' 8-gons, on workloads 0, 1 and 3 (the scene has no polygons).
#include <collide2d/batch.h>
#include <collide2d/chain.h>
#include <collide2d/kernels.h>

#include "bench/box2d_baseline.h"
#include "bench/scene_workload.h"
#include "bench/workload.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

namespace collide2d {
namespace {

using bench::kPairs;

// The typed kernels under one name, without and with the orientations kept (as Box2D keeps its
// transforms; a circle has none).
Contact kernel(const Rect& a, const Rect& b) { return contact_rect_rect(a, b); }
Contact kernel(const Rect& a, const Circle& b) { return contact_rect_circle(a, b); }
Contact kernel(const Circle& a, const Circle& b) { return contact_circle_circle(a, b); }
Contact kernel(const Rect& a, const Ellipse& b) { return contact_rect_ellipse(a, b); }
Contact kernel(const Circle& a, const Ellipse& b) { return contact_circle_ellipse(a, b); }
Contact kernel(const Ellipse& a, const Ellipse& b) { return contact_ellipse_ellipse(a, b); }
Contact kernel(const Rect& a, const Orientation& oa, const Rect& b, const Orientation& ob, const ContactOptions& o) {
  return contact_rect_rect(a, oa, b, ob, o);
}
Contact kernel(const Rect& a, const Orientation& oa, const Circle& b, const Orientation&, const ContactOptions& o) {
  return contact_rect_circle(a, oa, b, o);
}
Contact kernel(const Circle& a, const Orientation&, const Circle& b, const Orientation&, const ContactOptions& o) {
  return contact_circle_circle(a, b, o);
}
Contact kernel(const Rect& a, const Orientation& oa, const Ellipse& b, const Orientation& ob, const ContactOptions& o) {
  return contact_rect_ellipse(a, oa, b, ob, o);
}
Contact kernel(const Circle& a, const Orientation&, const Ellipse& b, const Orientation& ob, const ContactOptions& o) {
  return contact_circle_ellipse(a, b, ob, o);
}
Contact kernel(const Ellipse& a, const Orientation& oa, const Ellipse& b, const Orientation& ob,
               const ContactOptions& o) {
  return contact_ellipse_ellipse(a, oa, b, ob, o);
}
Contact kernel(const ConvexPolygon& a, const Orientation& oa, const Circle& b, const Orientation&,
               const ContactOptions& o) {
  return contact_polygon_circle(a, oa, b, o);
}

template <class A, class B>
void ours(benchmark::State& state) {
  const auto& w = bench::pairs<A, B>(state);
  bench::time_queries(state, [&](std::size_t k) { return kernel(w.a[k], w.b[k]); });
}

// Orientations kept; `limited`: no contact beyond separation 0 (ContactOptions::max_separation), as
// Box2D's manifolds of shapes of radius 0 are empty there.
template <class A, class B, bool limited = false>
void ours_oriented(benchmark::State& state) {
  const auto& w = bench::pairs<A, B>(state);
  const std::vector<Orientation> oa = bench::orientations(w.a), ob = bench::orientations(w.b);
  const ContactOptions options{.max_separation = limited ? 0.0 : HUGE_VAL};
  bench::time_queries(state, [&](std::size_t k) { return kernel(w.a[k], oa[k], w.b[k], ob[k], options); });
}

// Pairs with a polygon and no typed kernel of their own through kernels.h's contact on Shape with
// kept orientations (the World's call).
template <class A, class B, bool limited = false>
void ours_shape(benchmark::State& state) {
  const auto& w = bench::pairs<A, B>(state);
  const std::vector<Orientation> oa = bench::orientations(w.a), ob = bench::orientations(w.b);
  std::vector<Shape> sa(w.a.begin(), w.a.end()), sb(w.b.begin(), w.b.end());
  const ContactOptions options{.max_separation = limited ? 0.0 : HUGE_VAL};
  bench::time_queries(state, [&](std::size_t k) { return contact(sa[k], oa[k], sb[k], ob[k], options); });
}

// The batched circle–ellipse contact (orientations kept) on the whole workload per iteration.
void batch_circle_ellipse(benchmark::State& state) {
  const auto& w = bench::pairs<Circle, Ellipse>(state);
  const std::vector<Orientation> ob = bench::orientations(w.b);
  std::vector<Contact> out(kPairs);
  bench::time_batches(state, [&] { contact_circle_ellipse(w.a, w.b, ob, out); });
}

// The batched rectangle–circle contact (orientations kept) on the whole workload per iteration.
void batch_rect_circle(benchmark::State& state) {
  const auto& w = bench::pairs<Rect, Circle>(state);
  const std::vector<Orientation> oa = bench::orientations(w.a);
  std::vector<Contact> out(kPairs);
  bench::time_batches(state, [&] { contact_rect_circle(w.a, oa, w.b, out); });
}

// The benchmark's pairs as Box2D shapes, ellipses as inscribed Sides-gons (not timed).
template <class A, class B, int Sides>
std::vector<baseline::ShapePair> box2d_pairs(const benchmark::State& state) {
  const auto& w = bench::pairs<A, B>(state);
  std::vector<baseline::ShapePair> pairs;
  for (std::size_t k = 0; k < kPairs; ++k) {
    const Vec2 origin = w.a[k].center;
    pairs.push_back(baseline::to_box2d_shapes(baseline::to_box2d(w.a[k], Sides, baseline::Fit::inscribed, origin),
                                              baseline::to_box2d(w.b[k], Sides, baseline::Fit::inscribed, origin)));
  }
  return pairs;
}

template <class A, class B, int Sides = 8>
void box2d(benchmark::State& state) {
  const std::vector<baseline::ShapePair> pairs = box2d_pairs<A, B, Sides>(state);
  b2Manifold manifold;
  // box2d_manifold is compiled apart (the baseline library): the call cannot be optimised away.
  bench::time_queries(state, [&](std::size_t k) {
    baseline::box2d_manifold(pairs[k], &manifold);
    return manifold.pointCount;
  });
}

// Box2D through a whole list per iteration, in one loop: the rival of the batched contacts.
template <class A, class B, int Sides>
void box2d_batch(benchmark::State& state) {
  const std::vector<baseline::ShapePair> pairs = box2d_pairs<A, B, Sides>(state);
  std::vector<b2Manifold> out(kPairs);
  bench::time_batches(state, [&] { baseline::box2d_manifolds(pairs, out); });
}

BENCHMARK(ours<Rect, Rect>)->Name("ours/rect_rect")->Apply(bench::contact_workloads);
BENCHMARK(ours_oriented<Rect, Rect>)->Name("ours/rect_rect_oriented")->Apply(bench::contact_workloads);
BENCHMARK(ours_oriented<Rect, Rect, true>)->Name("ours/rect_rect_limited")->Apply(bench::contact_workloads);
BENCHMARK(box2d<Rect, Rect>)->Name("box2d_collide_polygons/rect_rect_4gons")->Apply(bench::contact_workloads);
BENCHMARK(ours<Rect, Circle>)->Name("ours/rect_circle")->Apply(bench::contact_workloads);
BENCHMARK(ours_oriented<Rect, Circle>)->Name("ours/rect_circle_oriented")->Apply(bench::contact_workloads);
BENCHMARK(ours_oriented<Rect, Circle, true>)->Name("ours/rect_circle_limited")->Apply(bench::contact_workloads);
BENCHMARK(batch_rect_circle)->Name("batch_contact/rect_circle")->Apply(bench::contact_workloads);
BENCHMARK(box2d<Rect, Circle>)->Name("box2d_collide_polygon_and_circle/rect_circle")->Apply(bench::contact_workloads);
BENCHMARK(box2d_batch<Rect, Circle, 4>)->Name("box2d_batch_contact/rect_circle")->Apply(bench::contact_workloads);
BENCHMARK(ours<Circle, Circle>)->Name("ours/circle_circle")->Apply(bench::contact_workloads);
BENCHMARK(ours_oriented<Circle, Circle, true>)->Name("ours/circle_circle_limited")->Apply(bench::contact_workloads);
BENCHMARK(box2d<Circle, Circle>)->Name("box2d_collide_circles/circle_circle")->Apply(bench::contact_workloads);
BENCHMARK(ours<Rect, Ellipse>)->Name("ours/rect_ellipse")->Apply(bench::contact_workloads);
BENCHMARK(ours_oriented<Rect, Ellipse>)->Name("ours/rect_ellipse_oriented")->Apply(bench::contact_workloads);
BENCHMARK(ours_oriented<Rect, Ellipse, true>)->Name("ours/rect_ellipse_limited")->Apply(bench::contact_workloads);
BENCHMARK(box2d<Rect, Ellipse>)->Name("box2d_collide_polygons/rect_ellipse_8gon")->Apply(bench::contact_workloads);
BENCHMARK(ours<Circle, Ellipse>)->Name("ours/circle_ellipse")->Apply(bench::contact_workloads);
BENCHMARK(ours_oriented<Circle, Ellipse>)->Name("ours/circle_ellipse_oriented")->Apply(bench::contact_workloads);
BENCHMARK(ours_oriented<Circle, Ellipse, true>)->Name("ours/circle_ellipse_limited")->Apply(bench::contact_workloads);
BENCHMARK(batch_circle_ellipse)->Name("batch_contact/circle_ellipse")->Apply(bench::contact_workloads);
BENCHMARK(box2d<Circle, Ellipse>)
    ->Name("box2d_collide_polygon_and_circle/circle_ellipse_8gon")
    ->Apply(bench::contact_workloads);
BENCHMARK(ours<Ellipse, Ellipse>)->Name("ours/ellipse_ellipse")->Apply(bench::contact_workloads);
BENCHMARK(ours_oriented<Ellipse, Ellipse>)->Name("ours/ellipse_ellipse_oriented")->Apply(bench::contact_workloads);
BENCHMARK(ours_oriented<Ellipse, Ellipse, true>)->Name("ours/ellipse_ellipse_limited")->Apply(bench::contact_workloads);
BENCHMARK(box2d<Ellipse, Ellipse>)
    ->Name("box2d_collide_polygons/ellipse_ellipse_8gons")
    ->Apply(bench::contact_workloads);
BENCHMARK(box2d<Rect, Ellipse, 16>)->Name("box2d_collide_polygons/rect_ellipse_16gon")->Apply(bench::contact_workloads);
BENCHMARK(box2d<Circle, Ellipse, 16>)
    ->Name("box2d_collide_polygon_and_circle/circle_ellipse_16gon")
    ->Apply(bench::contact_workloads);
BENCHMARK(box2d<Ellipse, Ellipse, 16>)
    ->Name("box2d_collide_polygons/ellipse_ellipse_16gons")
    ->Apply(bench::contact_workloads);
BENCHMARK(box2d_batch<Circle, Ellipse, 8>)
    ->Name("box2d_batch_contact/circle_ellipse_8gon")
    ->Apply(bench::contact_workloads);
BENCHMARK(box2d_batch<Circle, Ellipse, 16>)
    ->Name("box2d_batch_contact/circle_ellipse_16gon")
    ->Apply(bench::contact_workloads);

BENCHMARK(ours_shape<ConvexPolygon, ConvexPolygon>)->Name("ours/polygon_polygon")->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<ConvexPolygon, ConvexPolygon, true>)
    ->Name("ours/polygon_polygon_limited")
    ->Apply(bench::polygon_workloads);
BENCHMARK(box2d<ConvexPolygon, ConvexPolygon>)
    ->Name("box2d_collide_polygons/polygon_polygon_8gons")
    ->Apply(bench::polygon_workloads);
BENCHMARK(ours_oriented<ConvexPolygon, Circle>)->Name("ours/polygon_circle")->Apply(bench::polygon_workloads);
BENCHMARK(ours_oriented<ConvexPolygon, Circle, true>)
    ->Name("ours/polygon_circle_limited")
    ->Apply(bench::polygon_workloads);
BENCHMARK(box2d<ConvexPolygon, Circle>)
    ->Name("box2d_collide_polygon_and_circle/polygon_circle")
    ->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<ConvexPolygon, Ellipse>)->Name("ours/polygon_ellipse")->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<ConvexPolygon, Ellipse, true>)
    ->Name("ours/polygon_ellipse_limited")
    ->Apply(bench::polygon_workloads);
BENCHMARK(box2d<ConvexPolygon, Ellipse>)
    ->Name("box2d_collide_polygons/polygon_ellipse_8gon")
    ->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<Capsule, Circle>)->Name("ours/capsule_circle")->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<Capsule, Circle, true>)->Name("ours/capsule_circle_limited")->Apply(bench::polygon_workloads);
BENCHMARK(box2d<Capsule, Circle>)
    ->Name("box2d_collide_polygon_and_circle/capsule_circle")
    ->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<Capsule, Ellipse>)->Name("ours/capsule_ellipse")->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<Capsule, Ellipse, true>)->Name("ours/capsule_ellipse_limited")->Apply(bench::polygon_workloads);
BENCHMARK(box2d<Capsule, Ellipse>)
    ->Name("box2d_collide_polygons/capsule_ellipse_8gon")
    ->Apply(bench::polygon_workloads);

// A segment (Box2D's two-sided b2EdgeShape) against the core kinds, a circle and an ellipse.
BENCHMARK(ours_shape<Segment, ConvexPolygon>)->Name("ours/segment_polygon")->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<Segment, ConvexPolygon, true>)
    ->Name("ours/segment_polygon_limited")
    ->Apply(bench::polygon_workloads);
BENCHMARK(box2d<Segment, ConvexPolygon>)
    ->Name("box2d_collide_edge_and_polygon/segment_polygon")
    ->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<Segment, Circle>)->Name("ours/segment_circle")->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<Segment, Circle, true>)->Name("ours/segment_circle_limited")->Apply(bench::polygon_workloads);
BENCHMARK(box2d<Segment, Circle>)
    ->Name("box2d_collide_edge_and_circle/segment_circle")
    ->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<Segment, Ellipse>)->Name("ours/segment_ellipse")->Apply(bench::polygon_workloads);
BENCHMARK(ours_shape<Segment, Ellipse, true>)->Name("ours/segment_ellipse_limited")->Apply(bench::polygon_workloads);
BENCHMARK(box2d<Segment, Ellipse>)
    ->Name("box2d_collide_edge_and_polygon/segment_ellipse_8gon")
    ->Apply(bench::polygon_workloads);

// A chain segment against B, no contact beyond separation 0 (as Box2D's), through chain.h's contact
// with kept orientations (the World's call).
template <class B>
void ours_chain(benchmark::State& state) {
  const auto& w = bench::pairs<Segment, B>(state);
  const std::vector<ChainSegment> chain = bench::chain_segments_of(w.a);
  const std::vector<Orientation> oa = bench::orientations(w.a), ob = bench::orientations(w.b);
  const std::vector<Shape> sb(w.b.begin(), w.b.end());
  const ContactOptions options{.max_separation = 0.0};
  bench::time_queries(state, [&](std::size_t k) { return contact(chain[k], oa[k], sb[k], ob[k], options); });
}

// The same chain segments as child edges of Box2D's b2ChainShape (one-sided, with ghost vertices).
template <class B>
void box2d_chain(benchmark::State& state) {
  const auto& w = bench::pairs<Segment, B>(state);
  const std::vector<ChainSegment> chain = bench::chain_segments_of(w.a);
  std::vector<baseline::ShapePair> pairs;
  for (std::size_t k = 0; k < kPairs; ++k) {
    const Segment& s = chain[k].segment;
    const Vec2 origin = s.center, p2 = s.point2();
    const Vec2 points[] = {origin + chain[k].ghost1, origin, p2, origin + chain[k].ghost2};
    const baseline::Box2dShape edge = baseline::to_box2d_chain(points, origin)[0];
    pairs.push_back(
        {{edge, baseline::to_box2d_shape(baseline::to_box2d(w.b[k], 8, baseline::Fit::inscribed, origin))}});
  }
  b2Manifold manifold;
  bench::time_queries(state, [&](std::size_t k) {
    baseline::box2d_manifold(pairs[k], &manifold);
    return manifold.pointCount;
  });
}

// A chain segment (Box2D's b2ChainShape child edge) against the core kinds, a circle and an ellipse.
BENCHMARK(ours_chain<ConvexPolygon>)->Name("ours/chain_polygon_limited")->Apply(bench::polygon_workloads);
BENCHMARK(box2d_chain<ConvexPolygon>)
    ->Name("box2d_collide_edge_and_polygon/chain_polygon")
    ->Apply(bench::polygon_workloads);
BENCHMARK(ours_chain<Circle>)->Name("ours/chain_circle_limited")->Apply(bench::polygon_workloads);
BENCHMARK(box2d_chain<Circle>)->Name("box2d_collide_edge_and_circle/chain_circle")->Apply(bench::polygon_workloads);
BENCHMARK(ours_chain<Ellipse>)->Name("ours/chain_ellipse_limited")->Apply(bench::polygon_workloads);
BENCHMARK(box2d_chain<Ellipse>)
    ->Name("box2d_collide_edge_and_polygon/chain_ellipse_8gon")
    ->Apply(bench::polygon_workloads);

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
