// Rectangle–ellipse: overlap (the kernel and the two plain-double baselines) and distance on the
// hard-case families, against the 50-digit reference; agreement of the three overlap tests on a
// large random set.
#include "hard_cases.h"
#include "mp_reference.h"

#include <collide2d/kernels.h>

#include "narrowphase/baselines/baselines.h"
#include "narrowphase/overlap/overlap_rect_ellipse.h"
#include "tools/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

namespace collide2d::testing {
namespace {

Family rect_ellipse(std::string name) { return Family{.name = std::move(name), .a = Kind::rect, .b = Kind::ellipse}; }

class RectEllipseFamilies : public ::testing::TestWithParam<Family> {};

TEST_P(RectEllipseFamilies, MeetTargets) { run_family(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Standard, RectEllipseFamilies,
                         ::testing::ValuesIn(standard_families(Kind::rect, Kind::ellipse)),
                         [](const auto& info) { return test_name(info.param); });

// Gaps at the rounding level: the filter must defer, and run_family asserts that the default
// verdict (the double-double fallback) matches the exact verdict of the rounded input.
TEST(RectEllipseRounding, FallbackDecidesRoundingLevelContacts) {
  for (const double aspect : {1.0, 1e3, 1e6}) {
    char name[64];
    std::snprintf(name, sizeof name, "rect-ellipse gap<=1e-14 aspect %.0e", aspect);
    Family f = rect_ellipse(name);
    f.aspect_min = aspect;
    f.aspect_max = 4 * aspect;
    f.deltas = {0.0, 1e-14, -1e-14, 1e-15, -1e-15, 1e-16, -1e-16};
    f.cases = 280;
    f.seed = 3;
    const FamilyStats s = run_family(f);
    EXPECT_GT(s.fallbacks, 0) << "the filter never deferred at rounding-level gaps";
    EXPECT_EQ(s.rounding_verdicts_checked, 2 * f.cases) << "every verdict here is at the rounding level";
  }
}

// Choosing the corner by the quadrant of the ellipse centre, as Eberly's "Intersection of Rectangle
// and Ellipse" does, calls this pair overlapping; the needle's axis passes 3.39 from the rectangle.
TEST(RectEllipseOverlap, QuadrantCornerChoiceCounterexample) {
  const Rect r{Vec2(0, 0), Vec2(0.1, 0.1), 0.0};
  const Ellipse e{Vec2(1.1, 6.1), 10.0, 0.01, std::numbers::pi / 4};
  ASSERT_FALSE(reference::overlap(r, e));
  EXPECT_FALSE(overlap_rect_ellipse(r, e));
  for (const auto t : {baselines::RectEllipseTest::closest_features, baselines::RectEllipseTest::all_features}) {
    EXPECT_FALSE(baselines::overlap_rect_ellipse(r, e, t));
  }
  EXPECT_NEAR(distance_rect_ellipse(r, e).distance, static_cast<double>(reference::distance(r, e)), 1e-14);
}

// Random pairs at random gaps: the three tests must agree, and the filter rarely defers.
TEST(RectEllipseOverlap, MethodsAgreeOnRandomPairs) {
  std::mt19937_64 rng(42);
  const tool::Uniform u(0.0, 1.0);
  const auto log_u = [&](double lo, double hi) { return lo * std::pow(hi / lo, u(rng)); };
  const int n = 200000;
  int disagreements = 0, fallbacks = 0, overlapping = 0;
  for (int k = 0; k < n; ++k) {
    const Vec2 rc = tool::uniform_point(rng, -1, 1);
    const double height = log_u(0.01, 2);
    const Rect r{rc, Vec2(log_u(0.01, 2), height), 7 * u(rng)};
    const Ellipse e{tool::uniform_point(rng, -1, 1), log_u(0.001, 2), log_u(0.001, 2), 7 * u(rng)};
    const bool m = overlap_rect_ellipse(r, e);
    const bool c = baselines::overlap_rect_ellipse(r, e, baselines::RectEllipseTest::closest_features);
    const bool a = baselines::overlap_rect_ellipse(r, e, baselines::RectEllipseTest::all_features);
    overlapping += m;
    fallbacks += detail::overlap_rect_ellipse_filter(r, e) == detail::FilterVerdict::uncertain;
    if (m != c || m != a) {
      ++disagreements;
      ADD_FAILURE() << "methods disagree (minkowski " << m << ", closest " << c << ", all " << a << ") on rect "
                    << r.center.transpose() << " " << r.half_extents.transpose() << " " << r.angle << " ellipse "
                    << e.center.transpose() << " " << e.a << " " << e.b << " " << e.angle;
    }
  }
  std::printf("[random] %d pairs, %d overlapping, %d disagreements, %d fallbacks\n", n, overlapping, disagreements,
              fallbacks);
  EXPECT_GT(overlapping, n / 10);
  EXPECT_LT(overlapping, n - n / 10);
}

}  // namespace
}  // namespace collide2d::testing

namespace collide2d::testing {
namespace {

// With each shape's orientation given, the test is the same computation without the sines and
// cosines: the same verdict on every pair, near-tangent ones included.
TEST(RectEllipseOverlap, OrientedOverloadGivesTheSameVerdicts) {
  std::mt19937_64 rng(17);
  const tool::Uniform u(0.0, 1.0);
  int overlapping = 0;
  for (int k = 0; k < 200000; ++k) {
    const double aspect = std::pow(10.0, 6 * u(rng));
    const Vec2 rc = tool::uniform_point(rng, 0, 4);
    const double height = 0.05 + u(rng);
    const Rect r{rc, Vec2(0.05 + u(rng), height), 7 * u(rng)};
    Ellipse e{Vec2::Zero(), 0.05 + u(rng), 0, 7 * u(rng)};
    e.b = e.a / aspect;
    const double sine = std::sin(7 * u(rng));
    const Vec2 n(std::cos(7 * u(rng)), sine);
    const double gaps[] = {0.0, 1e-12, -1e-12, 1e-6, -1e-6, 0.3};
    e.center = support(r, n) + gaps[k % 6] * n - support(e, Vec2(-n));
    const bool plain = overlap_rect_ellipse(r, e);
    ASSERT_EQ(overlap_rect_ellipse(r, Orientation::of(r.angle), e, Orientation::of(e.angle)), plain) << k;
    overlapping += plain;
  }
  EXPECT_GT(overlapping, 50000);
}

}  // namespace
}  // namespace collide2d::testing
