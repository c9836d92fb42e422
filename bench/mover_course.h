// The mover suite's verdict (tests/support/mover_course.h) as a benchmark's counters, for
// bench/bench_movers.cpp and bench/box2d_v3/mover_course.cpp: the worst value of each check, and
// how many moves each judged.
#pragma once

#include "tests/support/mover_course.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <utility>

namespace collide2d::bench {

inline void report_verdict(benchmark::State& state, const testing::Verdict& v) {
  const std::pair<const char*, double> worst[] = {{"depth", v.depth},
                                                  {"blocked_low", v.blocked_low},
                                                  {"blocked_high", v.blocked_high},
                                                  {"seam", v.seam},
                                                  {"bump_low", v.bump_low},
                                                  {"bump_high", v.bump_high},
                                                  {"progress", v.progress},
                                                  {"slide", v.slide},
                                                  {"drift", v.drift},
                                                  {"soft", v.soft},
                                                  {"moves", double(v.moves)},
                                                  {"blocked", double(v.blocked)},
                                                  {"clear", double(v.clear)},
                                                  {"on_tiles", double(v.on_tiles)},
                                                  {"standing", double(v.standing)},
                                                  {"riding", double(v.riding)},
                                                  {"crushed", double(v.crushed)},
                                                  {"fell", double(v.fell)}};
  // A check that judged nothing has no worst value (and JSON no infinity).
  for (const auto& [name, value] : worst)
    if (std::isfinite(value)) state.counters[name] = value;
}

}  // namespace collide2d::bench
