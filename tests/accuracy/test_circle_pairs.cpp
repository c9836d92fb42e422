// Circle–circle, rectangle–circle and circle–ellipse on the hard-case families, against the 50-digit
// reference; and the circle path agreeing with the ellipse path at a = b.
#include "hard_cases.h"
#include "mp_reference.h"

#include <collide2d/kernels.h>
#include "narrowphase/shared/ellipse/distance_point_ellipse.h"
#include "tools/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <vector>

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
  const tool::Uniform u(-2.0, 2.0);
  for (int k = 0; k < 20000; ++k) {
    const double cy = u(rng);
    const Circle c{Vec2(u(rng), cy), 0.1 + std::abs(u(rng))};
    const double dy = u(rng);
    const Circle d{Vec2(u(rng), dy), 0.1 + std::abs(u(rng))};
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

// The point–ellipse distance inside, near the major axis, where the secular root is tiny: points
// beside the evolute's cusp at heights 0 and 1e-17 ... 1e-3 (a height of 1e-17 once gave a distance
// off by 1.3e-2), and random points inside and out, against the 50-digit curve distance.
TEST(PointEllipse, DistanceInsideNearTheAxisMatchesReference) {
  std::mt19937_64 rng(9);
  const tool::Uniform u(-1.0, 1.0);
  double worst = 0;
  for (int k = 0; k < 2000; ++k) {
    const double a = 1.0, b = std::pow(10.0, -3.0 * std::abs(u(rng)));
    const double cusp = (a * a - b * b) / a;
    Vec2 p;
    if (k % 2 == 0) {
      const double height = k % 20 == 0 ? 0.0 : std::pow(10.0, -3.0 - 14.0 * std::abs(u(rng)));
      const double y = std::copysign(height, u(rng));
      p = Vec2(cusp * (1 + 0.05 * u(rng)), y);
    } else {
      const double y = 1.5 * b * u(rng);
      p = Vec2(1.5 * u(rng), y);
    }
    const PointEllipseResult r = distance_point_ellipse(a, b, p);
    const Ellipse e{Vec2::Zero(), a, b, 0.0};
    const double ref = static_cast<double>(reference::curve_distance(e, reference::to_mp(p)));
    const double err = std::abs(r.distance - ref) / std::max(a, p.norm());
    worst = std::max(worst, err);
    ASSERT_LE(err, 4 * std::numeric_limits<double>::epsilon()) << "b " << b << " p " << p.transpose();
    EXPECT_EQ(r.inside, p.x() * p.x() / (a * a) + p.y() * p.y() / (b * b) <= 1.0);
  }
  std::printf("[point-ellipse] 2,000 points near the cusp and at random: worst error %.2e of the scale\n", worst);
}

// Points a subnormal height off the major axis, inside, where the secular root t ~ z1 lies below
// 1e-308 and 1 / t overflows (the fuzzer's circle-ellipse contact came out infinite: a circle 0.25
// from the centre of a near-circular ellipse 1.08e16 across, turned by 2e-314 rad), and heights
// whose ratio to the axis underflows to 0: finite, and within 4 u of the scale of the 50-digit
// curve distance of the point on the axis below (the distance moves by at most the height, and the
// 50-digit reference's own Newton, started at -b^2 + b y1, loses a height below 1e-50 of the size).
TEST(PointEllipse, SubnormalHeightsOffTheAxisMatchReference) {
  int checked = 0;
  for (const double a : {1.0, 1.0843961455776390e16}) {
    for (const double aspect : {1.0 + 1e-11, 2.0, 1e3}) {
      const double b = a / aspect;
      for (const double along : {0.0, 0.25, 0.5 * (a * a - b * b) / a, 0.999 * a}) {
        for (const double height : {1e-300, 1e-310, 5.2896e-315, 1e-322}) {
          const Vec2 p(along, height);
          const PointEllipseResult r = distance_point_ellipse(a, b, p);
          ASSERT_TRUE(std::isfinite(r.distance) && r.closest.allFinite()) << a << " " << b << " " << p.transpose();
          const Ellipse e{Vec2::Zero(), a, b, 0.0};
          const double ref = static_cast<double>(reference::curve_distance(e, reference::to_mp(Vec2(along, 0.0))));
          EXPECT_LE(std::abs(r.distance - ref),
                    4 * std::numeric_limits<double>::epsilon() * std::max(a, p.norm()) + height)
              << "a " << a << " b " << b << " p " << p.transpose();
          // The same point seen from the other axis (the ellipse turned a quarter).
          const PointEllipseResult q = distance_point_ellipse(b, a, Vec2(height, along));
          EXPECT_EQ(q.distance, r.distance) << "a " << a << " b " << b << " p " << p.transpose();
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 96);
}

// other_local_nearest against a dense scan of the dual function g(v) = v.p - h(v) over 20,000
// directions, whose local maxima are the feet of the normals through p where the distance along
// the curve is locally least: as many as the scan finds (one, or two inside the evolute), each foot on
// the curve with p on its normal, p nearer than the centre of curvature (a minimum, not the
// maximum beside it), and its direction and value those of the scan's second maximum within the
// grid's spacing. Points span the evolute's bounding box, a >= b and b > a, aspects 1 to 100;
// points whose scan is ambiguous (within 1e-3 of the evolute, where the two roots merge) are
// skipped.
TEST(PointEllipse, OtherLocalNearestMatchesADenseScan) {
  std::mt19937_64 rng(3);
  const tool::Uniform u(-1.0, 1.0);
  constexpr int kGrid = 20000;
  int found = 0, checked = 0;
  for (int k = 0; k < 1500; ++k) {
    double a = 1.0, b = std::pow(10.0, -2.0 * std::abs(u(rng)));
    if (k % 2 == 1) std::swap(a, b);
    const double e0 = std::max(a, b), e1 = std::min(a, b), c = (e0 - e1) * (e0 + e1);
    const double along = c / e0 * u(rng), across = c / e1 * u(rng);
    const Vec2 p = a >= b ? Vec2(along, across) : Vec2(across, along);
    const double evolute = std::cbrt(std::pow(e0 * along, 2)) + std::cbrt(std::pow(e1 * across, 2)) - std::cbrt(c * c);
    if (std::abs(evolute) < 1e-3) continue;
    std::vector<double> g(kGrid);
    for (int i = 0; i < kGrid; ++i) {
      const double angle = 2 * M_PI * i / kGrid, vx = std::cos(angle), vy = std::sin(angle);
      g[static_cast<std::size_t>(i)] = vx * p.x() + vy * p.y() - std::hypot(a * vx, b * vy);
    }
    std::vector<int> maxima;
    for (int i = 0; i < kGrid; ++i) {
      const double here = g[static_cast<std::size_t>(i)];
      if (here > g[static_cast<std::size_t>((i + kGrid - 1) % kGrid)] &&
          here >= g[static_cast<std::size_t>((i + 1) % kGrid)]) {
        maxima.push_back(i);
      }
    }
    const std::optional<CurveFoot> other = other_local_nearest(a, b, p);
    ++checked;
    ASSERT_EQ(maxima.size(), other ? 2u : 1u) << "a " << a << " b " << b << " p " << p.transpose();
    if (!other) continue;
    ++found;
    const Vec2& x = other->point;
    EXPECT_NEAR(std::pow(x.x() / a, 2) + std::pow(x.y() / b, 2), 1.0, 1e-14)
        << "a " << a << " b " << b << " p " << p.transpose();
    const Vec2 d = p - x;
    EXPECT_NEAR(d.x() * other->normal.y() - d.y() * other->normal.x(), 0.0, 1e-14)
        << "a " << a << " b " << b << " p " << p.transpose();
    EXPECT_NEAR(d.dot(other->normal), other->signed_distance, 1e-14);
    // The radius of curvature at x: (ab)^2 / h^3 with h the support value along the normal.
    const double h = x.dot(other->normal);
    EXPECT_GT(other->signed_distance, -a * a * b * b / (h * h * h)) << "a local maximum of the distance";
    const double angle = std::atan2(other->normal.y(), other->normal.x());
    double nearest = M_PI;
    std::size_t at = 0;
    for (const int i : maxima) {
      const double off = std::abs(std::remainder(2 * M_PI * i / kGrid - angle, 2 * M_PI));
      if (off < nearest) nearest = off, at = static_cast<std::size_t>(i);
    }
    EXPECT_LE(nearest, M_PI / kGrid) << "a " << a << " b " << b << " p " << p.transpose();
    EXPECT_NEAR(g[at], other->signed_distance, 1e-6);
  }
  std::printf("[point-ellipse] %d points, %d with a second local minimum\n", checked, found);
  EXPECT_GT(found, checked / 5);
}

}  // namespace
}  // namespace collide2d::testing
