// Continuous bodies: no tunnelling, teleports against sweeps, and impacts against time_of_impact on
// every pair.
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>
#include "tools/random.h"
#include "world_testing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace collide2d {
namespace {

using namespace testing;
// A bullet 10 of its sizes per frame... 1,000 of them, through a wall 10 sizes thick: on one side
// at one update and on the other at the next. Without the flag the World sees nothing; with it,
// impacts() holds the pair, at the exact time less at most the tolerance over the speed.
TEST(World, ContinuousBodiesDoNotTunnel) {
  for (const bool flagged : {false, true}) {
    World world;
    const BodyId wall = world.add(Rect{{0, 0}, {0.005, 1}, 0});
    const BodyId bullet = world.add(Circle{{-1, 0.3}, 0.001});
    if (flagged) world.set_continuous(bullet);
    world.update();
    world.move_to(bullet, {1, 0.3}, 0);
    world.update();
    EXPECT_TRUE(world.overlapping().empty());
    if (!flagged) {
      EXPECT_TRUE(world.impacts().empty());
      continue;
    }
    ASSERT_EQ(world.impacts().size(), 1u);
    const Impact& hit = world.impacts()[0];
    EXPECT_EQ(hit.a, wall);
    EXPECT_EQ(hit.b, bullet);
    const double t0 = (1 - 0.005 - 0.001) / 2;
    EXPECT_LE(hit.t, t0 + 1e-15);
    EXPECT_GE(hit.t, t0 - 1e-9);
    EXPECT_NEAR(hit.normal.x(), -1.0, 1e-12);
    EXPECT_EQ(world.last_frame().impacts, 1u);
    world.update();  // the next step begins where this one ended: no motion, no impact
    EXPECT_TRUE(world.impacts().empty());
  }
}

// set_pose() teleports: a continuous bullet put across the wall, before or after a move_to() in the
// same frame, hits nothing; move_to() from where it landed sweeps again. A body's pose reads back as
// it was given, a circle's angle too.
TEST(World, SetPoseTeleportsAndMoveToSweeps) {
  World world;
  world.add(Rect{{0, 0}, {0.005, 1}, 0});
  const BodyId bullet = world.add(Circle{{-1, 0.3}, 0.001});
  world.set_continuous(bullet);
  EXPECT_TRUE(world.is_continuous(bullet));
  world.update();
  world.set_pose(bullet, {1, 0.3}, 2.5);
  world.update();
  EXPECT_TRUE(world.impacts().empty());
  EXPECT_EQ(world.pose(bullet).position, Vec2(1, 0.3));
  EXPECT_EQ(world.pose(bullet).angle, 2.5);
  world.move_to(bullet, {0.5, 0.3}, 0);
  world.set_pose(bullet, {-1, 0.3}, 0);  // the step starts again here
  world.update();
  EXPECT_TRUE(world.impacts().empty());
  world.move_to(bullet, {0.5, 0.3}, 0);
  world.move_by(bullet, {0.5, 0}, 1);
  world.update();
  ASSERT_EQ(world.impacts().size(), 1u);
  EXPECT_EQ(world.pose(bullet).position, Vec2(1, 0.3));
  EXPECT_EQ(world.pose(bullet).angle, 1.0);
}

// Over frames of random moves and turns, with a third of the bodies continuous (and some switched
// off again, some removed), impacts() equals time_of_impact on every pair with a continuous body
// from the poses the test recorded at the last update.
TEST(World, ImpactsMatchAllPairs) {
  Rng rng(21);
  World world;
  std::vector<BodyId> ids;
  for (int k = 0; k < 120; ++k) ids.push_back(world.add(random_shape(rng, 12.0)));
  for (std::size_t k = 0; k < ids.size(); k += 3) world.set_continuous(ids[k]);
  world.update();
  std::vector<Shape> start;
  for (const BodyId id : ids) start.push_back(world.shape(id));
  std::size_t total = 0;
  for (int frame = 0; frame < 12; ++frame) {
    for (std::size_t k = 0; k < ids.size(); ++k) {
      if (!world.contains(ids[k])) continue;
      const double speed = k % 3 == 0 ? 3.0 : 0.3;
      const double turn = uniform(rng, -1, 1);
      world.move_by(ids[k], uniform_point(rng, -speed, speed), turn);
    }
    if (frame == 5) world.set_continuous(ids[3], false);
    if (frame == 7) world.remove(ids[6]);
    world.update();
    std::vector<Impact> expected;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      for (std::size_t j = i + 1; j < ids.size(); ++j) {
        const bool ci = i % 3 == 0 && !(i == 3 && frame >= 5), cj = j % 3 == 0 && !(j == 3 && frame >= 5);
        if (!world.contains(ids[i]) || !world.contains(ids[j]) || !(ci || cj)) continue;
        const auto motion = [&](std::size_t k, bool c) {
          return c ? Motion{center_of(world.shape(ids[k])) - center_of(start[k]),
                            angle_of(world.shape(ids[k])) - angle_of(start[k])}
                   : Motion{};
        };
        const TimeOfImpact r = time_of_impact(ci ? start[i] : world.shape(ids[i]), motion(i, ci),
                                              cj ? start[j] : world.shape(ids[j]), motion(j, cj));
        if (r.status == ToiStatus::hit || r.status == ToiStatus::stalled)
          expected.push_back({ids[i], ids[j], world.shapes(ids[i])[0], world.shapes(ids[j])[0], world.user_id(ids[i]),
                              world.user_id(ids[j]), world.user_id(ids[i]), world.user_id(ids[j]), r.t, r.normal,
                              r.point});
      }
    }
    ASSERT_EQ(world.impacts().size(), expected.size()) << "frame " << frame;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      const Impact& got = world.impacts()[k];
      EXPECT_EQ(got.a, expected[k].a);
      EXPECT_EQ(got.b, expected[k].b);
      EXPECT_EQ(got.user_a, expected[k].user_a);
      EXPECT_EQ(got.user_b, expected[k].user_b);
      EXPECT_EQ(got.t, expected[k].t);
      EXPECT_EQ(got.normal, expected[k].normal);
    }
    total += expected.size();
    for (std::size_t k = 0; k < ids.size(); ++k) {
      if (world.contains(ids[k])) start[k] = world.shape(ids[k]);
    }
  }
  EXPECT_GT(total, 20u);
  std::printf("[world] impacts over 12 frames: %zu, all equal to all-pairs time of impact\n", total);
}

}  // namespace
}  // namespace collide2d
