// Circle–circle, rectangle–circle and circle–ellipse on the hard-case families, against the 50-digit
// reference; and the circle path agreeing with the ellipse path at a = b.
#include "hard_cases.h"
#include "mp_reference.h"

#include "narrowphase/overlap_circle_ellipse.h"

#include <gtest/gtest.h>

#include <random>

namespace collide2d::testing {
namespace {

std::vector<Family> circle_families() {
  std::vector<Family> out;
  for (const auto& [a, b] : {std::pair{Kind::circle, Kind::circle}, std::pair{Kind::rect, Kind::circle},
                             std::pair{Kind::circle, Kind::ellipse}}) {
    const std::vector<Family> fs = standard_families(a, b);
    out.insert(out.end(), fs.begin(), fs.end());
  }
  return out;
}

class CircleFamilies : public ::testing::TestWithParam<Family> {};

TEST_P(CircleFamilies, MeetTargets) { run_family(GetParam()); }

INSTANTIATE_TEST_SUITE_P(Standard, CircleFamilies, ::testing::ValuesIn(circle_families()),
                         [](const auto& info) { return test_name(info.param); });

// A circle is an ellipse with a = b: the circle–circle path and the circle–ellipse path must agree.
TEST(CircleEllipse, CirclePathMatchesEllipsePathAtEqualAxes) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int k = 0; k < 20000; ++k) {
    const Circle c{Vec2(u(rng), u(rng)), 0.1 + std::abs(u(rng))};
    const Circle d{Vec2(u(rng), u(rng)), 0.1 + std::abs(u(rng))};
    const Ellipse e{d.center, d.radius, d.radius, u(rng)};
    const DistanceResult as_circle = distance(c, d);
    const DistanceResult as_ellipse = distance(c, e);
    ASSERT_EQ(overlaps(c, d), overlaps(c, e)) << k;
    ASSERT_NEAR(as_circle.distance, as_ellipse.distance, 1e-14) << k;
    if (!as_circle.overlapping) {
      ASSERT_LT((as_circle.point_b - as_ellipse.point_b).norm(), 1e-13) << k;
    }
  }
}

}  // namespace
}  // namespace collide2d::testing
