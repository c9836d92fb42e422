// Rectangle–ellipse: overlap (three methods) and distance on the hard-case families, against the
// 50-digit reference; agreement of the three overlap tests on a large random set.
#include "hard_cases.h"
#include "mp_reference.h"

#include "narrowphase/distance_rect_ellipse.h"
#include "narrowphase/overlap_rect_ellipse.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

namespace collide2d::testing {
namespace {

Family rect_ellipse(std::string name) { return Family{.name = std::move(name), .a = Kind::rect, .b = Kind::ellipse}; }

TEST(RectEllipseFamilies, NearTangent) {
  Family f = rect_ellipse("rect-ellipse near-tangent");
  f.cases = 400;
  run_family(f);
}

// Gaps at the rounding level: no verdict is owed here, but the filter must defer and the
// long-double fallback should still match the exact verdict of the rounded input.
TEST(RectEllipseFamilies, RoundingLevelContacts) {
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
  }
}

TEST(RectEllipseFamilies, AspectRatios) {
  for (const double aspect : {1e2, 1e3, 1e4, 1e5, 1e6}) {
    char name[64];
    std::snprintf(name, sizeof name, "rect-ellipse aspect %.0e", aspect);
    Family f = rect_ellipse(name);
    f.aspect_min = f.aspect_max = aspect;
    f.seed = static_cast<std::uint64_t>(aspect);
    run_family(f);
  }
}

TEST(RectEllipseFamilies, NearCircles) {
  Family f = rect_ellipse("rect-ellipse near-circle 1+1e-12");
  f.aspect_min = f.aspect_max = 1 + 1e-12;
  run_family(f);
}

TEST(RectEllipseFamilies, FarFromOrigin) {
  for (const double offset : {1e6, 1e9}) {
    Family f = rect_ellipse(offset > 1e7 ? "rect-ellipse offset 1e9" : "rect-ellipse offset 1e6");
    f.offset = offset;
    f.seed = 7;
    run_family(f);
  }
}

TEST(RectEllipseFamilies, TinyAndHuge) {
  for (const double size : {1e-6, 1e6}) {
    Family f = rect_ellipse(size < 1 ? "rect-ellipse size 1e-6" : "rect-ellipse size 1e6");
    f.size = size;
    f.seed = 11;
    run_family(f);
  }
}

TEST(RectEllipseFamilies, OneInsideTheOther) {
  Family f = rect_ellipse("rect-ellipse ellipse inside rect");
  f.placement = Placement::inside;
  run_family(f);
  Family g{.name = "rect-ellipse rect inside ellipse", .a = Kind::ellipse, .b = Kind::rect};
  g.placement = Placement::inside;
  g.aspect_max = 100;
  run_family(g);
}

TEST(RectEllipseFamilies, Identical) {
  Family f = rect_ellipse("rect-ellipse inscribed");
  f.placement = Placement::identical;
  f.aspect_max = 1e6;
  run_family(f);
}

// Seed 004 picks the corner by the quadrant of the ellipse centre and calls this pair overlapping;
// the needle's axis passes 3.39 from the rectangle.
TEST(RectEllipseOverlap, SeedCornerChoiceCounterexample) {
  const Rect r{Vec2(0, 0), Vec2(0.1, 0.1), 0.0};
  const Ellipse e{Vec2(1.1, 6.1), 10.0, 0.01, std::numbers::pi / 4};
  ASSERT_FALSE(reference::overlap(r, e));
  for (const auto m : {RectEllipseMethod::minkowski, RectEllipseMethod::closest_features, RectEllipseMethod::all_features}) {
    EXPECT_FALSE(overlap_rect_ellipse(r, e, m));
  }
  EXPECT_NEAR(distance_rect_ellipse(r, e).distance, static_cast<double>(reference::distance(r, e)), 1e-14);
}

// Random pairs at random gaps: the three tests must agree, and the filter rarely defers.
TEST(RectEllipseOverlap, MethodsAgreeOnRandomPairs) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto log_u = [&](double lo, double hi) { return lo * std::pow(hi / lo, u(rng)); };
  const int n = 200000;
  int disagreements = 0, fallbacks = 0, overlapping = 0;
  for (int k = 0; k < n; ++k) {
    const Rect r{Vec2(2 * u(rng) - 1, 2 * u(rng) - 1), Vec2(log_u(0.01, 2), log_u(0.01, 2)), 7 * u(rng)};
    const Ellipse e{Vec2(2 * u(rng) - 1, 2 * u(rng) - 1), log_u(0.001, 2), log_u(0.001, 2), 7 * u(rng)};
    const bool m = overlap_rect_ellipse(r, e, RectEllipseMethod::minkowski);
    const bool c = overlap_rect_ellipse(r, e, RectEllipseMethod::closest_features);
    const bool a = overlap_rect_ellipse(r, e, RectEllipseMethod::all_features);
    overlapping += m;
    fallbacks += overlap_rect_ellipse_filter(r, e) == FilterVerdict::uncertain;
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
