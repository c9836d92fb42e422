// The benchmarks' timing loops over the workloads of bench/shape_pairs.h, and the choice of workload
// by a benchmark's argument.
#pragma once

#include <benchmark/benchmark.h>

#include "bench/shape_pairs.h"

namespace collide2d::bench {

// Runs query(k) once per benchmark iteration, k cycling over the pairs.
template <class Query>
void time_queries(benchmark::State& state, Query query) {
  std::size_t k = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(query(k));
    k = (k + 1) & (kPairs - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

// Runs batch() over all the pairs once per benchmark iteration; per_pair is the time divided by the
// pairs, to set beside the one-off kernels' times.
template <class Batch>
void time_batches(benchmark::State& state, Batch batch) {
  for (auto _ : state) {
    batch();
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * kPairs);
  state.counters["per_pair"] = benchmark::Counter(
      static_cast<double>(kPairs), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// The benchmark's workload, by its first argument: random pairs (0), the generator's candidate pairs
// (1), the built-in scene's (2), and the overlapping pairs among the generator's candidates (3) and
// among the scene's (4).
template <class A, class B>
const Workload<A, B>& pairs(const benchmark::State& state) {
  switch (state.range(0)) {
    case 0:
      return workload<A, B>();
    case 1:
      return candidate_workload<A, B>();
    case 2:
      return scene_workload<A, B>();
    case 3: {
      static const Workload<A, B> w = overlapping(candidate_workload<A, B>());
      return w;
    }
    default: {
      static const Workload<A, B> w = overlapping(scene_workload<A, B>());
      return w;
    }
  }
}

// Registers a benchmark on the three workloads, named candidates:0, candidates:1 and candidates:2
// (->Apply(...)); contact_workloads adds the overlapping pairs, candidates:3 and candidates:4.
inline void workloads(benchmark::internal::Benchmark* b) { b->ArgName("candidates")->Arg(0)->Arg(1)->Arg(2); }
inline void contact_workloads(benchmark::internal::Benchmark* b) {
  workloads(b);
  b->Arg(3)->Arg(4);
}
// The built-in scene has no polygons, capsules or segments: pairs with one run on the random pairs
// (0), the generator's candidates (1) and the overlapping ones among them (3).
inline void polygon_workloads(benchmark::internal::Benchmark* b) { b->ArgName("candidates")->Arg(0)->Arg(1)->Arg(3); }

}  // namespace collide2d::bench
