// move(): a character on scripted levels, frame by frame (gravity, walking, jumping), each check
// against what the level's construction makes exact: the height of a flat floor, the slope's
// line, the single box a row of tiles stands in for, and the exact separation of every shape after
// every move (contact()), never below the floor of the cast.
#include <collide2d/mover.h>
#include <collide2d/query.h>
#include <collide2d/world.h>

#include <gtest/gtest.h>

#include "mover_course.h"
#include "refusals.h"
#include "tools/random.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace collide2d {
namespace {

using testing::expect_refused;
using tool::uniform;
using Rng = std::mt19937_64;

constexpr double kDt = 1.0 / 60, kGravity = 20.0, kSkin = 0.01;

// The movers of every kind, about a unit tall, centred at the origin: the mover suite's.
std::vector<Shape> movers() {
  std::vector<Shape> out;
  for (const testing::CourseMover& m : testing::course_movers()) out.push_back(m.shape);
  return out;
}

// The height of a shape's lowest point: its support point's along -up.
double lowest(const Shape& s) { return support(s, Vec2(0, -1)).y(); }

// A character: its shape where it is, its velocity, the last move.
struct Character {
  Shape shape;
  Vec2 velocity = Vec2::Zero();
  MoveResult last{};

  // One frame: gravity, the walking speed commanded, a jump on the ground, then the move.
  void step(const World& world, double walk, bool jump, const MoverOptions& options = {}) {
    velocity.x() = walk;
    velocity.y() -= kGravity * kDt;
    if (jump && last.ground.on_ground) velocity.y() = 6.0;
    last = move(world, shape, velocity, kDt, options);
    shape = moved_to(shape, last.position);
    velocity = last.velocity;
  }
};

// The shape placed with its lowest point at height `y` + skin over x.
Shape standing(const Shape& s, double x, double y) {
  const Shape placed = moved_to(s, Vec2(x, 0.0));
  return moved_to(s, Vec2(x, y + kSkin - lowest(placed)));
}

TEST(MoverMove, WalksAFlatFloorAtTheCommandedSpeed) {
  for (const Shape& kind : movers()) {
    World world;
    world.add(Rect{Vec2(0, -1), Vec2(100, 1), 0.0}, {.is_static = true});
    Character c{standing(kind, 0, 0)};
    const double height = center_of(c.shape).y();
    for (int frame = 0; frame < 600; ++frame) {
      const double x = center_of(c.shape).x();
      c.step(world, 3.0, false);
      ASSERT_NEAR(center_of(c.shape).x() - x, 3.0 * kDt, 1e-12) << frame;
      ASSERT_NEAR(center_of(c.shape).y(), height, 1e-12) << frame;
      ASSERT_TRUE(c.last.ground.on_ground) << frame;
      ASSERT_FALSE(c.last.blocked) << frame;  // the floor holds it up; nothing stops it
      ASSERT_EQ(c.last.velocity.y(), 0.0) << frame;
    }
  }
}

// A slope of 30 degrees as a polygon and as a chain: a mover standing on it does not slide.
TEST(MoverMove, StandsOnASlopeBelowTheMaxSlope) {
  const double rise = std::tan(std::numbers::pi / 6);
  for (int chain = 0; chain < 2; ++chain) {
    for (const Shape& kind : movers()) {
      World world;
      const std::vector<Vec2> hill{Vec2(-20, -20 * rise - 1), Vec2(20, -20 * rise - 1), Vec2(20, 20 * rise),
                                   Vec2(-20, -20 * rise)};
      if (chain) {
        const std::vector<Vec2> line{Vec2(30, 30 * rise), Vec2(20, 20 * rise), Vec2(-20, -20 * rise),
                                     Vec2(-30, -30 * rise)};
        world.add_chain(line, false);
      } else {
        world.add(ConvexPolygon::of(hill), {.is_static = true});
      }
      Character c{moved_to(kind, Vec2(0, 3))};
      for (int frame = 0; frame < 120; ++frame) c.step(world, 0.0, false);  // falls and lands
      ASSERT_TRUE(c.last.ground.on_ground);
      const Vec2 rest = center_of(c.shape);
      for (int frame = 0; frame < 600; ++frame) {
        c.step(world, 0.0, false);
        ASSERT_NEAR(center_of(c.shape).x(), rest.x(), 1e-12) << frame;
        ASSERT_NEAR(center_of(c.shape).y(), rest.y(), 1e-12) << frame;
        ASSERT_TRUE(c.last.ground.on_ground) << frame;
      }
    }
  }
}

// A wall of 70 degrees at the foot of a flat floor: pushing into it never climbs it.
TEST(MoverMove, NeverClimbsAWallSteeperThanTheMaxSlope) {
  const double run = 1 / std::tan(70 * std::numbers::pi / 180);
  for (const Shape& kind : movers()) {
    World world;
    world.add(Rect{Vec2(0, -1), Vec2(100, 1), 0.0}, {.is_static = true});
    const std::vector<Vec2> wall{Vec2(5, 0), Vec2(20, 0), Vec2(20, 10), Vec2(5 + 10 * run, 10)};
    world.add(ConvexPolygon::of(wall), {.is_static = true});
    Character c{standing(kind, 3, 0)};
    const double floor = lowest(c.shape);
    for (int frame = 0; frame < 600; ++frame) {
      c.step(world, 4.0, false);
      ASSERT_LE(lowest(c.shape), floor + kSkin) << frame;
    }
  }
}

// Falling against a vertical wall while pushing into it: the fall along the wall is kept.
TEST(MoverMove, SlidesDownAWallAtTheCommandedSpeed) {
  for (const Shape& kind : movers()) {
    World world;
    world.add(Rect{Vec2(1, 0), Vec2(0.5, 100), 0.0}, {.is_static = true});
    Character c{moved_to(kind, Vec2(-0.6, 50))};
    for (int frame = 0; frame < 120; ++frame) {
      const double y = center_of(c.shape).y(), fall = c.velocity.y() - kGravity * kDt;
      c.step(world, 2.0, false);
      if (frame > 30) ASSERT_NEAR(center_of(c.shape).y() - y, fall * kDt, 1e-12) << frame;
    }
  }
}

// A jump under a ceiling stops at the skin.
TEST(MoverMove, StopsUnderACeiling) {
  for (const Shape& kind : movers()) {
    World world;
    world.add(Rect{Vec2(0, -1), Vec2(100, 1), 0.0}, {.is_static = true});
    const Shape ceiling = Rect{Vec2(0, 2.0), Vec2(100, 0.5), 0.0};  // 1.5 over the floor
    world.add(ceiling, {.is_static = true});
    Character c{standing(kind, 0, 0)};
    double nearest = INFINITY;
    for (int frame = 0; frame < 120; ++frame) {
      c.step(world, 1.0, frame == 1);  // on the ground after the first move
      nearest = std::min(nearest, contact(ceiling, c.shape).separation);
    }
    EXPECT_GE(nearest, kSkin - 1e-9);
    EXPECT_LE(nearest, kSkin + 1e-9);
  }
}

// 100 tiles edge to edge, and a chain of 100 segments, against one box and one segment of the same
// length: the same path at every frame under the same random inputs.
TEST(MoverMove, FeelsNoSeamBetweenTilesOrChainSegments) {
  for (const Shape& kind : movers()) {
    for (int chain = 0; chain < 2; ++chain) {
      World tiles, whole;
      if (chain) {
        std::vector<Vec2> points{Vec2(60, 0)};
        for (int i = 100; i >= 0; --i) points.push_back(Vec2(0.5 * i - 25, 0));
        points.push_back(Vec2(-60, 0));
        tiles.add_chain(points, false);
        const std::vector<Vec2> line{Vec2(60, 0), Vec2(25, 0), Vec2(-25, 0), Vec2(-60, 0)};
        whole.add_chain(line, false);
      } else {
        for (int i = 0; i < 100; ++i)
          tiles.add(Rect{Vec2(0.5 * i - 24.75, -0.5), Vec2(0.25, 0.5), 0.0}, {.is_static = true});
        whole.add(Rect{Vec2(0, -0.5), Vec2(25, 0.5), 0.0}, {.is_static = true});
      }
      Character a{standing(kind, -20, 0)}, b = a;
      Rng rng(7);
      for (int frame = 0; frame < 2000; ++frame) {
        const double walk = uniform(rng, -2, 6);
        const bool jump = uniform(rng, 0, 1) < 0.02;
        a.step(tiles, walk, jump);
        b.step(whole, walk, jump);
        ASSERT_NEAR(center_of(a.shape).x(), center_of(b.shape).x(), 1e-12) << frame;
        ASSERT_NEAR(center_of(a.shape).y(), center_of(b.shape).y(), 1e-12) << frame;
        ASSERT_EQ(a.last.ground.on_ground, b.last.ground.on_ground) << frame;
      }
    }
  }
}

// Tiles whose tops are jittered by up to 1e-9: the path never strays from the flat floor's by more.
TEST(MoverMove, FeelsNoMoreThanTheJitterOfTiles) {
  for (const Shape& kind : movers()) {
    World tiles, whole;
    Rng rng(8);
    for (int i = 0; i < 100; ++i) {
      const double top = uniform(rng, 0, 1e-9);
      tiles.add(Rect{Vec2(0.5 * i - 24.75, -0.5 + top), Vec2(0.25, 0.5), 0.0}, {.is_static = true});
    }
    whole.add(Rect{Vec2(0, -0.5), Vec2(25, 0.5), 0.0}, {.is_static = true});
    Character a{standing(kind, -20, 1e-9)}, b{standing(kind, -20, 0)};
    for (int frame = 0; frame < 600; ++frame) {
      a.step(tiles, 3.0, false);
      b.step(whole, 3.0, false);
      ASSERT_NEAR(center_of(a.shape).x(), center_of(b.shape).x(), 1e-12) << frame << " kind " << kind.index();
      ASSERT_GE(center_of(a.shape).y() - center_of(b.shape).y(), -1e-12) << frame;
      ASSERT_LE(center_of(a.shape).y() - center_of(b.shape).y(), 1e-9 + 1e-12) << frame;
    }
  }
}

// Walking down a 30-degree slope faster than gravity follows: with a snap distance the mover
// stays on the ground.
TEST(MoverMove, SnapsToTheGroundWalkingDownASlope) {
  const double rise = std::tan(std::numbers::pi / 6);
  for (const Shape& kind : movers()) {
    World world;
    const std::vector<Vec2> line{Vec2(-30, 30 * rise), Vec2(-20, 20 * rise), Vec2(20, -20 * rise),
                                 Vec2(30, -30 * rise)};
    std::vector<Vec2> reversed(line.rbegin(), line.rend());
    world.add_chain(reversed, false);
    Character c{moved_to(kind, Vec2(-15, 15 * rise + 1))};
    for (int frame = 0; frame < 60; ++frame) c.step(world, 0.0, false);
    ASSERT_TRUE(c.last.ground.on_ground);
    for (int frame = 0; center_of(c.shape).x() < 19; ++frame) {  // the slope ends at x = 20
      c.step(world, 8.0, false, {.snap_distance = 0.5});
      ASSERT_TRUE(c.last.ground.on_ground) << frame;
    }
  }
}

// A step of 0.2 and one of 0.3 on a flat floor: with a step height of 0.25 the mover climbs the
// first onto its top and stops at the second's edge, its skin away.
TEST(MoverMove, ClimbsStepsUpToTheStepHeightAndNoHigher) {
  for (const Shape& kind : movers()) {
    World world;
    world.add(Rect{Vec2(0, -1), Vec2(100, 1), 0.0}, {.is_static = true});
    world.add(Rect{Vec2(15, 0.1), Vec2(10, 0.1), 0.0}, {.is_static = true});  // from x = 5, 0.2 high
    const Shape high = Rect{Vec2(25, 0.25), Vec2(10, 0.25), 0.0};             // from x = 15, 0.3 above the first
    world.add(high, {.is_static = true});
    Character c{standing(kind, 0, 0)};
    const MoverOptions options{.step_height = 0.25};
    for (int frame = 0; frame < 600; ++frame) c.step(world, 3.0, false, options);
    ASSERT_TRUE(c.last.ground.on_ground);
    EXPECT_NEAR(lowest(c.shape), 0.2 + kSkin, 1e-9);
    EXPECT_NEAR(contact(high, c.shape).separation, kSkin, 1e-9);
  }
}

// A platform moving along a curve and a lift going up and down: a mover standing still on each
// moves with it, to the rounding of one frame's step, and stays on it at the skin.
TEST(MoverMove, RidesMovingPlatformsWithoutDrifting) {
  for (const Shape& kind : movers()) {
    World world;
    const BodyId platform = world.add(Rect{Vec2(0, 0), Vec2(3, 0.25), 0.0});
    const BodyId lift = world.add(Rect{Vec2(20, 0), Vec2(3, 0.25), 0.0});
    Character a{standing(kind, 0.5, 0.25)}, b{standing(kind, 20.5, 0.25)};
    world.update();
    for (int frame = 0; frame < 600; ++frame) {
      const double t = frame * kDt;
      const Vec2 on_platform = center_of(a.shape) - world.pose(platform).position;
      world.move_to(platform, Vec2(2 * std::sin(t), 0.5 * std::sin(2 * t)), 0.0);
      world.move_to(lift, Vec2(20, 3 * std::sin(t)), 0.0);
      world.update();
      a.last = move(world, a.shape, Vec2::Zero(), kDt, {}, a.last.ground);
      a.shape = moved_to(a.shape, a.last.position);
      b.last = move(world, b.shape, Vec2::Zero(), kDt, {}, b.last.ground);
      b.shape = moved_to(b.shape, b.last.position);
      if (frame == 0) continue;  // standing on them from the first move on
      ASSERT_TRUE(a.last.ground.on_ground && b.last.ground.on_ground) << frame;
      const Vec2 drift = center_of(a.shape) - world.pose(platform).position - on_platform;
      ASSERT_NEAR(drift.x(), 0.0, 1e-12) << frame;
      ASSERT_NEAR(lowest(a.shape), world.pose(platform).position.y() + 0.25 + kSkin, 1e-9) << frame;
      ASSERT_NEAR(center_of(b.shape).x(), 20.5, 1e-12) << frame;
      ASSERT_NEAR(lowest(b.shape), world.pose(lift).position.y() + 0.25 + kSkin, 1e-9) << frame;
    }
  }
}

// Two soft movers walking into each other, each pushed at most the push limit a move: where that
// is more than a move's walk, they keep their skin apart.
TEST(MoverMove, SoftMoversPushEachOtherWithinTheirLimit) {
  World world;
  world.add(Rect{Vec2(0, -1), Vec2(100, 1), 0.0}, {.is_static = true});
  const Filter soft{.category = 2};
  std::vector<Character> pair{Character{standing(movers()[0], -2, 0)}, Character{standing(movers()[1], 2, 0)}};
  std::vector<BodyId> bodies;
  for (const Character& c : pair) bodies.push_back(world.add(c.shape, {.filter = soft}));
  const double limit = 0.04;  // a move's walk is at most 2 / 60
  for (int frame = 0; frame < 600; ++frame) {
    for (std::size_t i = 0; i < 2; ++i) {
      Character& c = pair[i];
      const double walk = i == 0 ? 2.0 : -1.0;
      const Vec2 start = center_of(c.shape);
      const MoverOptions options{.query = {.self = bodies[i]}, .soft_categories = 2, .soft_push_limit = limit};
      c.step(world, walk, false, options);
      world.move_to(bodies[i], center_of(c.shape), angle_of(c.shape));
      const double commanded = start.x() + walk * kDt;
      ASSERT_LE(std::abs(center_of(c.shape).x() - commanded), limit + 1e-12) << frame;
    }
    ASSERT_LT(center_of(pair[0].shape).x(), center_of(pair[1].shape).x()) << frame;
    ASSERT_GE(contact(pair[0].shape, pair[1].shape).separation, kSkin - 1e-9) << frame;
  }
}

// A level of everything, random inputs: after every move no shape overlaps the mover beyond
// rounding.
TEST(MoverMove, NeverSinksIntoALevel) {
  for (const Shape& kind : movers()) {
    World world;
    std::vector<Shape> solid{Rect{Vec2(0, -1), Vec2(30, 1), 0.0},
                             Rect{Vec2(-31, 10), Vec2(1, 12), 0.0},
                             Rect{Vec2(31, 10), Vec2(1, 12), 0.0},
                             Ellipse{Vec2(-10, 1), 3, 1, 0.3},
                             Circle{Vec2(5, 0.5), 1.0},
                             Capsule{Vec2(12, 1.5), 2, 0.3, 0.4},
                             ConvexPolygon::regular(5, 1.5).at(Vec2(-3, 4), 0.2),
                             Rect{Vec2(20, 4), Vec2(3, 0.2), -0.2}};
    for (const Shape& s : solid) world.add(s, {.is_static = true});
    Character c{moved_to(kind, Vec2(0, 3))};
    Rng rng(9);
    double walk = 0;
    for (int frame = 0; frame < 3000; ++frame) {
      if (frame % 40 == 0) walk = uniform(rng, -6, 6);
      c.step(world, walk, uniform(rng, 0, 1) < 0.03);
      // Never nearer than the skin, less the cast's hair (1e-12 of the centre's magnitude).
      for (const Shape& s : solid) ASSERT_GE(contact(s, c.shape).separation, kSkin - 1e-10) << frame;
    }
  }
}

TEST(MoverMove, RefusesBadInput) {
  World world;
  const Shape mover = Circle{Vec2(0, 0), 0.5};
  expect_refused<std::invalid_argument>([&] { move(world, mover, Vec2(NAN, 0), kDt); }, "move velocity x");
  expect_refused<std::invalid_argument>([&] { move(world, mover, Vec2(0, 0), -1.0); }, "move dt");
  expect_refused<std::invalid_argument>([&] { move(world, mover, Vec2(0, 0), kDt, {.max_slope = 2.0}); }, "max slope");
  expect_refused<std::invalid_argument>([&] { move(world, mover, Vec2(0, 0), kDt, {.up = Vec2(0, 2)}); }, "up");
  expect_refused<std::invalid_argument>([&] { move(world, mover, Vec2(0, 0), kDt, {.max_iterations = 0}); },
                                        "iterations");
  expect_refused<std::invalid_argument>([&] { move(world, mover, Vec2(0, 0), kDt, {.step_height = -1}); },
                                        "step height");
  expect_refused<std::invalid_argument>([&] { move(world, mover, Vec2(0, 0), kDt, {.query = {.skin = -1}}); }, "skin");
}

}  // namespace
}  // namespace collide2d
