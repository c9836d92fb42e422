// Time of impact against Box2D 2.4.1's b2TimeOfImpact on 8- and 16-gons (b2DistanceProxy takes any
// vertex count, so Debian's binary serves). Pairs apart at t = 0, B 2 to 4 away from A and coming
// back at 4 to 8 per step with a sideways drift (sizes 0.05 to 1, aspect up to 10): most meet within
// the step. Translation only, and with both turning up to 2 radians per step. Box2D's shapes and
// sweeps are built beforehand; its proxies are set per call (a few stores).
#include <collide2d/query.h>
#include <collide2d/time_of_impact.h>

#include "bench/box2d_baseline.h"
#include "bench/toi_pairs.h"
#include "bench/workload.h"

#include <benchmark/benchmark.h>

#include <vector>

namespace collide2d {
namespace {

using bench::kPairs;
using bench::Moving;
using bench::toi_workload;

template <class A, class B, bool Turning>
void ours(benchmark::State& state) {
  const Moving& w = toi_workload<A, B, Turning>();
  bench::time_queries(state, [&](std::size_t k) { return time_of_impact(w.a[k], w.ma[k], w.b[k], w.mb[k]).t; });
}

template <class A, class B, bool Turning, int Sides>
void box2d(benchmark::State& state) {
  const Moving& w = toi_workload<A, B, Turning>();
  std::vector<baseline::ToiPair> pairs;
  for (std::size_t k = 0; k < kPairs; ++k) {
    pairs.push_back(baseline::to_box2d_toi(w.a[k], w.ma[k], w.b[k], w.mb[k], Sides, baseline::Fit::inscribed));
  }
  b2TOIOutput out;
  bench::time_queries(state, [&](std::size_t k) {
    baseline::box2d_time_of_impact(pairs[k], &out);
    return out.t;
  });
}

BENCHMARK(ours<Ellipse, Ellipse, false>)->Name("ours/ellipse_ellipse_translating");
BENCHMARK(box2d<Ellipse, Ellipse, false, 8>)->Name("box2d_toi/ellipse_ellipse_translating_8gons");
BENCHMARK(box2d<Ellipse, Ellipse, false, 16>)->Name("box2d_toi/ellipse_ellipse_translating_16gons");
BENCHMARK(ours<Ellipse, Ellipse, true>)->Name("ours/ellipse_ellipse_turning");
BENCHMARK(box2d<Ellipse, Ellipse, true, 8>)->Name("box2d_toi/ellipse_ellipse_turning_8gons");
BENCHMARK(box2d<Ellipse, Ellipse, true, 16>)->Name("box2d_toi/ellipse_ellipse_turning_16gons");
BENCHMARK(ours<Rect, Ellipse, false>)->Name("ours/rect_ellipse_translating");
BENCHMARK(box2d<Rect, Ellipse, false, 8>)->Name("box2d_toi/rect_ellipse_translating_8gon");
BENCHMARK(box2d<Rect, Ellipse, false, 16>)->Name("box2d_toi/rect_ellipse_translating_16gon");
BENCHMARK(ours<Rect, Ellipse, true>)->Name("ours/rect_ellipse_turning");
BENCHMARK(box2d<Rect, Ellipse, true, 8>)->Name("box2d_toi/rect_ellipse_turning_8gon");
BENCHMARK(box2d<Rect, Ellipse, true, 16>)->Name("box2d_toi/rect_ellipse_turning_16gon");
BENCHMARK(ours<Circle, Ellipse, false>)->Name("ours/circle_ellipse_translating");
BENCHMARK(box2d<Circle, Ellipse, false, 8>)->Name("box2d_toi/circle_ellipse_translating_8gon");
BENCHMARK(box2d<Circle, Ellipse, false, 16>)->Name("box2d_toi/circle_ellipse_translating_16gon");
BENCHMARK(ours<Circle, Ellipse, true>)->Name("ours/circle_ellipse_turning");
BENCHMARK(box2d<Circle, Ellipse, true, 8>)->Name("box2d_toi/circle_ellipse_turning_8gon");
BENCHMARK(box2d<Circle, Ellipse, true, 16>)->Name("box2d_toi/circle_ellipse_turning_16gon");
BENCHMARK(ours<Rect, Rect, true>)->Name("ours/rect_rect_turning");
BENCHMARK(box2d<Rect, Rect, true, 4>)->Name("box2d_toi/rect_rect_turning");

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
