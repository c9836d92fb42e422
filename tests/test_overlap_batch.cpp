// The batched overlap tests (overlap_batch.h) against the one-off kernels, verdict for verdict, on
// every SIMD target Highway compiled that this CPU runs: the hard-case families (rounding-level
// gaps included, where the batch must hand pairs to the fallback), two million random candidate
// pairs in batches of ragged lengths, and lists of different lengths refused.
#include "hard_cases.h"

#include "narrowphase/overlap_batch.h"
#include "narrowphase/overlap_rect_ellipse.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

namespace collide2d::testing {
namespace {

struct RectEllipsePairs {
  std::vector<Rect> rects;
  std::vector<Orientation> rect_orientations;
  std::vector<Ellipse> ellipses;
  std::vector<Orientation> ellipse_orientations;

  void add(const Rect& r, const Ellipse& e) {
    rects.push_back(r);
    rect_orientations.push_back(Orientation::of(r.angle));
    ellipses.push_back(e);
    ellipse_orientations.push_back(Orientation::of(e.angle));
  }
  std::size_t size() const { return rects.size(); }
};

// Runs the batch on [start, start + count) and compares each verdict with the one-off kernel's;
// returns the number of mismatches (each also reported).
int mismatches(const RectEllipsePairs& p, std::size_t start, std::size_t count, const char* target) {
  std::vector<std::uint8_t> out(count, 7);
  overlap_rect_ellipse(std::span(p.rects).subspan(start, count), std::span(p.rect_orientations).subspan(start, count),
                       std::span(p.ellipses).subspan(start, count),
                       std::span(p.ellipse_orientations).subspan(start, count), out);
  int wrong = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t k = start + i;
    const bool one = overlap_rect_ellipse(p.rects[k], p.rect_orientations[k], p.ellipses[k], p.ellipse_orientations[k]);
    if (out[i] == (one ? 1 : 0)) continue;
    if (++wrong <= 5) {
      ADD_FAILURE() << target << ": pair " << k << " batch " << int(out[i]) << ", one-off " << one << ": "
                    << describe(p.rects[k]) << " ; " << describe(p.ellipses[k]);
    }
  }
  return wrong;
}

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

TEST(OverlapBatch, HardCaseFamiliesMatchTheOneOffKernel) {
  std::vector<Family> families = standard_families(Kind::rect, Kind::ellipse);
  for (const double aspect : {1.0, 1e3, 1e6}) {
    Family rounding{.name = "rounding", .a = Kind::rect, .b = Kind::ellipse, .cases = 280};
    rounding.aspect_min = aspect;
    rounding.aspect_max = 4 * aspect;
    rounding.deltas = {0.0, 1e-14, -1e-14, 1e-15, -1e-15, 1e-16, -1e-16};
    families.push_back(rounding);
  }
  RectEllipsePairs p;
  for (const Family& f : families) {
    for (const Case& c : family_cases(f)) {
      const bool rect_first = std::holds_alternative<Rect>(c.a);
      p.add(std::get<Rect>(rect_first ? c.a : c.b), std::get<Ellipse>(rect_first ? c.b : c.a));
    }
  }
  int uncertain = 0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    uncertain += overlap_rect_ellipse_filter(p.rects[k], p.ellipses[k]) == FilterVerdict::uncertain;
  }
  std::printf("%zu hard-case pairs, %d of them uncertain for the filter\n", p.size(), uncertain);
  EXPECT_GT(uncertain, 500) << "the families must send pairs to the fallback";
  on_every_target([&](const char* target) { EXPECT_EQ(mismatches(p, 0, p.size(), target), 0) << target; });
}

// Candidate pairs as a broad phase hands them over, half of them placed at a small gap (either
// sign) along a random direction, needles to aspect 1e6; batches of 1 to 600 pairs, so that chunks
// end everywhere in a vector and the padding is exercised.
TEST(OverlapBatch, RandomCandidatePairsMatchTheOneOffKernel) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  RectEllipsePairs p;
  while (p.size() < 2'000'000) {
    const double aspect = std::pow(10.0, 6 * u(rng));
    const Rect r{Vec2(4 * u(rng), 4 * u(rng)), Vec2(0.05 + u(rng), 0.05 + u(rng)), 7 * u(rng)};
    Ellipse e{Vec2(4 * u(rng), 4 * u(rng)), 0.05 + u(rng), 0, 7 * u(rng)};
    e.b = e.a / aspect;
    if (p.size() % 2 == 1) {
      const Vec2 n(std::cos(7 * u(rng)), std::sin(7 * u(rng)));
      const double gap = (u(rng) - 0.5) * std::pow(10.0, -16 * u(rng));
      e.center = support(r, n) + gap * n - support(e, Vec2(-n));
    }
    if (intersects(aabb(r), aabb(e))) p.add(r, e);
  }
  on_every_target([&](const char* target) {
    std::mt19937_64 lengths(5);
    int wrong = 0;
    for (std::size_t start = 0; start < p.size();) {
      const std::size_t count = std::min<std::size_t>(1 + lengths() % 600, p.size() - start);
      wrong += mismatches(p, start, count, target);
      start += count;
    }
    EXPECT_EQ(wrong, 0) << target;
  });
}

TEST(OverlapBatch, ListsOfDifferentLengthsAreRefusedBeforeAnyWrite) {
  RectEllipsePairs p;
  p.add(Rect{{0, 0}, {1, 1}, 0}, Ellipse{{1.5, 0}, 1, 0.5, 0});
  p.add(Rect{{0, 0}, {1, 1}, 0}, Ellipse{{5, 0}, 1, 0.5, 0});
  std::vector<std::uint8_t> out(3, 7);
  try {
    overlap_rect_ellipse(p.rects, p.rect_orientations, p.ellipses, p.ellipse_orientations, out);
    ADD_FAILURE() << "three verdicts for two pairs were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "overlap_rect_ellipse: the lists differ in length (2, 2, 2, 2 pairs in, 3 verdicts out)");
  }
  EXPECT_EQ(out, std::vector<std::uint8_t>(3, 7));
  EXPECT_THROW(overlap_rect_ellipse(p.rects, std::span(p.rect_orientations).first(1), p.ellipses,
                                    p.ellipse_orientations, std::span(out).first(2)),
               std::invalid_argument);
  out.resize(2);
  overlap_rect_ellipse(p.rects, p.rect_orientations, p.ellipses, p.ellipse_orientations, out);
  EXPECT_EQ(out, (std::vector<std::uint8_t>{1, 0}));
  overlap_rect_ellipse({}, {}, {}, {}, {});  // nothing to do, and nothing touched
}

}  // namespace
}  // namespace collide2d::testing
