// Chains: what chain_segments() and the World refuse, the segments and ghosts a chain makes, the
// one-sided, shared-vertex and smooth rules on constructions whose answers are known exactly (binary
// fractions, or the square roots of a few), one-sided ray casts, and bodies of every moving kind
// sliding along long chains in a World without catching on a vertex.
#include <collide2d/chain.h>
#include <collide2d/query.h>
#include <collide2d/ray_cast.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>

#include <gtest/gtest.h>

#include "refusals.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide2d {
namespace {

using testing::expect_refused;

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

// A floor along the x axis, run from right to left so that it collides from above (y > 0):
// segment 0 from (2, 0) to (0, 0), segment 1 from (0, 0) to (-2, 0).
const std::vector<Vec2> kFloor{{3, 0}, {2, 0}, {0, 0}, {-2, 0}, {-3, 0}};
// The square island of half side 1, counter-clockwise: bottom, right, top, left.
const std::vector<Vec2> kIsland{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

TEST(ChainShape, RefusesBadInput) {
  const auto refused = [](std::vector<Vec2> points, bool loop, const std::string& words) {
    expect_refused<InvalidShape>([&] { chain_segments(points, loop); }, words);
  };
  refused({{0, 0}, {1, 0}}, true, "a chain loop needs at least 3 points (got 2)");
  refused({{0, 0}, {1, 0}, {2, 1}}, false,
          "an open chain needs at least 4 points, its first and last ghosts only (got 3)");
  refused({{0, 0}, {1, 0}, {kNan, 1}, {3, 0}}, false, "chain point 2 x must be finite (got nan)");
  refused({{0, 0}, {1, 0}, {1, 0}, {3, 0}}, false, "chain point 2 repeats point 1");
  refused({{0, 0}, {1, 0}, {1, 1}, {0, 0}}, true, "chain point 0 repeats point 3");
  refused({{0, 0}, {1, 0}, {2, 0}, {1.5, 0}, {3, 0}}, false,
          "chain segment from point 1: chain segment folds back on itself at point2");
  expect_refused<InvalidShape>([] { validate(ChainSegment::of(Vec2(0, 0), Vec2(0, 0), Vec2(1, 0), Vec2(2, 0))); },
                               "chain segment ghost1 must differ from point1");
  const ChainSegment floor = chain_segments(kFloor, false)[0];
  expect_refused<UnsupportedPair>([&] { contact(floor, Segment::between(Vec2(0, 1), Vec2(1, 1))); },
                                  "a chain segment does not pair with a segment");
  expect_refused<InvalidShape>([&] { contact(floor, Circle{Vec2(0, 1), -1.0}); }, "circle radius must be positive");

  World world;
  expect_refused<InvalidShape>(
      [&] {
        world.add_chain(std::vector<Vec2>{{0, 0}, {1, 0}}, false);
      },
      "an open chain needs at least 4 points");
  EXPECT_EQ(world.size(), 0u);
  const BodyId chain = world.add_chain(kFloor, false);
  const ShapeId first = world.shapes(chain)[0];
  expect_refused<std::invalid_argument>([&] { world.remove_shape(first); }, "is a chain's segment");
  expect_refused<std::invalid_argument>([&] { world.set_local_shape(first, Circle{}); }, "is a chain's segment");
  EXPECT_EQ(world.shapes(chain).size(), 2u);
  // A chain's body is static whatever its definition holds; its user id and filter are the
  // definition's.
  const Filter layer{.category = 4, .mask = 5, .group = -2};
  const BodyId named = world.add_chain(kFloor, false, {.user_id = 7, .filter = layer});
  EXPECT_TRUE(world.is_static(chain) && world.is_static(named));
  EXPECT_FALSE(world.is_sensor(named));
  EXPECT_EQ(world.user_id(named), 7u);
  for (const ShapeId s : world.shapes(named)) EXPECT_EQ(world.filter(s), layer);
}

TEST(ChainShape, SegmentsAndGhosts) {
  const std::vector<ChainSegment> open = chain_segments(kFloor, false);
  ASSERT_EQ(open.size(), 2u);
  EXPECT_EQ(open[0].segment.point1(), Vec2(2, 0));
  EXPECT_EQ(open[0].segment.point2(), Vec2(0, 0));
  EXPECT_EQ(open[0].ghost1, Vec2(1, 0));   // (3, 0) from (2, 0)
  EXPECT_EQ(open[0].ghost2, Vec2(-4, 0));  // (-2, 0)
  EXPECT_EQ(open[1].segment.point1(), Vec2(0, 0));
  EXPECT_EQ(open[1].ghost2, Vec2(-3, 0));
  const std::vector<ChainSegment> loop = chain_segments(kIsland, true);
  ASSERT_EQ(loop.size(), 4u);
  EXPECT_EQ(loop[0].segment.point1() + loop[0].ghost1, kIsland[3]);
  EXPECT_EQ(loop[3].segment.point2(), kIsland[0]);
  EXPECT_EQ(loop[3].segment.point1() + loop[3].ghost2, kIsland[1]);

  // A World's chain keeps the ghosts in each segment's frame as the body turns.
  World world;
  const BodyId body = world.add_chain(kIsland, true);
  world.set_pose(body, Vec2(5, 0), std::acos(-1.0) / 2);
  const auto top = world.chain_segment(world.shapes(body)[2]);
  ASSERT_TRUE(top);
  EXPECT_EQ(top->ghost1, loop[2].ghost1);
  EXPECT_NEAR((top->segment.point2() - Vec2(4, -1)).norm(), 0.0, 8 * kU * 5);
  const BodyId ball = world.add(Circle{});
  EXPECT_FALSE(world.chain_segment(world.shapes(ball)[0]));
}

TEST(ChainContact, OneSided) {
  const ChainSegment s = chain_segments(kFloor, false)[0];
  const Contact above = contact(s, Circle{Vec2(1, 0.25), 0.5});
  ASSERT_FALSE(above.empty());
  EXPECT_EQ(above.separation, -0.25);
  EXPECT_EQ(above.normal, Vec2(0, 1));
  EXPECT_EQ(above.point_a, Vec2(1, 0));
  EXPECT_EQ(above.point_b, Vec2(1, -0.25));
  const Contact box = contact(s, Rect{Vec2(1, 0.375), Vec2(0.5, 0.5), 0.0});
  EXPECT_EQ(box.separation, -0.125);
  EXPECT_EQ(box.normal, Vec2(0, 1));
  EXPECT_EQ(box.manifold_size, 2);
  // Below the floor the segment's geometry still overlaps the shapes; the chain gives no contact.
  for (const Shape& below : {Shape(Circle{Vec2(1, -0.25), 0.5}), Shape(Rect{Vec2(1, -0.375), Vec2(0.5, 0.5), 0.0}),
                             Shape(Ellipse{Vec2(1, -0.25), 1.0, 0.5, 0.5})}) {
    EXPECT_TRUE(overlaps(s.segment, below));
    EXPECT_FALSE(in_front(s, below));
    EXPECT_TRUE(contact(s, below).empty());
  }
}

// A box sunk 1/64 into the floor slides across the vertex at x = 0, upright and tilted. The segment
// alone catches it (its way out is sideways where the box has only just crossed the vertex); the
// chain's segments give the floor's normal and, between them, the box's lowest corner's depth.
TEST(ChainContact, FlatVertexNeverCatches) {
  const std::vector<ChainSegment> floor = chain_segments(kFloor, false);
  const Rect crossing{Vec2(0.5 - 0x1p-7, 0.5 - 0x1p-6), Vec2(0.5, 0.5), 0.0};
  const Contact snag = contact(floor[1].segment, crossing);
  EXPECT_EQ(std::abs(snag.normal.x()), 1.0) << "the plain segment's way out is sideways";
  for (const double tilt : {0.0, 1e-3, -1e-3, 0.1, -0.1}) {
    for (double x = -1.0; x <= 1.0; x += 0x1p-5) {
      const Rect box{Vec2(x, 0.5 - 0x1p-6), Vec2(0.5, 0.5), tilt};
      double deepest = std::numeric_limits<double>::infinity();
      for (const ChainSegment& s : floor) {
        const Contact c = contact(s, box);
        if (c.empty()) continue;
        EXPECT_NEAR((c.normal - Vec2(0, 1)).norm(), 0.0, 64 * kU) << "x " << x << " tilt " << tilt;
        deepest = std::min(deepest, c.separation);
      }
      // The lowest corner, independently: the centre less the half extents turned, in long double.
      const long double t = tilt;
      const long double lowest = (0.5L - 0x1p-6L) - (0.5L * std::abs(std::sin(t)) + 0.5L * std::cos(t));
      EXPECT_NEAR(deepest, static_cast<double>(lowest), 16 * kU) << "x " << x << " tilt " << tilt;
    }
  }
}

// A circle resting over the seam of a straight floor lands on it wherever the floor lies: far from
// the origin the seam's vertex is rounded in the world, and the centre, nudged by an ulp either way,
// sits over one segment or the other, or just beyond both ends; one of them still reports the floor.
TEST(ChainContact, CircleOverAFarSeamLands) {
  for (const double far : {0.0, 1e3, 1e5}) {
    for (const double theta : {0.0, 0.3, -1.1}) {
      const Vec2 dir(-std::cos(theta), -std::sin(theta));  // from right to left: the floor faces up
      const Vec2 origin(far, 0.5 * far), up(dir.y(), -dir.x());
      std::vector<Vec2> points;
      for (int k = 0; k < 5; ++k) points.push_back(origin + (0.75 * k) * dir);
      const std::vector<ChainSegment> both = chain_segments(points, false);  // meeting at points[2]
      ASSERT_EQ(both.size(), 2u);
      for (const double height : {0.1, 0.3}) {
        for (const Vec2 nudge : {Vec2(0, 0), Vec2(1, 0), Vec2(-1, 0), Vec2(0, 1), Vec2(0, -1), Vec2(1, 1)}) {
          Vec2 centre = points[2] + height * up;
          centre.x() = std::nextafter(centre.x(), centre.x() + nudge.x());
          centre.y() = std::nextafter(centre.y(), centre.y() + nudge.y());
          const Circle ball{centre, 0.25};
          double deepest = std::numeric_limits<double>::infinity();
          for (const ChainSegment& s : both) {
            const Contact c = contact(s, ball);
            if (c.empty()) continue;
            EXPECT_LT((c.normal - up).norm(), 1e-9) << "far " << far << " theta " << theta;
            deepest = std::min(deepest, c.separation);
          }
          EXPECT_NEAR(deepest, height - 0.25, 1e-9) << "far " << far << " theta " << theta << " height " << height;
        }
      }
    }
  }
}

// The island's top-right corner is convex: the top and the right split the space around it along
// the bisector, and the normal there is the vertex's, in the cone between the two faces' normals.
TEST(ChainContact, ConvexCornerSplitsBetweenFaces) {
  const std::vector<ChainSegment> island = chain_segments(kIsland, true);
  const ChainSegment &right = island[1], &top = island[2];
  const Circle beside{Vec2(1.5, 1.25), 0.5};
  EXPECT_TRUE(contact(top, beside).empty()) << "nearer the right face's line: the right owns it";
  const Contact c = contact(right, beside);
  ASSERT_FALSE(c.empty());
  const long double d = std::sqrt(0.3125L);
  EXPECT_NEAR(c.separation, static_cast<double>(d - 0.5L), 4 * kU);
  EXPECT_NEAR(c.normal.x(), static_cast<double>(0.5L / d), 4 * kU);
  EXPECT_NEAR(c.normal.y(), static_cast<double>(0.25L / d), 4 * kU);
  const Circle over{Vec2(1.25, 1.5), 0.5};
  EXPECT_TRUE(contact(right, over).empty());
  EXPECT_NEAR(contact(top, over).normal.x(), static_cast<double>(0.25L / d), 4 * kU);
  // On the bisector both report the corner.
  const Circle diagonal{Vec2(1.25, 1.25), 0.5};
  for (const ChainSegment& s : {right, top}) {
    const Contact both = contact(s, diagonal);
    ASSERT_FALSE(both.empty());
    EXPECT_NEAR(both.normal.x(), std::sqrt(0.5), 2 * kU);
    EXPECT_NEAR(both.normal.y(), std::sqrt(0.5), 2 * kU);
  }
}

// A valley: the vertex at the origin is concave, and a ball resting in it touches both faces,
// each with its own normal.
TEST(ChainContact, ConcaveVertexKeepsBothFaces) {
  const std::vector<ChainSegment> valley =
      chain_segments(std::vector<Vec2>{{3, 3}, {2, 2}, {0, 0}, {-2, 2}, {-3, 3}}, false);
  const Circle ball{Vec2(0, 1), 0.75};
  const Vec2 normals[] = {Vec2(-1, 1) / std::sqrt(2.0), Vec2(1, 1) / std::sqrt(2.0)};
  for (int k = 0; k < 2; ++k) {
    const Contact c = contact(valley[k], ball);
    ASSERT_FALSE(c.empty());
    EXPECT_NEAR((c.normal - normals[k]).norm(), 0.0, 4 * kU);
    EXPECT_NEAR(c.separation, static_cast<double>(std::sqrt(0.5L) - 0.75L), 4 * kU);
  }
}

TEST(ChainRayCast, OnlyFromTheFront) {
  const ChainSegment s = chain_segments(kFloor, false)[0];
  const auto down = ray_cast(s, Vec2(1, 1), Vec2(0, -1), 5.0);
  ASSERT_TRUE(down);
  EXPECT_EQ(down->distance, 1.0);
  EXPECT_EQ(down->normal, Vec2(0, 1));
  EXPECT_TRUE(ray_cast(Shape(s.segment), Vec2(1, -1), Vec2(0, 1), 5.0)) << "the segment alone is hit from below";
  EXPECT_FALSE(ray_cast(s, Vec2(1, -1), Vec2(0, 1), 5.0));
}

// An open chain of `count` unit segments from the origin along `angle`, turning `bend` to the left
// (towards its solid side: a hill) at each vertex, each point the last plus a step (so that points
// in line carry their rounding), with a ghost at each end.
std::vector<Vec2> polyline(int count, double angle, double bend) {
  std::vector<Vec2> points{Vec2::Zero()};
  for (int k = 0; k < count + 2; ++k)
    points.push_back(points.back() + Vec2(std::cos(angle + k * bend), std::sin(angle + k * bend)));
  return points;
}

Vec2 right_of(const Vec2& d) { return Vec2(d.y(), -d.x()); }

// Whether n lies in the arc from `from` counter-clockwise to `to`, or within `slack` of it.
bool in_arc(const Vec2& from, const Vec2& n, const Vec2& to, double slack) {
  const auto cross = [](const Vec2& p, const Vec2& q) { return p.x() * q.y() - p.y() * q.x(); };
  return n.dot(from) > 0.0 && cross(from, n) >= -slack && cross(n, to) >= -slack;
}

// A body of each moving kind slides along the chain, 10,000 steps from segment 50 to segment 950,
// sunk 1/100 of its size into the chain and wobbling by 1e-4 rad about the chain's direction: at
// every step it touches, and every contact's normal lies in the arc of the normals of the touched
// segment and its neighbours (the segment's own where they are in line), never against the motion
// beyond that arc. A twin behind the chain, sunk as deep from the back, touches nothing.
void expect_smooth_slide(const std::vector<Vec2>& points, double bend, const Shape& local) {
  World world({.contacts = true, .threads = 1});
  const BodyId chain = world.add_chain(points, false);
  const std::vector<ShapeId> segments = world.shapes(chain);
  const Filter apart{.group = -1};
  const BodyId body = world.add(local, {.filter = apart});
  const BodyId twin = world.add(local, {.filter = apart});
  const auto direction = [&](int k) { return Vec2((points[k + 2] - points[k + 1]).normalized()); };
  const double size = reach_of(local);
  const double slack = 1e-12 + std::sin(bend);
  constexpr int kSteps = 10000;
  for (int step = 0; step < kSteps; ++step) {
    const double s = 50.0 + 900.0 * step / kSteps;
    const int k = static_cast<int>(s);
    const Vec2 e = direction(k), n = right_of(e);
    const Vec2 on = points[k + 1] + (s - k) * (points[k + 2] - points[k + 1]);
    const double angle = std::atan2(e.y(), e.x()) + 1e-4 * std::sin(0.1 * step);
    const Shape turned = placed(local, {Vec2::Zero(), angle}, Orientation::of(angle));
    const double below = -n.dot(support(turned, -n)), above = n.dot(support(turned, n));
    world.set_pose(body, on + (below - 0.01 * size) * n, angle);
    world.set_pose(twin, on - (above - 0.01 * size) * n, angle);
    world.update();
    int touching = 0;
    for (const BodyContact& c : world.contacts()) {
      ASSERT_TRUE(c.a == chain && c.b == body) << "step " << step << ": only the body above touches the chain";
      const int j = static_cast<int>(std::find(segments.begin(), segments.end(), c.shape_a) - segments.begin());
      ASSERT_GE(j, 1);
      ASSERT_LT(j + 1, static_cast<int>(segments.size()));
      const Vec2 normal = c.contact.normal;
      EXPECT_TRUE(in_arc(right_of(direction(j - 1)), normal, right_of(direction(j + 1)), 1e-12))
          << "step " << step << " segment " << j << " normal " << normal.transpose();
      EXPECT_GE(normal.dot(e), -slack) << "step " << step << " normal " << normal.transpose();
      touching += c.touching;
    }
    ASSERT_GT(touching, 0) << "step " << step << ": the body sunk into the chain touches it";
  }
}

const Shape kSliders[] = {Rect{Vec2::Zero(), Vec2(0.5, 0.25), 0.0}, Circle{Vec2::Zero(), 0.4},
                          Capsule{Vec2::Zero(), 0.5, 0.2, 0.0}, Ellipse{Vec2::Zero(), 0.6, 0.3, 0.0},
                          ConvexPolygon::regular(6, 0.5)};

TEST(ChainWorld, SlidesAlongSegmentsInLineWithoutCatching) {
  const std::vector<Vec2> points = polyline(1000, std::acos(-1.0) + 0.3, 0.0);
  for (const Shape& shape : kSliders) {
    SCOPED_TRACE(shape_name(shape));
    expect_smooth_slide(points, 0.0, shape);
  }
}

TEST(ChainWorld, SlidesOverAHillBendingAtEveryVertex) {
  const std::vector<Vec2> points = polyline(1000, std::acos(-1.0), 1e-3);
  for (const Shape& shape : kSliders) {
    SCOPED_TRACE(shape_name(shape));
    expect_smooth_slide(points, 1e-3, shape);
  }
}

// A bullet 1/32 across fired down at the floor at 1e4 times its size per step stops at the exact
// time of impact; fired up from below, it passes.
TEST(ChainWorld, BulletStopsOnlyFromTheFront) {
  World world({.threads = 1});
  const BodyId floor = world.add_chain(kFloor, false);
  const double radius = 0x1p-6, speed = 1e4 * 2 * radius;
  const BodyId down = world.add(Circle{Vec2(1, 0.5 * speed + radius), radius});
  const BodyId up = world.add(Circle{Vec2(-1, -0.5 * speed - radius), radius});
  world.set_continuous(down);
  world.set_continuous(up);
  world.move_by(down, Vec2(0, -speed));
  world.move_by(up, Vec2(0, speed));
  world.update();
  ASSERT_EQ(world.impacts().size(), 1u);
  const Impact& hit = world.impacts()[0];
  EXPECT_EQ(hit.a, floor);
  EXPECT_EQ(hit.b, down);
  EXPECT_NEAR(hit.t, 0.5, 1e-9);
  EXPECT_NEAR((hit.normal - Vec2(0, 1)).norm(), 0.0, 1e-12);
}

// A chain blocks sight from either side: a line of sight through it finds its body, one above it
// does not; a ray from above hits it, one from below passes.
TEST(ChainWorld, BlocksSightFromEitherSide) {
  World world({.threads = 1});
  const BodyId floor = world.add_chain(kFloor, false);
  EXPECT_EQ(world.overlapping(Shape(Segment::between(Vec2(1, 1), Vec2(1.5, -1)))), std::vector<BodyId>{floor});
  EXPECT_EQ(world.overlapping(Shape(Segment::between(Vec2(-1, -1), Vec2(-1.5, 1)))), std::vector<BodyId>{floor});
  EXPECT_TRUE(world.overlapping(Shape(Segment::between(Vec2(-1, 0.5), Vec2(1, 0.5)))).empty());
  const auto down = world.ray_cast(Vec2(1, 1), Vec2(0, -1), 5.0);
  ASSERT_TRUE(down);
  EXPECT_EQ(down->body, floor);
  EXPECT_EQ(down->distance, 1.0);
  EXPECT_FALSE(world.ray_cast(Vec2(1, -1), Vec2(0, 1), 5.0));
}

// Records name the segment: a box across the vertex between two segments in line gets one record
// from each, each with the floor's normal and its points over that segment; a ball on a hill's top
// gets one, from the segment that owns the corner's half it lies in.
TEST(ChainWorld, RecordsNameTheSegments) {
  World world({.contacts = true, .threads = 1});
  const BodyId floor = world.add_chain(kFloor, false);
  const std::vector<ShapeId> segments = world.shapes(floor);
  const BodyId crate = world.add(Rect{Vec2(0.25, 0.5 - 0x1p-6), Vec2(0.5, 0.5), 0.0});
  world.update();
  ASSERT_EQ(world.overlapping().size(), 2u);
  ASSERT_EQ(world.contacts().size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const BodyContact& c = world.contacts()[k];
    EXPECT_EQ(c.b, crate);
    EXPECT_EQ(c.shape_a, segments[k]);
    EXPECT_EQ(c.contact.normal, Vec2(0, 1));
    for (const ContactPoint& p : c.contact.points()) {
      EXPECT_TRUE(k == 0 ? p.point_a.x() >= 0.0 : p.point_a.x() <= 0.0)
          << "segment " << k << " point " << p.point_a.x();
    }
  }
  World hill({.contacts = true, .threads = 1});
  const BodyId top = hill.add_chain(std::vector<Vec2>{{3, -1}, {1, 0}, {0, 0.25}, {-1, 0}, {-3, -1}}, false);
  hill.add(Circle{Vec2(0.0625, 0.7), 0.5});
  hill.update();
  ASSERT_EQ(hill.contacts().size(), 1u);
  EXPECT_EQ(hill.contacts()[0].shape_a, hill.shapes(top)[0]) << "right of the top: the first segment's half";
}

}  // namespace
}  // namespace collide2d
