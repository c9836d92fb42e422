// Segments: what their maker and validation refuse, their points, boxes, support and containment,
// and every query against each kind on constructions whose answers are binary fractions (exact in
// double), ray casts, a bullet's time of impact, and the World's static-only rule and its queries.
// (test_polygon_capsule.cpp checks their queries' symmetry and consistency on random pairs.)
#include <collide2d/query.h>
#include <collide2d/ray_cast.h>
#include <collide2d/shapes.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>

#include <gtest/gtest.h>

#include "refusals.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide2d {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

using testing::expect_refused;

TEST(SegmentShape, RefusesBadFields) {
  const auto refused = [](const Segment& s, const std::string& words) {
    expect_refused<InvalidShape>([&] { validate(s); }, words);
    expect_refused<InvalidShape>([&] { overlaps(s, Circle{}); }, words);
  };
  refused(Segment::between(Vec2(1, 2), Vec2(1, 2)), "segment length must be positive (its two points are one) (got 0)");
  refused(Segment::between(Vec2(kNan, 0), Vec2(1, 0)), "segment x1 must be finite (got nan)");
  refused(Segment{Vec2(0, 3e50), Vec2(1, 0), 0.0}, "segment y1 is beyond the supported range of +-1e50");
  refused(Segment{Vec2(0, 0), Vec2(2e50, 0), 0.0}, "segment end x is beyond the supported range of +-1e50");
  refused(Segment::between(Vec2(0, 0), Vec2(1e-51, 0)), "segment length is outside the supported range 1e-50 to 1e50");
  refused(Segment{Vec2(0, 0), Vec2(1, 0), kNan}, "segment angle must be finite (got nan)");
  validate(Segment::between(Vec2(-1e50, 0), Vec2(-1e50 + 1e35, 1e-15)));
}

TEST(SegmentShape, PointsBoxSupportAndContainment) {
  const Segment s = Segment::between(Vec2(-1.5, 2.25), Vec2(3.75, -0.5));
  EXPECT_EQ(s.point1(), Vec2(-1.5, 2.25));
  EXPECT_EQ(s.point2(), Vec2(3.75, -0.5));
  EXPECT_EQ(shape_name(s), std::string("segment"));
  EXPECT_EQ(center_of(s), s.point1());
  EXPECT_EQ(angle_of(s), 0.0);
  EXPECT_EQ(reach_of(s), std::hypot(5.25, 2.75));
  const Aabb box = aabb(s);
  EXPECT_TRUE(encloses(box, Aabb{Vec2(-1.5, -0.5), Vec2(3.75, 2.25)}));
  EXPECT_LE((box.max - box.min - Vec2(5.25, 2.75)).cwiseAbs().maxCoeff(), 64 * kU * 4);
  EXPECT_EQ(support(s, Vec2(1, 0)), s.point2());
  EXPECT_EQ(support(s, Vec2(-1, 0.5)), s.point1());
  // On the segment (its midpoint, exact here), beside it, and on its line past an end.
  EXPECT_TRUE(contains(s, Vec2(1.125, 0.875)));
  EXPECT_TRUE(contains(s, s.point2()));
  EXPECT_FALSE(contains(s, Vec2(1.125, 0.875 + 1e-12)));
  EXPECT_FALSE(contains(s, Vec2(9.0, -3.25)));
  // Turned about its first point: a quarter turn takes its end (2, 0) to (0, 2), to rounding.
  const Segment turned{Vec2(1, 1), Vec2(2, 0), std::acos(-1.0) / 2};
  EXPECT_NEAR((turned.point2() - Vec2(1, 3)).norm(), 0.0, 4 * kU * 3);
}

// The segment from (0, 0) to (4, 0) against each kind, placed so that the answer is known exactly.
const Segment kFloor = Segment::between(Vec2(0, 0), Vec2(4, 0));

void expect_contact(const Shape& b, double separation, const Vec2& normal, int points) {
  const Contact c = contact(Shape(kFloor), b);
  EXPECT_NEAR(c.separation, separation, 8 * kU * 8) << shape_name(b);
  EXPECT_NEAR((c.normal - normal).norm(), 0.0, 8 * kU) << shape_name(b);
  EXPECT_EQ(c.manifold_size, points) << shape_name(b);
  const DistanceResult d = distance(Shape(kFloor), b);
  EXPECT_EQ(d.overlapping, separation <= 0.0) << shape_name(b);
  EXPECT_EQ(overlaps(Shape(kFloor), b), separation <= 0.0) << shape_name(b);
  if (separation > 0) EXPECT_NEAR(d.distance, separation, 8 * kU * 8) << shape_name(b);
}

TEST(SegmentQueries, KnownAnswers) {
  // A circle above the middle, and one beyond the second point on the segment's line.
  expect_contact(Circle{Vec2(2, 3), 1}, 2.0, Vec2(0, 1), 1);
  expect_contact(Circle{Vec2(7, 0), 1}, 2.0, Vec2(1, 0), 1);
  // A box across the segment: out by 0.25 upwards (0.75 down).
  expect_contact(Rect{Vec2(2, 0.25), Vec2(1, 0.5), 0.0}, -0.25, Vec2(0, 1), 2);
  // A capsule lying on the segment along x = 1 ... 3, and lifted off it by 2^-20.
  expect_contact(Capsule{Vec2(2, 1), 1.0, 1.0, 0.0}, 0.0, Vec2(0, 1), 2);
  expect_contact(Capsule{Vec2(2, 1 + 0x1p-20), 1.0, 1.0, 0.0}, 0x1p-20, Vec2(0, 1), 2);
  // A triangle's tip on the segment.
  expect_contact(ConvexPolygon::of(std::vector<Vec2>{{0, 0}, {1, 2}, {-1, 2}}).at(Vec2(1.5, 0)), 0.0, Vec2(0, 1), 1);
  // An ellipse of aspect 1e4 whose tip touches the second point, and one 2^-30 beyond it.
  expect_contact(Ellipse{Vec2(5, 0), 1.0, 1e-4, 0.0}, 0.0, Vec2(1, 0), 1);
  expect_contact(Ellipse{Vec2(5 + 0x1p-30, 0), 1.0, 1e-4, 0.0}, 0x1p-30, Vec2(1, 0), 1);
  // Far from the origin the segment keeps its own scale: the same circle above it.
  const Vec2 far(0x1p30, -0x1p30);
  const Segment moved = Segment::between(far, far + Vec2(4, 0));
  const DistanceResult d = distance(Shape(moved), Shape(Circle{far + Vec2(2, 3), 1}));
  EXPECT_NEAR(d.distance, 2.0, 8 * kU * 0x1p31);
  EXPECT_THROW(boundary_distance(Shape(kFloor), Shape(Circle{})), UnsupportedPair);
}

TEST(SegmentQueries, RayCasts) {
  // Up and down through the segment: the face the ray crosses gives the normal.
  const auto up = ray_cast(kFloor, Vec2(1, -3), Vec2(0, 1), 10);
  ASSERT_TRUE(up);
  EXPECT_EQ(up->distance, 3.0);
  EXPECT_EQ(up->point, Vec2(1, 0));
  EXPECT_EQ(up->normal, Vec2(0, -1));
  const auto down = ray_cast(kFloor, Vec2(2, 2), Vec2(0.6, -0.8), 10);
  ASSERT_TRUE(down);
  EXPECT_NEAR(down->distance, 2.5, 4 * kU * 4);
  EXPECT_EQ(down->normal, Vec2(0, 1));
  EXPECT_FALSE(ray_cast(kFloor, Vec2(1, -3), Vec2(0, 1), 2.5));  // too short
  EXPECT_FALSE(ray_cast(kFloor, Vec2(5, -3), Vec2(0, 1), 10));   // beside the end
  EXPECT_FALSE(ray_cast(kFloor, Vec2(1, -3), Vec2(0, -1), 10));  // away
  EXPECT_FALSE(ray_cast(kFloor, Vec2(-2, 0), Vec2(1, 0), 10));   // along its line: no crossing
  // Through its end point exactly, and from a point on it.
  EXPECT_EQ(ray_cast(kFloor, Vec2(4, 1), Vec2(0, -1), 10)->distance, 1.0);
  EXPECT_EQ(ray_cast(kFloor, Vec2(2, 0), Vec2(0, 1), 10)->distance, 0.0);
  // A vertical segment, crossed from the left.
  const auto side = ray_cast(Segment::between(Vec2(0, 0), Vec2(0, 4)), Vec2(-3, 1), Vec2(1, 0), 10);
  ASSERT_TRUE(side);
  EXPECT_EQ(side->distance, 3.0);
  EXPECT_EQ(side->normal, Vec2(-1, 0));
}

// A bullet at 4e4 of its radius per step stops at the exact time of impact, never through.
TEST(SegmentQueries, BulletStopsAtTheSegment) {
  const Shape bullet = Circle{Vec2(2, 10000.25), 0.25};
  const TimeOfImpact hit = time_of_impact(bullet, {Vec2(0, -20000), 0.0}, Shape(kFloor), {});
  ASSERT_EQ(hit.status, ToiStatus::hit);
  EXPECT_NEAR(hit.t, 0.5, 1e-9);
  EXPECT_GE(contact(at_time(bullet, {Vec2(0, -20000), 0.0}, hit.t), Shape(kFloor)).separation, 0.0);
  // Turning and sliding, a capsule meets the segment without passing it.
  const Shape capsule = Capsule{Vec2(2, 3), 1.0, 0.25, 0.0};
  const Motion spin{Vec2(0, -4), 5.0};
  const TimeOfImpact turn = time_of_impact(capsule, spin, Shape(kFloor), {});
  ASSERT_EQ(turn.status, ToiStatus::hit);
  const double gap = contact(at_time(capsule, spin, turn.t), Shape(kFloor)).separation;
  EXPECT_GT(gap, 0.0);
  EXPECT_LE(gap, 1e-8);
}

// Segments are level geometry: static bodies only. A box resting on a segment floor, a sight line
// across the level, a ray down onto the floor.
TEST(SegmentQueries, InAWorld) {
  World world({.contacts = true, .threads = 1});
  const Segment floor_shape = Segment::between(Vec2(-8, 0), Vec2(8, 0));
  expect_refused<std::invalid_argument>([&] { world.add(floor_shape); }, "add: a segment is level geometry");
  const BodyId floor = world.add(floor_shape, {.is_static = true});
  const BodyId crate = world.add(Rect{Vec2(1, 0.5 - 0x1p-10), Vec2(0.5, 0.5), 0.0});
  const BodyId ball = world.add(Circle{Vec2(-4, 3), 0.5});
  expect_refused<std::invalid_argument>([&] { world.set_static(floor, false); }, "set_static: a segment");
  expect_refused<std::invalid_argument>([&] { world.add_shape(crate, {.shape = floor_shape}); },
                                        "add_shape: a segment");
  world.update();
  ASSERT_EQ(world.overlapping().size(), 1u);
  ASSERT_EQ(world.contacts().size(), 1u);
  const Contact& c = world.contacts()[0].contact;
  EXPECT_NEAR(c.separation, -0x1p-10, 8 * kU * 16);
  EXPECT_EQ(c.manifold_size, 2);
  const auto ray = world.ray_cast(Vec2(6, 5), Vec2(0, -1), 20);
  ASSERT_TRUE(ray);
  EXPECT_EQ(ray->body, floor);
  EXPECT_EQ(ray->distance, 5.0);
  // A sight line through the crate and over the floor, and one down through the ball and the floor.
  const auto seen = [&](const Segment& line) {
    std::vector<BodyId> found;
    world.overlapping(Shape(line), [&](const BodyShape& s) {
      found.push_back(s.body);
      return true;
    });
    std::sort(found.begin(), found.end());
    return found;
  };
  EXPECT_EQ(seen(Segment::between(Vec2(-6, 0.25), Vec2(6, 0.25))), std::vector<BodyId>{crate});
  std::vector<BodyId> both{floor, ball};
  std::sort(both.begin(), both.end());
  EXPECT_EQ(seen(Segment::between(Vec2(-4, 5), Vec2(-4, -1))), both);
}

}  // namespace
}  // namespace collide2d
