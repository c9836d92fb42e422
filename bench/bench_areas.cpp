// Overlap areas and IoU (area.h). Rotated boxes as a detector scores them: a batch of 4,096 pairs
// of a box and a noisy copy of it (centre moved by up to a fifth of its size, sides changed by up
// to a tenth, angle by up to 0.3 rad) against a rival written from detectron2's method
// (narrowphase/baselines/rotated_box_iou.h), a loop of it over the same pairs; and one pair at a
// time against one pair at a time. Then overlap_area() one pair at a time on the generator's
// overlapping candidate pairs of each kind (bench/shape_pairs.h), and the N x M problem of
// 100,000 boxes against 100,000 through iou_pairs(). Two ellipses also against a rival that follows
// Hughes and Chraibi (narrowphase/baselines/ellipse_overlap_area.h), one pair at a time. And iou()
// beside iou_distance() on near-identical pairs, the price of the distance's own digits.
#include <collide2d/area.h>

#include "bench/scene_workload.h"
#include "bench/workload.h"
#include "narrowphase/baselines/ellipse_overlap_area.h"
#include "narrowphase/baselines/rotated_box_iou.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace collide2d {
namespace {

using bench::kPairs;

// n boxes over a square of side `side`, sides 2 to 20.
std::vector<Shape> boxes(std::size_t n, double side, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> at(0, side), half(1, 10), turn(-std::numbers::pi, std::numbers::pi);
  std::vector<Shape> out;
  for (std::size_t k = 0; k < n; ++k)
    out.push_back(Rect{Vec2(at(rng), at(rng)), Vec2(half(rng), half(rng)), turn(rng)});
  return out;
}

// Each box's noisy copy, as a detection of it.
std::vector<Shape> detections_of(const std::vector<Shape>& truths, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<Shape> out;
  for (const Shape& s : truths) {
    const Rect& r = std::get<Rect>(s);
    const double size = r.half_extents.maxCoeff();
    out.push_back(Rect{r.center + 0.2 * size * Vec2(unit(rng), unit(rng)),
                       r.half_extents.cwiseProduct(Vec2(1 + 0.1 * unit(rng), 1 + 0.1 * unit(rng))),
                       r.angle + 0.3 * unit(rng)});
  }
  return out;
}

struct Detections {
  std::vector<Shape> truths, found;
  std::vector<Rect> truth_rects, found_rects;
};

const Detections& detections() {
  static const Detections d = [] {
    std::mt19937_64 rng(56);
    Detections out;
    out.truths = boxes(kPairs, 1000, rng);
    out.found = detections_of(out.truths, rng);
    for (std::size_t k = 0; k < kPairs; ++k) {
      out.truth_rects.push_back(std::get<Rect>(out.truths[k]));
      out.found_rects.push_back(std::get<Rect>(out.found[k]));
    }
    return out;
  }();
  return d;
}

void ours_batch(benchmark::State& state) {
  const Detections& d = detections();
  std::vector<double> out(kPairs);
  bench::time_batches(state, [&] { ious(d.truths, d.found, out); });
}

void rival_batch(benchmark::State& state) {
  const Detections& d = detections();
  std::vector<double> out(kPairs);
  bench::time_batches(state, [&] {
    for (std::size_t k = 0; k < kPairs; ++k) out[k] = baselines::rotated_box_iou(d.truth_rects[k], d.found_rects[k]);
  });
}

void ours_one(benchmark::State& state) {
  const Detections& d = detections();
  bench::time_queries(state, [&](std::size_t k) { return iou(d.truths[k], d.found[k]); });
}

void rival_one(benchmark::State& state) {
  const Detections& d = detections();
  bench::time_queries(state,
                      [&](std::size_t k) { return baselines::rotated_box_iou(d.truth_rects[k], d.found_rects[k]); });
}

BENCHMARK(ours_batch)->Name("ours/iou_rotated_boxes_batch");
BENCHMARK(rival_batch)->Name("detectron2_method/iou_rotated_boxes_batch");
BENCHMARK(ours_one)->Name("ours/iou_rotated_boxes");
BENCHMARK(rival_one)->Name("detectron2_method/iou_rotated_boxes");

template <class A, class B>
void overlap_area_pairs(benchmark::State& state) {
  const auto& w = bench::pairs<A, B>(state);
  bench::time_queries(state, [&](std::size_t k) { return overlap_area(w.a[k], w.b[k]).area; });
}

void hughes_chraibi(benchmark::State& state) {
  const auto& w = bench::pairs<Ellipse, Ellipse>(state);
  bench::time_queries(state, [&](std::size_t k) { return baselines::ellipse_overlap_area(w.a[k], w.b[k]); });
}

// The overlapping pairs among the generator's candidates (workload 3).
void overlapping_candidates(benchmark::internal::Benchmark* b) { b->ArgName("candidates")->Arg(3); }

BENCHMARK(overlap_area_pairs<Circle, Circle>)->Name("ours/overlap_area/circle_circle")->Apply(overlapping_candidates);
BENCHMARK(overlap_area_pairs<Rect, Rect>)->Name("ours/overlap_area/rect_rect")->Apply(overlapping_candidates);
BENCHMARK(overlap_area_pairs<Capsule, Capsule>)
    ->Name("ours/overlap_area/capsule_capsule")
    ->Apply(overlapping_candidates);
BENCHMARK(overlap_area_pairs<Circle, Ellipse>)->Name("ours/overlap_area/circle_ellipse")->Apply(overlapping_candidates);
BENCHMARK(overlap_area_pairs<Rect, Ellipse>)->Name("ours/overlap_area/rect_ellipse")->Apply(overlapping_candidates);
BENCHMARK(overlap_area_pairs<Ellipse, Ellipse>)
    ->Name("ours/overlap_area/ellipse_ellipse")
    ->Apply(overlapping_candidates);
BENCHMARK(hughes_chraibi)->Name("hughes_chraibi/overlap_area/ellipse_ellipse")->Apply(overlapping_candidates);

// Each overlapping candidate's first shape beside itself moved by 1e-6 of its size and turned by
// 1e-6 rad: near-identical pairs, which iou_distance() takes again in double-double.
template <class A>
const bench::Workload<A, A>& near_identical() {
  static const bench::Workload<A, A> w = [] {
    bench::Workload<A, A> out;
    out.a = bench::overlapping(bench::candidate_workload<A, A>()).a;
    for (const A& s : out.a) {
      const Aabb box = aabb(s);
      A near = s;
      near.center += 1e-6 * (box.max - box.min).maxCoeff() * Vec2(0.6, 0.8);
      if constexpr (requires { near.angle; }) near.angle += 1e-6;
      out.b.push_back(near);
    }
    return out;
  }();
  return w;
}

template <class A>
void iou_distance_near(benchmark::State& state) {
  const auto& w = near_identical<A>();
  bench::time_queries(state, [&](std::size_t k) { return iou_distance(w.a[k], w.b[k]); });
}

template <class A>
void iou_near(benchmark::State& state) {
  const auto& w = near_identical<A>();
  bench::time_queries(state, [&](std::size_t k) { return iou(w.a[k], w.b[k]); });
}

BENCHMARK(iou_near<Rect>)->Name("ours/iou/rect_rect/near_identical");
BENCHMARK(iou_distance_near<Rect>)->Name("ours/iou_distance/rect_rect/near_identical");
BENCHMARK(iou_near<Circle>)->Name("ours/iou/circle_circle/near_identical");
BENCHMARK(iou_distance_near<Circle>)->Name("ours/iou_distance/circle_circle/near_identical");
BENCHMARK(iou_near<Capsule>)->Name("ours/iou/capsule_capsule/near_identical");
BENCHMARK(iou_distance_near<Capsule>)->Name("ours/iou_distance/capsule_capsule/near_identical");
BENCHMARK(iou_near<Ellipse>)->Name("ours/iou/ellipse_ellipse/near_identical");
BENCHMARK(iou_distance_near<Ellipse>)->Name("ours/iou_distance/ellipse_ellipse/near_identical");

// N boxes against N over a square that keeps a box's expected overlaps near 3, and the pairs of
// them with IoU above 0 by `count`, reported with the time.
template <class Count>
void time_n_by_n(benchmark::State& state, Count count) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::mt19937_64 rng(57);
  const double side = std::sqrt(static_cast<double>(n) * 130);
  const std::vector<Shape> a = boxes(n, side, rng), b = boxes(n, side, rng);
  std::size_t found = 0;
  for (auto _ : state) found = count(a, b);
  state.counters["pairs"] = static_cast<double>(found);
}

void iou_pairs_of(benchmark::State& state) {
  time_n_by_n(state, [](const std::vector<Shape>& a, const std::vector<Shape>& b) { return iou_pairs(a, b).size(); });
}

// The same problem measured pair by pair, every pair.
void iou_dense_of(benchmark::State& state) {
  time_n_by_n(state, [](const std::vector<Shape>& a, const std::vector<Shape>& b) {
    std::size_t found = 0;
    for (const Shape& x : a)
      for (const Shape& y : b) found += iou(x, y) > 0;
    return found;
  });
}

BENCHMARK(iou_pairs_of)->Name("ours/iou_pairs")->Arg(2000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(iou_dense_of)->Name("ours/iou_dense")->Arg(2000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
