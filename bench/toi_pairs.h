// The time-of-impact benchmarks' moving pairs (bench/bench_toi.cpp, bench/box2d_v3/toi.cpp): apart at
// t = 0, B 2 to 4 away from A and coming back at 4 to 8 per step with a sideways drift, both turning
// up to 2 radians per step where asked.
#pragma once

#include <collide2d/query.h>
#include <collide2d/time_of_impact.h>

#include "bench/workload.h"

#include <cmath>
#include <vector>

namespace collide2d::bench {

struct Moving {
  std::vector<Shape> a, b;
  std::vector<Motion> ma, mb;
};

template <class A, class B>
Moving moving_pairs(bool turning) {
  bench::Generator g;
  Moving out;
  while (out.a.size() < kPairs) {
    A a;
    B b;
    g.make(a);
    g.make(b);
    const double heading = g.uniform(0, 6.283185307179586);
    const Vec2 u(std::cos(heading), std::sin(heading));
    b.center = a.center + g.uniform(2, 4) * u;
    if (overlaps(a, b)) continue;
    const Vec2 drift(-u.y(), u.x());
    const double spin_a = turning ? g.uniform(-2, 2) : 0.0, spin_b = turning ? g.uniform(-2, 2) : 0.0;
    out.a.push_back(a);
    out.b.push_back(b);
    out.ma.push_back({Vec2::Zero(), spin_a});
    out.mb.push_back({-g.uniform(4, 8) * u + g.uniform(-1, 1) * drift, spin_b});
  }
  return out;
}

template <class A, class B, bool Turning>
const Moving& toi_workload() {
  static const Moving w = moving_pairs<A, B>(Turning);
  return w;
}

}  // namespace collide2d::bench
