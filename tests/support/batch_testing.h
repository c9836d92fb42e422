// Test helpers for the batched kernels: pair lists with their orientations, and a check run on
// every SIMD target Highway compiled that this CPU runs.
#pragma once

#include "hard_cases.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstdint>
#include <cstdio>
#include <variant>
#include <vector>

namespace collide2d::testing {

template <class A, class B>
struct Pairs {
  std::vector<A> a;
  std::vector<Orientation> a_orientations;
  std::vector<B> b;
  std::vector<Orientation> b_orientations;

  void add(const A& x, const B& y) {
    a.push_back(x);
    a_orientations.push_back(Orientation::of(angle_of(x)));
    b.push_back(y);
    b_orientations.push_back(Orientation::of(angle_of(y)));
  }
  // A hard case's pair, either way round in the family, as (A, B).
  void add(const Case& c) {
    if (std::holds_alternative<A>(c.a) && std::holds_alternative<B>(c.b)) {
      add(std::get<A>(c.a), std::get<B>(c.b));
    } else {
      add(std::get<A>(c.b), std::get<B>(c.a));
    }
  }
  std::size_t size() const { return a.size(); }
};

// Runs check() once on every target Highway compiled that this CPU supports, then restores the
// normal choice.
template <class Check>
void on_every_target(Check check) {
  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  for (const std::int64_t target : targets) {
    hwy::SetSupportedTargetsForTest(target);
    std::printf("target %s\n", hwy::TargetName(target));
    check(hwy::TargetName(target));
  }
  hwy::SetSupportedTargetsForTest(0);
}

}  // namespace collide2d::testing
