// The World's mover queries: cast_mover() is the least of the pair cast over the shapes it lets
// through (checked against a scan of every shape, to the bit), collide_mover() the contacts within
// the skin (against a scan); the mover's own body, sensors and filtered shapes are left out; a
// chain stops only a mover in front of it and gives no plane out of a seam.
#include <collide2d/mover.h>
#include <collide2d/world.h>

#include <gtest/gtest.h>

#include "mover_testing.h"
#include "refusals.h"
#include "tools/random.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace collide2d {
namespace {

using testing::expect_refused;
using testing::random_kind;
using tool::uniform;
using tool::uniform_point;
using Rng = std::mt19937_64;

// A level of static and moving shapes of every kind, a chain, a sensor and a filtered-out body.
struct Level {
  World world;
  BodyId sensor, hidden;
  std::vector<Vec2> chain{Vec2(12, -1), Vec2(10, 0), Vec2(5, 0.5), Vec2(0, 0), Vec2(-2, 1)};
};

void build(Level& level, Rng& rng) {
  for (int k = 0; k < 60; ++k) {
    const Vec2 c = uniform_point(rng, -1, 11);
    level.world.add(random_kind(rng, k % 6, c, uniform(rng, 0.2, 1.0)), {.is_static = k % 2 == 0});
  }
  level.world.add_chain(level.chain, false);
  level.sensor = level.world.add(Circle{Vec2(5, 5), 2.0}, {.sensor = true});
  level.hidden = level.world.add(Circle{Vec2(5, 6), 2.0}, {.filter = {.category = 2}});
}

// Every solid shape the query sees, with the chain's segments as chain segments.
template <class F>
void each_seen(const World& world, const MoverQuery& query, F f) {
  for (const BodyId body : world.bodies()) {
    if (body == query.self || world.is_sensor(world.shapes(body)[0])) continue;
    for (const ShapeId shape : world.shapes(body)) {
      const Filter& filter = world.filter(shape);
      if ((filter.category & query.filter.mask) == 0 || (filter.mask & query.filter.category) == 0) continue;
      f(body, shape);
    }
  }
}

TEST(WorldMover, CastIsTheLeastPairCastOverTheShapesItSees) {
  Rng rng(21);
  Level level;
  build(level, rng);
  const World& world = level.world;
  int stopped = 0;
  for (int k = 0; k < 400; ++k) {
    const Shape mover = random_kind(rng, k % 6, uniform_point(rng, -1, 11), uniform(rng, 0.1, 0.5));
    const Vec2 move = uniform_point(rng, -3, 3);
    const MoverQuery query{.skin = uniform(rng, 0.0, 0.05), .filter = {.mask = 1}};
    double expected = 1.0;
    each_seen(world, query, [&](BodyId, ShapeId shape) {
      const auto chain = world.chain_segment(shape);
      if (chain && !in_front(*chain, mover)) return;
      expected = std::min(expected, cast_mover(mover, move, world.shape(shape), query.skin));
    });
    ASSERT_EQ(world.cast_mover(mover, move, query), expected) << k;
    stopped += expected < 1.0;
  }
  EXPECT_GT(stopped, 100);
}

TEST(WorldMover, CollideGivesEveryContactWithinTheSkin) {
  Rng rng(22);
  Level level;
  build(level, rng);
  const World& world = level.world;
  std::size_t planes = 0;
  for (int k = 0; k < 400; ++k) {
    const Shape mover = random_kind(rng, k % 6, uniform_point(rng, -1, 11), uniform(rng, 0.1, 0.5));
    const MoverQuery query{.skin = uniform(rng, 0.0, 0.3), .filter = {.mask = 1}};
    std::vector<MoverPlane> expected;
    each_seen(world, query, [&](BodyId body, ShapeId shape) {
      const auto chain = world.chain_segment(shape);
      const Contact c = chain ? contact(*chain, mover) : contact(world.shape(shape), mover);
      if (!c.empty() && c.separation <= query.skin)
        expected.push_back({body, shape, world.user_id(body), c.point_a, c.normal, c.separation});
    });
    const std::vector<MoverPlane> got = world.collide_mover(mover, query);
    ASSERT_EQ(got.size(), expected.size()) << k;
    for (std::size_t i = 0; i < got.size(); ++i) {
      ASSERT_EQ(got[i].body, expected[i].body) << k;
      ASSERT_EQ(got[i].shape, expected[i].shape) << k;
      ASSERT_EQ(got[i].separation, expected[i].separation) << k;
      ASSERT_EQ(got[i].normal, expected[i].normal) << k;
      ASSERT_EQ(got[i].point, expected[i].point) << k;
    }
    planes += got.size();
  }
  EXPECT_GT(planes, 200u);
}

TEST(WorldMover, LeavesOutItsOwnBodySensorsAndFilteredShapes) {
  World world;
  const Shape mover = Circle{Vec2(0, 0.5), 0.5};
  const BodyId self = world.add(mover);
  world.add(Circle{Vec2(0, 2), 0.5}, {.sensor = true});
  world.add(Circle{Vec2(0, 3), 0.5}, {.filter = {.category = 2}});
  const MoverQuery query{.filter = {.mask = 1}, .self = self};
  EXPECT_EQ(world.cast_mover(mover, Vec2(0, 4), query), 1.0);
  EXPECT_TRUE(world.collide_mover(mover, query).empty());
  // Its own body, named nowhere, overlaps it: a plane, but it leaves it freely.
  EXPECT_EQ(world.collide_mover(mover, {.filter = {.mask = 1}}).size(), 1u);
  EXPECT_EQ(world.cast_mover(mover, Vec2(0, 4), {.filter = {.mask = 1}}), 1.0);
  // The body of category 2, seen, stops it at the skin: centres 1.01 apart.
  EXPECT_NEAR(0.5 + 4 * world.cast_mover(mover, Vec2(0, 4), {.self = self}), 3 - 1.01, 1e-9);
}

// A floor chain runs from right to left. A mover below it passes up through it; one above lands.
TEST(WorldMover, AChainStopsOnlyAMoverInFrontOfIt) {
  World world;
  const std::vector<Vec2> floor{Vec2(6, 0), Vec2(4, 0), Vec2(-4, 0), Vec2(-6, 0)};
  world.add_chain(floor, false);
  EXPECT_EQ(world.cast_mover(Circle{Vec2(0, -2), 0.5}, Vec2(0, 4)), 1.0);
  const double f = world.cast_mover(Circle{Vec2(0, 2), 0.5}, Vec2(0, -4));
  EXPECT_NEAR(2 - 4 * f, 0.5 + 0.01, 1e-9);
}

// A mover resting within the skin on a straight chain of many segments: every plane is the
// floor's, wherever the vertices fall under it. (Boxes edge to edge are separate shapes: a rounded
// mover over the seam is within the skin of the next box's corner, and move() follows the floor by
// exact separations rather than by that plane.)
TEST(WorldMover, NoPlanePointsOutOfAChainsSeam) {
  World world;
  std::vector<Vec2> points;
  for (int i = 101; i >= -1; --i) points.push_back(Vec2(0.1 * i, 0.0));
  world.add_chain(points, false);
  Rng rng(23);
  for (int k = 0; k < 2000; ++k) {
    const double x = uniform(rng, 1, 9);
    const Shape mover =
        k % 2 == 0 ? Shape(Circle{Vec2(x, 0.3 + 0.005), 0.3}) : Shape(Rect{Vec2(x, 0.3 + 0.005), Vec2(0.2, 0.3), 0.0});
    const std::vector<MoverPlane> planes = world.collide_mover(mover);
    ASSERT_FALSE(planes.empty()) << k;
    for (const MoverPlane& p : planes) {
      ASSERT_NEAR(p.normal.x(), 0.0, 1e-12) << k;
      ASSERT_NEAR(p.separation, 0.005, 1e-12) << k;
    }
  }
}

TEST(WorldMover, RefusesBadInput) {
  World world;
  const BodyId gone = world.add(Circle{Vec2(5, 5), 1.0});
  world.remove(gone);
  const Shape mover = Circle{Vec2(0, 0), 0.5};
  expect_refused<std::invalid_argument>([&] { world.cast_mover(mover, Vec2(NAN, 0)); }, "mover translation x");
  expect_refused<std::invalid_argument>([&] { world.cast_mover(mover, Vec2(1, 0), {.skin = -1}); }, "mover skin");
  expect_refused<std::invalid_argument>([&] { world.collide_mover(mover, {.skin = NAN}); }, "mover skin");
  expect_refused<std::out_of_range>([&] { world.collide_mover(mover, {.self = gone}); }, "body");
  expect_refused<InvalidShape>([&] { world.cast_mover(Circle{Vec2(0, 0), 0.0}, Vec2(1, 0)); }, "radius");
}

}  // namespace
}  // namespace collide2d
