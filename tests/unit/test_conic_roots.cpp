// Where the unit circle meets an ellipse (narrowphase/area/conic_roots.h), against crossings known in
// closed form in long double (circles, near-tangent ones included; a centred ellipse's four) and, on
// random ellipses, against a dense sampling of f refined by bisection in long double.
#include "narrowphase/area/conic_roots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace collide2d::detail::areas {
namespace {

using Real = long double;
constexpr double kEps = std::numeric_limits<double>::epsilon();

struct Point {
  Real x, y;
};

// The angle along the circle from the found unit vector to the reference point.
double angle_between(const Vec2& u, const Point& p) {
  return static_cast<double>(std::atan2(u.x() * p.y - u.y() * p.x, u.x() * p.x + u.y() * p.y));
}

// Each reference point matched by one found root within `tolerance` radians.
void expect_roots(const UnitCircleRoots& got, const std::vector<Point>& want, double tolerance,
                  const std::string& what) {
  ASSERT_EQ(got.count, static_cast<int>(want.size())) << what;
  for (const Point& p : want) {
    double nearest = INFINITY;
    for (int i = 0; i < got.count; ++i) nearest = std::min(nearest, std::abs(angle_between(got.u[i], p)));
    EXPECT_LE(nearest, tolerance) << what;
  }
}

Point turned(const Point& p, Real angle) {
  const Real c = std::cos(angle), s = std::sin(angle);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

// A circle of radius r centred at distance d along `angle` meets the unit circle where
// x = (1 + d^2 - r^2) / (2 d) in its frame; at d = 2 - delta, r = 1 the two crossings are sqrt(delta)
// apart, meeting at an angle of about sqrt(delta).
TEST(ConicRoots, CirclesUpToNearTangent) {
  for (const double delta : {0.5, 1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
    for (const double angle : {0.0, 0.7, 2.0, 3.1, -1.9}) {
      const double d = 2 - delta, r = 1;
      const Vec2 center = d * Vec2(std::cos(angle), std::sin(angle));
      const Real dd = std::hypot(static_cast<Real>(center.x()), static_cast<Real>(center.y()));
      const Real x = (1 + dd * dd - Real{r} * r) / (2 * dd), y = std::sqrt((1 - x) * (1 + x));
      const Real toward = std::atan2(static_cast<Real>(center.y()), static_cast<Real>(center.x()));
      const std::vector<Point> want{turned({x, y}, toward), turned({x, -y}, toward)};
      const double crossing = static_cast<double>(y);  // the sine of half the angle they meet at
      expect_roots(unit_circle_meets(Eigen::Matrix2d::Identity() / r, -center / r), want,
                   16 * kEps / crossing + 4 * kEps,
                   "delta " + std::to_string(delta) + " angle " + std::to_string(angle));
    }
  }
}

// A centred ellipse of half axes a = 1 + s and b = 1 - s turned by `angle` meets the unit circle
// at four points, cos^2 = (1 - 1/b^2) / (1/a^2 - 1/b^2) in its frame, at an angle of about s.
TEST(ConicRoots, CentredEllipseFourCrossings) {
  for (const double s : {0.5, 1e-2, 1e-4, 1e-6}) {
    for (const double angle : {0.0, 0.3, 1.2, 2.9}) {
      const double a = 1 + s, b = 1 - s;
      const Eigen::Matrix2d turn{{std::cos(angle), -std::sin(angle)}, {std::sin(angle), std::cos(angle)}};
      // N carries the ellipse onto the unit circle: its axes scaled by 1/a and 1/b in its frame.
      const Eigen::Matrix2d n = Eigen::Vector2d(1 / a, 1 / b).asDiagonal() * turn.transpose();
      const Real ia = 1 / (Real{a} * a), ib = 1 / (Real{b} * b);
      const Real c2 = (1 - ib) / (ia - ib), c = std::sqrt(c2), si = std::sqrt(1 - c2);
      // The frame's turn as n's rows hold it, so that the reference sees the same rounded rotation.
      const Real toward = std::atan2(static_cast<Real>(turn(1, 0)), static_cast<Real>(turn(0, 0)));
      std::vector<Point> want;
      for (const Point& p : {Point{c, si}, Point{-c, si}, Point{-c, -si}, Point{c, -si}})
        want.push_back(turned(p, toward));
      expect_roots(unit_circle_meets(n, Vec2::Zero()), want, 16 * kEps / s + 4 * kEps,
                   "s " + std::to_string(s) + " angle " + std::to_string(angle));
    }
  }
}

// f(u) = |N u + h|^2 - 1 in long double.
Real f_at(const Eigen::Matrix2d& n, const Vec2& h, Real t) {
  const Real ux = std::cos(t), uy = std::sin(t);
  const Real x = n(0, 0) * ux + n(0, 1) * uy + h.x(), y = n(1, 0) * ux + n(1, 1) * uy + h.y();
  return x * x + y * y - 1;
}

// Random ellipses: the sign changes of f on 4096 angles, each refined by bisection in long double.
TEST(ConicRoots, RandomEllipsesAgainstSampling) {
  std::mt19937_64 rng(71);
  std::uniform_real_distribution<double> size(0.3, 3.0), offset(-1.5, 1.5), turn(0, 2 * M_PI);
  int crossings = 0;
  for (int k = 0; k < 300; ++k) {
    const double a = size(rng), b = size(rng), angle = turn(rng);
    const Eigen::Matrix2d rotation{{std::cos(angle), -std::sin(angle)}, {std::sin(angle), std::cos(angle)}};
    const Eigen::Matrix2d n = Eigen::Vector2d(1 / a, 1 / b).asDiagonal() * rotation.transpose();
    const Vec2 h = n * Vec2(-offset(rng), -offset(rng));
    constexpr int kSamples = 4096;
    const Real step = 2 * static_cast<Real>(M_PI) / kSamples;
    std::vector<Point> want;
    for (int i = 0; i < kSamples; ++i) {
      Real lo = i * step, hi = lo + step;
      const Real f_lo = f_at(n, h, lo);
      if ((f_lo < 0) == (f_at(n, h, hi) < 0)) continue;
      for (int j = 0; j < 80; ++j) {
        const Real mid = (lo + hi) / 2;
        ((f_at(n, h, mid) < 0) == (f_lo < 0) ? lo : hi) = mid;
      }
      want.push_back({std::cos(lo), std::sin(lo)});
    }
    crossings += static_cast<int>(want.size());
    expect_roots(unit_circle_meets(n, h), want, 1e-11, "ellipse " + std::to_string(k));
    if (HasFailure()) return;
  }
  EXPECT_GT(crossings, 300);
}

}  // namespace
}  // namespace collide2d::detail::areas
