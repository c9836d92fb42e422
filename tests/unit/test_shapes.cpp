// Shapes: validation messages name the field; support points and containment agree with boundary
// points sampled from the shapes' parametric forms; AABBs hold the exact 50-digit box.
#include <collide2d/shapes.h>

#include "mp_reference.h"
#include "narrowphase/toi/quick_orientation.h"
#include "tools/random.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

namespace collide2d {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

void expect_rejected(const Shape& s, const std::string& words) {
  try {
    validate(s);
    ADD_FAILURE() << "accepted a shape with a bad " << words;
  } catch (const InvalidShape& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(Shapes, ValidationNamesTheField) {
  expect_rejected(Circle{Vec2(kNan, 0), 1}, "circle cx must be finite");
  expect_rejected(Circle{Vec2(0, kInf), 1}, "circle cy must be finite");
  expect_rejected(Circle{Vec2(0, 0), 0}, "circle radius must be positive");
  expect_rejected(Circle{Vec2(0, 0), -kInf}, "circle radius must be finite");
  expect_rejected(Ellipse{Vec2(0, 0), -1, 1, 0}, "ellipse a must be positive");
  expect_rejected(Ellipse{Vec2(0, 0), 1, kNan, 0}, "ellipse b must be finite");
  expect_rejected(Ellipse{Vec2(0, 0), 1, 1, kInf}, "ellipse angle must be finite");
  expect_rejected(Rect{Vec2(0, 0), Vec2(0, 1), 0}, "rect hx must be positive");
  expect_rejected(Rect{Vec2(0, 0), Vec2(1, -2), 0}, "rect hy must be positive");
  expect_rejected(Rect{Vec2(0, 0), Vec2(1, 1), kNan}, "rect angle must be finite");
  EXPECT_NO_THROW(validate(Shape(Rect{Vec2(1e9, -1e9), Vec2(1e-6, 1e6), 100.0})));
}

// Boundary points from the parametric forms, independent of the library's own frame code.
std::vector<Vec2> boundary_samples(const Shape& s, int n) {
  std::vector<Vec2> out;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    if (const auto* c = std::get_if<Circle>(&s)) out.push_back(c->center + c->radius * Vec2(std::cos(t), std::sin(t)));
    if (const auto* e = std::get_if<Ellipse>(&s)) {
      const Vec2 local(e->a * std::cos(t), e->b * std::sin(t));
      out.push_back(e->center + Eigen::Rotation2Dd(e->angle) * local);
    }
    if (const auto* r = std::get_if<Rect>(&s)) {
      const double u = static_cast<double>(k % 4 < 2 ? 1 : -1), v = static_cast<double>(k % 2 ? 1 : -1);
      out.push_back(r->center + Eigen::Rotation2Dd(r->angle) * Vec2(u * r->half_extents.x(), v * r->half_extents.y()));
    }
  }
  return out;
}

std::vector<Shape> random_shapes(int n) {
  std::mt19937_64 rng(9);
  const tool::Uniform u(0.01, 3.0), angle(-10, 10), pos(-5, 5);
  std::vector<Shape> out;
  for (int k = 0; k < n; ++k) {
    const double y = pos(rng);
    const Vec2 c(pos(rng), y);
    out.push_back(Circle{c, u(rng)});
    out.push_back(Ellipse{c, u(rng), u(rng) / 100, angle(rng)});
    const double height = u(rng);
    out.push_back(Rect{c, Vec2(u(rng), height), angle(rng)});
  }
  return out;
}

// The farthest point from the centre: a radius, a major semi-axis, a half diagonal (3-4-5).
TEST(Shapes, ReachIsTheFarthestPointFromTheCentre) {
  EXPECT_EQ(reach_of(Circle{{1, 2}, 0.5}), 0.5);
  EXPECT_EQ(reach_of(Ellipse{{1, 2}, 0.5, 2, 0.3}), 2.0);
  EXPECT_EQ(reach_of(Rect{{1, 2}, {3, 4}, 0.3}), 5.0);
}

TEST(Shapes, SupportMaximisesTheDirection) {
  std::mt19937_64 rng(10);
  const tool::Uniform angle(0, 2 * std::numbers::pi);
  for (const Shape& s : random_shapes(200)) {
    const std::vector<Vec2> samples = boundary_samples(s, 720);
    for (int k = 0; k < 8; ++k) {
      const double sine = std::sin(angle(rng));
      const Vec2 d(std::cos(angle(rng)), sine);
      const double h = d.dot(support(s, d));
      for (const Vec2& p : samples) ASSERT_LE(d.dot(p), h + 1e-12) << shape_name(s);
      // The support value is attained up to the sampling density: within 1e-4 of the best sample.
      double best = -std::numeric_limits<double>::infinity();
      for (const Vec2& p : samples) best = std::max(best, d.dot(p));
      ASSERT_LE(h - best, 1e-4 * (1 + std::abs(h))) << shape_name(s);
    }
  }
}

// Against the exact box (50 digits, rounded outward; tests/support/mp_reference.h): aabb() holds it, and
// exceeds it by no more than its documented slack of 8 eps of the coordinates (asserted: 10 eps,
// for the rounding of the half widths themselves).
TEST(Shapes, AabbHoldsTheExactBoxAndIsTight) {
  const double eps = std::numeric_limits<double>::epsilon();
  for (const Shape& s : random_shapes(200)) {
    const Aabb box = aabb(s), exact = reference::bounding_box(s);
    for (int k = 0; k < 2; ++k) {
      const double reach = std::max(std::abs(exact.min[k]), std::abs(exact.max[k]));
      ASSERT_LE(box.min[k], exact.min[k]) << shape_name(s);
      ASSERT_GE(box.max[k], exact.max[k]) << shape_name(s);
      ASSERT_LE(exact.min[k] - box.min[k], 10 * eps * reach) << shape_name(s);
      ASSERT_LE(box.max[k] - exact.max[k], 10 * eps * reach) << shape_name(s);
    }
  }
}

TEST(Shapes, ContainmentSeparatesInsideFromOutside) {
  for (const Shape& s : random_shapes(200)) {
    const Vec2 c = std::visit([](const auto& x) { return x.center; }, s);
    EXPECT_TRUE(contains(s, c));
    for (const Vec2& p : boundary_samples(s, 64)) {
      EXPECT_TRUE(contains(s, c + 0.999 * (p - c))) << shape_name(s);
      EXPECT_FALSE(contains(s, c + 1.001 * (p - c))) << shape_name(s);
    }
  }
}

// The quick cosine and sine against 50-digit ones of the same double angle: random angles over the
// whole range, angles a few ulps from multiples of pi/2 (where the reduction cancels most), and
// small ones. Within 2^-52 in each coordinate (2 u of 1); beyond 8e5 and for NaN it declines.
TEST(Shapes, QuickOrientationMatchesTheCosineAndSine) {
  std::mt19937_64 rng(17);
  std::vector<double> angles;
  const tool::Uniform any(-8e5, 8e5), small(-1e-3, 1e-3);
  for (int i = 0; i < 20000; ++i) angles.push_back(any(rng));
  for (int i = 0; i < 2000; ++i) angles.push_back(small(rng));
  for (const double k : {1.0, -1.0, 2.0, 3.0, 1e3, -7777.0, 123457.0, 509295.0}) {
    double a = k * std::numbers::pi / 2;
    for (int step = 0; step < 8; ++step) a = std::nextafter(a, 0.0);
    for (int step = 0; step < 16; ++step, a = std::nextafter(a, 2 * a)) angles.push_back(a);
  }
  double worst = 0;
  for (const double angle : angles) {
    const std::optional<Orientation> o = detail::quick_orientation(angle);
    ASSERT_TRUE(o.has_value()) << angle;
    const reference::Real exact(angle);
    worst = std::max({worst, std::abs(static_cast<double>(reference::Real(o->c) - cos(exact))),
                      std::abs(static_cast<double>(reference::Real(o->s) - sin(exact)))});
  }
  EXPECT_LE(worst, 0x1p-52);
  std::printf("[shapes] quick orientation: worst error %.2g over %zu angles\n", worst, angles.size());
  EXPECT_FALSE(detail::quick_orientation(8.0000001e5).has_value());
  EXPECT_FALSE(detail::quick_orientation(-1e300).has_value());
  EXPECT_FALSE(detail::quick_orientation(kNan).has_value());
}

}  // namespace
}  // namespace collide2d
