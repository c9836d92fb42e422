// A steady World frame allocates nothing: the broad phase's strips and pair lists, the narrow
// phase's result lists and the trees keep their storage from frame to frame. This binary counts
// every operator new, so it holds these tests alone.
#include <collide2d/mover.h>
#include <collide2d/world.h>

#include "tests/support/allocation_counter.h"
#include "tools/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace collide2d {
namespace {

// 1,000 moving bodies of every kind in a square (8% covered), 200 static bodies and 4 static
// sensors among them. Every body moves and turns each frame, and its motion reverses every 20
// frames: the scene repeats itself every 40 frames, up to the rounding of the moves and the
// hysteresis of the fat boxes, so that once every list has met the largest size it will ever need a
// World that keeps its storage allocates nothing more. (Counted per period: 1,203 allocations in
// the first, then 3, 2, 0, 1, 1, 0, 1 as a few bodies' static neighbour lists meet a new largest
// size, and none from the ninth period on.)
struct Scene {
  World world;
  std::vector<BodyId> ids;
  std::vector<Vec2> velocity;
  std::vector<double> spin;
  int frames = 0;

  explicit Scene(const WorldOptions& options) : world(options) {
    std::mt19937_64 rng{5};
    const tool::Uniform u(0.0, 1.0);
    const double side = std::sqrt(28.0 * 1000);
    const auto shape = [&](const Vec2& c) -> Shape {
      const double half = 0.3 + 1.7 * u(rng);
      switch (rng() % 3) {
        case 0:
          return Circle{c, half};
        case 1:
          return Ellipse{c, half, half * (0.2 + 0.8 * u(rng)), 6.0 * u(rng)};
        default:
          return Rect{c, Vec2(half, half * (0.2 + 0.8 * u(rng))), 6.0 * u(rng)};
      }
    };
    for (int k = 0; k < 200; ++k) {
      const double y = u(rng) * side;
      world.add(shape(Vec2(u(rng) * side, y)), {.is_static = true});
    }
    for (int k = 0; k < 4; ++k) {
      const double y = u(rng) * side;
      world.add(Rect{Vec2(u(rng) * side, y), Vec2(8, 8), 0.0}, {.is_static = true, .sensor = true});
    }
    for (int k = 0; k < 1000; ++k) {
      const double y = u(rng) * side;
      ids.push_back(world.add(shape(Vec2(u(rng) * side, y))));
      const double vy = 0.4 * (u(rng) - 0.5);
      velocity.emplace_back(0.4 * (u(rng) - 0.5), vy);
      spin.push_back(0.1 * (u(rng) - 0.5));
    }
  }

  void frame() {
    const double sign = frames++ / 20 % 2 == 0 ? 1.0 : -1.0;
    for (std::size_t k = 0; k < ids.size(); ++k) world.move_by(ids[k], sign * velocity[k], sign * spin[k]);
    world.update();
  }
};

// Allocations over 200 frames (five periods) after ten periods, with the pairs found meanwhile.
long allocations_in_steady_frames(const WorldOptions& options) {
  Scene scene(options);
  for (int k = 0; k < 400; ++k) scene.frame();
  const long before = testing::allocation_count.load();
  std::size_t overlapping = 0, sensed = 0, entered = 0;
  for (int k = 0; k < 200; ++k) {
    scene.frame();
    overlapping += scene.world.overlapping().size();
    sensed += scene.world.sensing().size();
    entered += scene.world.began().size();
  }
  const long count = testing::allocation_count.load() - before;
  // The frames do fill their lists, and change them: the storage is in use.
  EXPECT_GT(overlapping, 200u * 100);
  EXPECT_GT(sensed, 100u);
  EXPECT_GT(entered, 100u);
  return count;
}

TEST(WorldAllocations, SteadyFramesAllocateNothing) {
  EXPECT_EQ(allocations_in_steady_frames({.fat_margin = 0.1, .threads = 1}), 0);
}

TEST(WorldAllocations, SteadyFramesWithContactsAndProximityAllocateNothing) {
  EXPECT_EQ(allocations_in_steady_frames({.fat_margin = 0.1, .proximity_margin = 0.5, .contacts = true, .threads = 1}),
            0);
}

// Every callback query, and a character's move, allocates nothing: 100 of each over a steady World, counted the second
// time they run (the first lets the curved kernels' per-thread scratch grow to the largest these need). The vector
// forms of the same queries do allocate, so the counter sees what they collect.
TEST(WorldAllocations, CallbackQueriesAllocateNothing) {
  Scene scene({.fat_margin = 0.1, .threads = 1});
  for (int k = 0; k < 400; ++k) scene.frame();
  std::mt19937_64 rng{8};
  const tool::Uniform u(0.0, 170.0);
  std::vector<Vec2> points;
  for (int k = 0; k < 100; ++k) {
    const double y = u(rng);
    points.emplace_back(u(rng), y);
  }
  // Callbacks that hold more than std::function keeps without allocating (two pointers in
  // libstdc++), as a game's do.
  std::size_t found = 0, index_sum = 0;
  std::uint32_t last = 0;
  double reach_sum = 0.0;
  const auto count = [&found, &index_sum, &last](const BodyShape& s) {
    index_sum += s.body.index;
    last = s.body.index;
    return ++found > 0;
  };
  const auto hit = [&found, &index_sum, &reach_sum](const auto& h) {
    index_sum += h.body.index;
    reach_sum += h.point.x();
    ++found;
    return -1.0;
  };
  const Vec2 direction(1.0, 0.3);
  const auto callbacks = [&] {
    for (const Vec2& p : points) {
      const Shape probe = Ellipse{p, 3.0, 1.0, 0.5};
      scene.world.overlapping(probe, count);
      scene.world.overlapping(Aabb{p, p + Vec2(4, 4)}, count);
      scene.world.within(p, 2.0, count);
      scene.world.within(probe, 1.0, count);
      scene.world.ray_cast(p, direction, 40.0, hit);
      scene.world.cast(probe, Vec2(10, 3), hit);
      reach_sum += scene.world.cast_mover(probe, Vec2(10, 3));
      scene.world.collide_mover(probe, [&found](const MoverPlane&) { return ++found > 0; }, {.skin = 0.5});
      reach_sum += move(scene.world, probe, Vec2(3, -5), 0.1, {.step_height = 0.2, .snap_distance = 0.2}).position.x();
    }
  };
  callbacks();
  found = 0;
  long before = testing::allocation_count.load();
  callbacks();
  EXPECT_EQ(testing::allocation_count.load() - before, 0);
  EXPECT_GT(found, 1000u);
  EXPECT_GT(index_sum + last, 0u);
  EXPECT_TRUE(std::isfinite(reach_sum));
  before = testing::allocation_count.load();
  for (const Vec2& p : points)
    found += scene.world.within(p, 2.0).size() + scene.world.ray_cast_all(p, direction, 40.0).size();
  EXPECT_GT(testing::allocation_count.load() - before, 100);
}

}  // namespace
}  // namespace collide2d
