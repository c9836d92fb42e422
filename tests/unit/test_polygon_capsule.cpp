// Convex polygons and capsules as shapes: what their makers refuse and why, hulls whose answer is
// known by construction, areas and centroids against closed forms and a dense outline traced
// independently, and support points, containment and boxes against points sampled on the outline.
#include <collide2d/batch.h>
#include <collide2d/query.h>
#include <collide2d/ray_cast.h>
#include <collide2d/shapes.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include "contact_testing.h"
#include "refusals.h"
#include "tools/random.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace collide2d {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = std::numbers::pi;

void expect_refused(const std::function<void()>& make, const std::string& words) {
  testing::expect_refused<InvalidShape>(make, words);
}

std::vector<Vec2> regular_points(int n, double r, double phase = 0.0) {
  std::vector<Vec2> v;
  for (int k = 0; k < n; ++k)
    v.push_back(r * Vec2(std::cos(phase + 2 * kPi * k / n), std::sin(phase + 2 * kPi * k / n)));
  return v;
}

TEST(PolygonShape, RefusesWhatIsNotAConvexPolygon) {
  const std::vector<Vec2> square = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  expect_refused(
      [] {
        ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {1, 0}});
      },
      "polygon must have 3 to 8 vertices (got 2)");
  expect_refused([] { ConvexPolygon::of(regular_points(9, 1)); }, "polygon must have 3 to 8 vertices (got 9)");
  expect_refused(
      [] {
        ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {kNan, 0}, {0, 1}});
      },
      "polygon vertex 1 x must be finite (got nan)");
  expect_refused(
      [] {
        ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {1, 0}, {0, 2e50}});
      },
      "polygon vertex 2 y is beyond the supported range");
  expect_refused(
      [] {
        ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {0, 1}, {1, 0}});
      },
      "the vertices must run counter-clockwise");
  expect_refused(
      [] {
        ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {1, 0}, {2, 0}, {1, 1}});
      },
      "vertex 2 lies on the line of the edge from vertex 0 to 1 (to rounding)");
  // Turns whose determinant, computed in double, is smaller than its rounding (the exact ones are
  // -1.4e-17 and +1.4e-17): refused either way, whatever the rounded sign.
  expect_refused([] { ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {0.3, 0.1}, {0.9, 0.3}}); }, "(to rounding)");
  expect_refused([] { ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {0.9, 0.3}, {0.3, 0.1}}); }, "(to rounding)");
  // A pentagram turns left at every vertex and still is no convex polygon.
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k) star.push_back(regular_points(5, 1)[(2 * k) % 5]);
  expect_refused([&] { ConvexPolygon::of(star); }, "right of the edge");
  expect_refused([&] { ConvexPolygon::of(square, -1); }, "polygon radius must be 0 or positive (got -1)");
  expect_refused([&] { ConvexPolygon::of(square, 1e-60); }, "polygon radius is outside the supported range");
  expect_refused(
      [] {
        ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {1e-51, 0}, {0, 1e-51}});
      },
      "polygon is smaller than 1e-50 across");
  expect_refused(
      [] {
        ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {1e-51, 0}, {1, 1}});
      },
      "polygon edge from vertex 0 to 1 is shorter than 1e-50");
  expect_refused(
      [] {
        ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {8, 1e-310}, {-7, 1e-310}});
      },
      "thinner than the supported range");
  expect_refused(
      [] {
        ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {1, 0}, {0.5, 1e-60}});
      },
      "polygon vertex 2 lies within 1e-50 of the line of the edge from vertex 0 to 1");
  expect_refused(
      [] {
        ConvexPolygon::hull(std::vector<Vec2>{{0, 0}, {1, 1}});
      },
      "polygon needs at least 3 points (got 2)");
  expect_refused(
      [] {
        ConvexPolygon::hull(std::vector<Vec2>{{0, 0}, {1, 1}, {2, 2}, {3, 3}});
      },
      "points lie on one line");
  expect_refused([] { ConvexPolygon::hull(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1e-12}}); }, "points lie on one line");
  expect_refused([] { ConvexPolygon::hull(regular_points(9, 1)); },
                 "polygon hull has 9 vertices, more than the 8 supported");
  expect_refused(
      [] {
        ConvexPolygon::hull(std::vector<Vec2>{{0, 0}, {1, 0}, {0, kNan}});
      },
      "polygon point 2 y must be finite");
  expect_refused([&] { ConvexPolygon::hull(square, 0, -1); }, "polygon weld must not be negative");
  expect_refused([] { ConvexPolygon::box(0, 1); }, "polygon hx must be positive (got 0)");
  expect_refused([] { ConvexPolygon::box(1, 1, kNan); }, "polygon radius must be finite");
  expect_refused([] { ConvexPolygon::regular(9, 1); }, "polygon must have 3 to 8 vertices (got 9)");
  expect_refused([] { ConvexPolygon::regular(5, -2); }, "polygon circumradius must be positive");
  ConvexPolygon posed = ConvexPolygon::box(1, 2);
  posed.center.x() = kNan;
  expect_refused([&] { validate(posed); }, "polygon cx must be finite");
  posed = ConvexPolygon::box(1, 2).at({0, 0}, std::numeric_limits<double>::infinity());
  expect_refused([&] { validate(posed); }, "polygon angle must be finite");
  posed.outline = nullptr;
  posed.angle = 0;
  expect_refused([&] { validate(posed); }, "polygon has no outline");
  EXPECT_NO_THROW(validate(ConvexPolygon::regular(8, 1e-6, 1e-9).at({1e9, -1e9}, 100.0)));
}

TEST(CapsuleShape, RefusesBadFields) {
  expect_refused(
      [] {
        validate(Capsule{Vec2(0, 0), 0.0, 1.0, 0.0});
      },
      "capsule half_length must be positive (a capsule of no length is a circle: use circle) (got 0)");
  expect_refused(
      [] {
        validate(Capsule{Vec2(0, 0), -1.0, 1.0, 0.0});
      },
      "capsule half_length must be positive (got -1)");
  expect_refused([] { validate(Capsule{Vec2(0, 0), 1.0, 0.0, 0.0}); }, "capsule radius must be positive");
  expect_refused([] { validate(Capsule{Vec2(kNan, 0), 1.0, 1.0, 0.0}); }, "capsule cx must be finite");
  expect_refused([] { validate(Capsule{Vec2(0, 0), 1.0, 1.0, kNan}); }, "capsule angle must be finite");
  expect_refused(
      [] {
        validate(Capsule{Vec2(0, 0), 1e51, 1.0, 0.0});
      },
      "capsule half_length is outside the supported range");
  EXPECT_NO_THROW(validate(Capsule{Vec2(1e9, 0), 1.0, 1e-9, 3.0}));
}

// The hull of a convex polygon's vertices, shuffled among points inside it and copies a rounding
// away: the polygon's own vertices, counter-clockwise, whatever the order.
TEST(PolygonShape, HullFindsTheVerticesOfAKnownPolygon) {
  std::mt19937_64 rng(7);
  const tool::Uniform unit(0.0, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    const int n = 3 + trial % 6;
    const double scale = std::pow(10.0, -6 + 12 * unit(rng));
    const double y = unit(rng) - 0.5;
    const Vec2 offset = scale * Vec2(unit(rng) - 0.5, y);
    // Vertices on an ellipse at angles at least 2 pi / (2 n) apart: strictly convex by construction.
    std::vector<double> angles;
    for (int k = 0; k < n; ++k) angles.push_back(2 * kPi * (k + 0.5 * unit(rng)) / n);
    std::vector<Vec2> vertices;
    for (const double t : angles) vertices.push_back(offset + scale * Vec2(std::cos(t), 0.4 * std::sin(t)));
    std::vector<Vec2> points = vertices;
    for (int k = 0; k < 20; ++k) {
      const Vec2& p = vertices[k % n];
      const Vec2& q = vertices[(k + 1) % n];
      const Vec2& o = vertices[(k + 2) % n];
      const double s = unit(rng), t = unit(rng) * (1 - s);
      points.push_back(o + 0.99 * (s * (p - o) + t * (q - o)));
    }
    points.push_back(vertices[trial % n] * (1 + 1e-15));
    std::shuffle(points.begin(), points.end(), rng);
    const ConvexPolygon hull = ConvexPolygon::hull(points);
    ASSERT_EQ(hull.count(), n) << "trial " << trial;
    const auto v = hull.vertices();
    const auto start = std::find_if(vertices.begin(), vertices.end(),
                                    [&](const Vec2& p) { return (p - v[0]).norm() <= 1e-14 * scale; });
    ASSERT_NE(start, vertices.end()) << "trial " << trial;
    for (int k = 0; k < n; ++k) {
      const Vec2& expected = vertices[(start - vertices.begin() + k) % n];
      EXPECT_LE((v[k] - expected).norm(), 1e-14 * scale) << "trial " << trial << " vertex " << k;
    }
  }
}

TEST(PolygonShape, WeldScalesWithThePolygon) {
  for (const double scale : {1e-30, 1.0, 1e40}) {
    // Two vertices 1e-12 of the size apart weld into one; a vertex 1e-12 of the size off its
    // neighbours' line is dropped by the hull's weld and kept by of(), which takes vertices as given.
    const std::vector<Vec2> near_twins = {{0, 0}, {scale, 0}, {scale, scale * 1e-12}, {0, scale}};
    EXPECT_EQ(ConvexPolygon::hull(near_twins).count(), 3);
    EXPECT_EQ(ConvexPolygon::hull(near_twins, 0.0, 0.0).count(), 4);
    const std::vector<Vec2> bent = {{0, 0}, {scale / 2, -scale * 1e-12}, {scale, 0}, {scale, scale}};
    EXPECT_EQ(ConvexPolygon::hull(bent).count(), 3);
    EXPECT_EQ(ConvexPolygon::of(bent).count(), 4);
  }
}

// The boundary of a posed, possibly rounded polygon traced with `per_arc` points on each corner's
// arc, in long double.
using Point = Eigen::Matrix<long double, 2, 1>;
std::vector<Point> outline_points(const ConvexPolygon& p, int per_arc) {
  const long double c = std::cos(static_cast<long double>(p.angle)), s = std::sin(static_cast<long double>(p.angle));
  const auto place = [&](const Point& q) {
    return Point(p.center.x() + c * q.x() - s * q.y(), p.center.y() + s * q.x() + c * q.y());
  };
  const auto v = p.vertices();
  const long double r = p.radius();
  std::vector<Point> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Point a = v[(i + v.size() - 1) % v.size()].cast<long double>(), b = v[i].cast<long double>();
    const Point next = v[(i + 1) % v.size()].cast<long double>();
    const auto normal_angle = [](const Point& from, const Point& to) {
      return std::atan2(-(to - from).x(), (to - from).y());
    };
    long double t0 = normal_angle(a, b), t1 = normal_angle(b, next);
    if (t1 < t0) t1 += 2 * std::numbers::pi_v<long double>;
    const int steps = r > 0 ? per_arc : 0;
    for (int k = 0; k <= steps; ++k) {
      const long double t = steps == 0 ? t0 : t0 + (t1 - t0) * k / steps;
      out.push_back(place(b + r * Point(std::cos(t), std::sin(t))));
    }
  }
  return out;
}

// Area and centroid by the shoelace formula over a traced outline.
std::pair<long double, Point> shoelace(const std::vector<Point>& pts) {
  long double area = 0;
  Point moment(0, 0);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Point& p = pts[i];
    const Point& q = pts[(i + 1) % pts.size()];
    const long double w = p.x() * q.y() - p.y() * q.x();
    area += w / 2;
    moment += w * (p + q) / 6;
  }
  return {area, moment / area};
}

TEST(PolygonShape, AreaAndCentroid) {
  for (int n = 3; n <= 8; ++n) {
    const ConvexPolygon p = ConvexPolygon::regular(n, 2.0);
    EXPECT_NEAR(p.area(), n / 2.0 * 4.0 * std::sin(2 * kPi / n), 1e-14) << n;
    EXPECT_LE(p.centroid().norm(), 1e-15) << n;
  }
  const ConvexPolygon box = ConvexPolygon::box(2.0, 0.5, 0.25);
  EXPECT_NEAR(box.area(), 4 * 2.0 * 0.5 + 4 * (2.0 + 0.5) * 0.25 + kPi * 0.0625, 1e-14);
  const std::vector<Vec2> kite = {{-1, -0.5}, {3, -0.25}, {2.5, 1.5}, {0.25, 2}, {-0.75, 1}};
  for (const double r : {0.0, 0.125, 3.0}) {
    const ConvexPolygon p = ConvexPolygon::of(kite, r).at({10, -5}, 0.7);
    const auto [area, centroid] = shoelace(outline_points(p, 20000));
    EXPECT_NEAR(p.area(), static_cast<double>(area), 1e-7 * p.area()) << r;
    EXPECT_NEAR((p.centroid() - centroid.cast<double>()).norm(), 0.0, 1e-7) << r;
  }
}

// Points of each shape's outline in the world frame, with the outward normal there (at a sharp
// corner, the bisector of its two faces' normals).
struct Sample {
  Vec2 point;
  Vec2 normal;
};
std::vector<Sample> samples(const ConvexPolygon& p) {
  const Eigen::Rotation2Dd turn(p.angle);
  const auto v = p.vertices();
  const std::size_t n = v.size();
  std::vector<Sample> out;
  for (std::size_t i = 0; i < n; ++i) {
    const auto normal_of = [&](std::size_t k) {
      const Vec2 e = v[(k + 1) % n] - v[k];
      return Vec2(e.y(), -e.x()).normalized();
    };
    const Vec2 before = normal_of((i + n - 1) % n), after = normal_of(i);
    const double t0 = std::atan2(before.y(), before.x());
    double t1 = std::atan2(after.y(), after.x());
    if (t1 < t0) t1 += 2 * kPi;
    for (int k = 0; k <= 64; ++k) {
      const double t = t0 + (t1 - t0) * k / 64;
      const Vec2 normal = p.radius() > 0 ? Vec2(std::cos(t), std::sin(t)) : Vec2((before + after).normalized());
      out.push_back({p.center + turn * Vec2(v[i] + p.radius() * normal), turn * normal});
    }
    for (int k = 1; k < 16; ++k) {
      const Vec2 on_edge = v[i] + (v[(i + 1) % n] - v[i]) * k / 16.0 + p.radius() * after;
      out.push_back({p.center + turn * on_edge, turn * after});
    }
  }
  return out;
}
std::vector<Sample> samples(const Capsule& c) {
  const Vec2 axis(std::cos(c.angle), std::sin(c.angle)), across(-axis.y(), axis.x());
  std::vector<Sample> out;
  for (int k = 0; k <= 64; ++k) {
    const double t = kPi * k / 64;
    const Vec2 normal = std::sin(t) * axis + std::cos(t) * across;
    out.push_back({c.center + c.half_length * axis + c.radius * normal, normal});
    out.push_back({c.center - c.half_length * axis - c.radius * normal, -normal});
  }
  for (int k = -7; k < 8; ++k) {
    out.push_back({c.center + c.half_length * k / 8.0 * axis + c.radius * across, across});
    out.push_back({c.center + c.half_length * k / 8.0 * axis - c.radius * across, -across});
  }
  return out;
}
double rounding_radius(const ConvexPolygon& p) {
  return p.radius() > 0 ? p.radius() : std::numeric_limits<double>::infinity();
}
double rounding_radius(const Capsule& c) { return c.radius; }

template <class S>
std::vector<S> posed_shapes();
template <>
std::vector<ConvexPolygon> posed_shapes() {
  std::vector<ConvexPolygon> out;
  const std::vector<Vec2> kite = {{-1, -0.5}, {3, -0.25}, {2.5, 1.5}, {0.25, 2}, {-0.75, 1}};
  for (const double r : {0.0, 0.3}) {
    out.push_back(ConvexPolygon::of(kite, r).at({1e6, 3}, 2.2));
    out.push_back(ConvexPolygon::regular(8, 1e-5, r * 1e-5).at({-2, 7}, -0.4));
    out.push_back(ConvexPolygon::box(4, 1e-3, r).at({0, 0}, kPi / 2));
    out.push_back(ConvexPolygon::regular(3, 1e20, r * 1e20).at({1e20, 0}, 1.0));
  }
  return out;
}
template <>
std::vector<Capsule> posed_shapes() {
  return {{Vec2(1, 2), 3.0, 0.5, 0.3},
          {Vec2(-1e6, 1e6), 1e-9, 1.0, -2.0},
          {Vec2(0, 0), 1.0, 1e-9, kPi / 2},
          {Vec2(5, 5), 1e20, 1e19, 1.0}};
}

template <class S>
class CurvedOutline : public ::testing::Test {};
using Kinds = ::testing::Types<ConvexPolygon, Capsule>;
TYPED_TEST_SUITE(CurvedOutline, Kinds);

TYPED_TEST(CurvedOutline, SupportMaximisesTheDirection) {
  for (const TypeParam& s : posed_shapes<TypeParam>()) {
    const std::vector<Sample> outline = samples(s);
    const double size = (aabb(s).max - aabb(s).min).norm();
    for (int k = 0; k < 360; ++k) {
      const Vec2 d(std::cos(k * kPi / 180 + 0.01), std::sin(k * kPi / 180 + 0.01));
      const Vec2 p = support(s, 3 * d);
      double best = -std::numeric_limits<double>::infinity();
      for (const Sample& q : outline) best = std::max(best, (q.point - s.center).dot(d));
      const double reached = (p - s.center).dot(d);
      EXPECT_GE(reached, best - 1e-14 * size) << k;
      EXPECT_LE(reached, best + 1e-3 * size) << k;  // the samples' spacing on an arc
    }
  }
}

// A step along the outward normal from a point of the outline leaves the shape; a step back, shorter
// than the rounding radius, stays in. Every point of the outline lies in the box.
TYPED_TEST(CurvedOutline, ContainmentSeparatesInsideFromOutside) {
  for (const TypeParam& s : posed_shapes<TypeParam>()) {
    const Aabb box = aabb(s);
    const double size = (box.max - box.min).norm();
    const double step = std::min(1e-7 * size, rounding_radius(s) / 2);
    for (const Sample& q : samples(s)) {
      EXPECT_FALSE(contains(s, q.point + step * q.normal)) << q.point.transpose();
      EXPECT_TRUE(contains(s, q.point - step * q.normal)) << q.point.transpose();
      EXPECT_TRUE(box.min.x() <= q.point.x() && q.point.x() <= box.max.x() && box.min.y() <= q.point.y() &&
                  q.point.y() <= box.max.y());
    }
  }
}

TYPED_TEST(CurvedOutline, AabbIsTight) {
  for (const TypeParam& s : posed_shapes<TypeParam>()) {
    const Aabb box = aabb(s);
    const double size = (box.max - box.min).norm();
    // The support points along the axes are the box's sides.
    EXPECT_NEAR(support(s, Vec2(1, 0)).x(), box.max.x(), 1e-14 * (size + s.center.norm()));
    EXPECT_NEAR(support(s, Vec2(-1, 0)).x(), box.min.x(), 1e-14 * (size + s.center.norm()));
    EXPECT_NEAR(support(s, Vec2(0, 1)).y(), box.max.y(), 1e-14 * (size + s.center.norm()));
    EXPECT_NEAR(support(s, Vec2(0, -1)).y(), box.min.y(), 1e-14 * (size + s.center.norm()));
  }
}

// Every query of query.h on the pairs with a polygon, a capsule or a segment: the same result bit
// for bit with the pair swapped (a contact as Contact::swapped() turns it), the distance 0 exactly when
// they overlap, the contact's separation the distance when apart.
TEST(PolygonCapsuleQueries, SymmetricAndConsistent) {
  std::mt19937_64 rng(11);
  const tool::Uniform unit(0.0, 1.0);
  const std::vector<Vec2> kite = {{-1, -0.5}, {3, -0.25}, {2.5, 1.5}, {0.25, 2}, {-0.75, 1}};
  const auto random_shape = [&](int kind) -> Shape {
    const double y = 4 * unit(rng) - 2;
    const Vec2 c(4 * unit(rng) - 2, y);
    const double angle = 7 * unit(rng);
    switch (kind) {
      case 0: {
        const double height = 0.2 + unit(rng);
        return Rect{c, Vec2(0.5 + unit(rng), height), angle};
      }
      case 1:
        return Circle{c, 0.3 + unit(rng)};
      case 2:
        return Ellipse{c, 0.3 + 2 * unit(rng), 0.2 + unit(rng), angle};
      case 3:
        return Capsule{c, 0.2 + unit(rng), 0.1 + unit(rng), angle};
      case 6: {
        const double dy = 4 * unit(rng) - 2;
        return Segment::between(c, c + Vec2(4 * unit(rng) - 2, dy));
      }
      default:
        return ConvexPolygon::of(kite, kind == 4 ? 0.0 : 0.2).at(c, angle);
    }
  };
  int apart = 0, overlapping = 0;
  for (int k = 0; k < 4000; ++k) {
    const int ka = 3 + k % 4, kb = (k / 4) % 6;
    const Shape a = random_shape(ka), b = random_shape(kb);
    const bool hit = overlaps(a, b);
    EXPECT_EQ(hit, overlaps(b, a));
    const DistanceResult d = distance(a, b), back = distance(b, a);
    EXPECT_EQ(d.distance, back.distance);
    EXPECT_EQ(d.point_a, back.point_b);
    EXPECT_EQ(d.overlapping, hit);
    EXPECT_EQ(d.distance == 0, hit);
    const Contact c = contact(a, b), r = contact(b, a);
    testing::expect_same_contact(c, r.swapped(), "swapped");
    if (!hit) EXPECT_NEAR(c.separation, d.distance, 1e-14);
    if (hit) EXPECT_LE(c.separation, 1e-14);
    (hit ? overlapping : apart)++;
    EXPECT_THROW(boundary_distance(a, b), UnsupportedPair);
  }
  EXPECT_GT(apart, 500);
  EXPECT_GT(overlapping, 500);
}

// A circle whose centre lies on a capsule's axis: both of the segment's faces measure 0 there, which
// says nothing of whether the centre lies over the segment or beyond an end. Binary fractions, so
// that every answer is exact.
TEST(PolygonCapsuleQueries, CircleOnTheCapsuleAxis) {
  const Capsule capsule{Vec2(-7.875, -8), 0.1875, 1.5625, 0.0};
  for (const double side : {1.0, -1.0}) {
    const Circle beyond{Vec2(-7.875 + side * 11.3125, -8), 8};
    const Contact c = contact(Shape(capsule), Shape(beyond));
    EXPECT_EQ(c.separation, 1.5625);
    EXPECT_EQ(c.normal, Vec2(side, 0));
    EXPECT_EQ(c.point_a, Vec2(-7.875 + side * 1.75, -8));
    EXPECT_EQ(c.point_b, Vec2(-7.875 + side * 3.3125, -8));
    EXPECT_EQ(distance(Shape(capsule), Shape(beyond)).distance, 1.5625);
  }
  const Circle over{Vec2(-7.75, -8), 8};  // its centre on the segment
  EXPECT_EQ(contact(Shape(capsule), Shape(over)).separation, -9.5625);
}

// A polygon whose outline lies off its own origin, that origin deep inside an ellipse: the disc
// test's tangent line stands for an ellipse seen from outside, and must not call the pair apart.
// The outline lies inside the ellipse, so that every test must find them overlapping, the batch too.
TEST(PolygonCapsuleQueries, OriginOffTheOutlineInsideAnEllipse) {
  const ConvexPolygon p = ConvexPolygon::of(std::vector<Vec2>{{10, 0}, {11, 0}, {10, 1}}).at(Vec2(1, 0));
  const Ellipse e{Vec2(0, 0), 100, 50, 0};
  EXPECT_TRUE(overlaps(p, e));
  EXPECT_TRUE(distance(p, e).overlapping);
  const std::vector<ConvexPolygon> polygons{p};
  const std::vector<Ellipse> ellipses{e};
  const std::vector<Orientation> unturned{Orientation{}};
  std::vector<std::uint8_t> out(1, 0);
  overlap_polygon_ellipse(polygons, unturned, ellipses, unturned, out);
  EXPECT_EQ(out[0], 1);
}

TEST(PolygonCapsuleQueries, RayCasts) {
  const Vec2 right(1, 0);
  // A unit square's left face at x = -1: from x = -3 the ray enters at 2, normal -x.
  const auto square = ray_cast(ConvexPolygon::box(1, 1), Vec2(-3, 0.5), right, 10);
  ASSERT_TRUE(square);
  EXPECT_EQ(square->distance, 2.0);
  EXPECT_EQ(square->normal, Vec2(-1, 0));
  // Rounded by 0.5, the face moves out to -1.5; along y = 1.25 the ray meets the corner's arc,
  // centred on (-1, 1): x = -1 - sqrt(0.25 - 0.0625).
  const ConvexPolygon rounded = ConvexPolygon::box(1, 1, 0.5);
  EXPECT_EQ(ray_cast(rounded, Vec2(-3, 0.5), right, 10)->distance, 1.5);
  const auto arc = ray_cast(rounded, Vec2(-3, 1.25), right, 10);
  ASSERT_TRUE(arc);
  EXPECT_NEAR(arc->distance, 2 - std::sqrt(0.1875), 1e-15);
  EXPECT_NEAR(arc->normal.x(), -std::sqrt(0.1875) / 0.5, 1e-15);
  // A capsule along x, half length 2, radius 1: end on, the ray meets the cap at x = 3.
  const Capsule capsule{Vec2(0, 0), 2.0, 1.0, 0.0};
  EXPECT_EQ(ray_cast(capsule, Vec2(10, 0), Vec2(-1, 0), 20)->distance, 7.0);
  EXPECT_EQ(ray_cast(capsule, Vec2(0.5, 5), Vec2(0, -1), 20)->distance, 4.0);
  EXPECT_FALSE(ray_cast(capsule, Vec2(0.5, 5), Vec2(0, -1), 3.5));
  EXPECT_FALSE(ray_cast(capsule, Vec2(10, 1.5), Vec2(-1, 0), 20));
  EXPECT_EQ(ray_cast(capsule, Vec2(0, 0), right, 1)->distance, 0.0);  // starts inside
  // A triangle seen along its face: missed beside it, hit through its vertex.
  const ConvexPolygon triangle = ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {2, 0}, {0, 2}});
  EXPECT_FALSE(ray_cast(triangle, Vec2(-1, -0.5), right, 10));
  EXPECT_EQ(ray_cast(triangle, Vec2(-1, 1), right, 10)->distance, 1.0);
}

// A capsule sliding, then also turning, into a box: the translation's exact time, and a turning step
// that stops at contact, never beyond.
TEST(PolygonCapsuleQueries, TimeOfImpact) {
  const Shape box = ConvexPolygon::box(1, 1);
  const Shape capsule = Capsule{Vec2(-5, 0), 1.0, 0.5, 0.0};
  const TimeOfImpact slide = time_of_impact(capsule, {Vec2(5, 0), 0.0}, box, {});
  ASSERT_EQ(slide.status, ToiStatus::hit);
  EXPECT_NEAR(slide.t, 2.5 / 5, 1e-9);
  for (const double spin : {1.0, 3.0, -6.0}) {
    const TimeOfImpact turn = time_of_impact(capsule, {Vec2(5, 0), spin}, box, {Vec2(0, 0), -spin / 2});
    ASSERT_EQ(turn.status, ToiStatus::hit) << spin;
    const Contact at =
        contact(at_time(capsule, {Vec2(5, 0), spin}, turn.t), at_time(box, {Vec2(0, 0), -spin / 2}, turn.t));
    EXPECT_GT(at.separation, 0.0) << spin;
    EXPECT_LE(at.separation, 1e-9 * 4) << spin;
  }
}

// A polygon whose outline reaches farther towards the moving shape than away from it, as B: a spike
// at x = 7 in front of a flat back at x = 11. Every shape A reaches x = 1 and moves 20 along x, so
// that it first touches the spike at t = 6 / 20; the far side's support would put it at 8 / 20.
TEST(PolygonCapsuleQueries, TimeOfImpactAgainstTheSideFacingTheMover) {
  const Shape spike = ConvexPolygon::of(std::vector<Vec2>{{-3, 0}, {1, -1}, {1, 1}}).at(Vec2(10, 0));
  for (const Shape& a : {Shape(Capsule{Vec2(0, 0), 0.5, 0.5, 0.0}), Shape(Ellipse{Vec2(0, 0), 1.0, 0.5, 0.0}),
                         Shape(Rect{Vec2(0, 0), Vec2(1, 0.5), 0.0}), Shape(ConvexPolygon::box(1, 0.5))}) {
    const TimeOfImpact r = time_of_impact(a, {Vec2(20, 0), 0.0}, spike, {});
    ASSERT_EQ(r.status, ToiStatus::hit) << a.index();
    EXPECT_NEAR(r.t, 0.3, 1e-9) << a.index();
    const TimeOfImpact back = time_of_impact(spike, {}, a, {Vec2(20, 0), 0.0});
    EXPECT_NEAR(back.t, 0.3, 1e-9) << a.index();
  }
}

// Polygons and capsules in a World: their pairs found, their contacts made, their rays and shape
// queries answered.
TEST(PolygonCapsuleQueries, InAWorld) {
  World world({.contacts = true, .threads = 1});
  const BodyId floor = world.add(Capsule{Vec2(0, 0), 5.0, 0.5, 0.0}, {.is_static = true});
  const BodyId crate = world.add(ConvexPolygon::box(0.5, 0.5).at(Vec2(1, 0.99)));
  const BodyId wedge = world.add(ConvexPolygon::regular(3, 0.5).at(Vec2(-3, 3)));
  world.update();
  ASSERT_EQ(world.overlapping().size(), 1u);
  EXPECT_EQ(world.overlapping()[0].a == floor ? world.overlapping()[0].b : world.overlapping()[0].a, crate);
  ASSERT_EQ(world.contacts().size(), 1u);
  EXPECT_NEAR(std::abs(world.contacts()[0].contact.separation), 0.01, 1e-12);
  EXPECT_EQ(world.contacts()[0].contact.manifold_size, 2);
  const auto ray = world.ray_cast(Vec2(-3, 10), Vec2(0, -1), 20);
  ASSERT_TRUE(ray);
  EXPECT_EQ(ray->body, wedge);
  std::vector<BodyId> found;
  world.overlapping(Shape(Capsule{Vec2(1, 2), 0.5, 0.6, 1.5}), [&](const BodyShape& s) {
    found.push_back(s.body);
    return true;
  });
  EXPECT_EQ(found, std::vector<BodyId>{crate});
}

}  // namespace
}  // namespace collide2d
