// Filters and the pair predicate: Box2D's rules, the pairs and queries under them.
#include <collide2d/ray_cast.h>
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
// Box2D's rules, case by case: masks both ways, a shared positive group overriding masks that
// refuse, a shared negative group overriding masks that accept, different groups left to the masks.
TEST(WorldFilter, FollowsBox2DsRules) {
  const Filter any;
  const Filter player{.category = 0b01, .mask = ~std::uint64_t{0b10}};
  const Filter bullet{.category = 0b10, .mask = ~std::uint64_t{0b01}};
  EXPECT_TRUE(should_pair(any, any));
  EXPECT_FALSE(should_pair(player, bullet));
  EXPECT_FALSE(should_pair(bullet, player));
  EXPECT_TRUE(should_pair(player, any));
  const Filter deaf{.category = 1, .mask = 0};
  EXPECT_FALSE(should_pair(deaf, any));
  EXPECT_FALSE(should_pair(any, deaf));
  EXPECT_TRUE(should_pair({.category = 1, .mask = 0, .group = 3}, {.category = 1, .mask = 0, .group = 3}));
  EXPECT_FALSE(should_pair({.group = -2}, {.group = -2}));
  EXPECT_TRUE(should_pair({.group = -2}, {.group = -3}));
  EXPECT_FALSE(should_pair({.category = 1, .mask = 0, .group = 3}, {.group = 4}));
}

// Over frames of motion, with random filters, a pair predicate, and filters changed mid-run: the
// overlapping pairs are exactly the all-pairs ones that pass both, and began()/ended() are the
// differences from the frame before (a filter change ends the pairs it refuses).
TEST(WorldFilter, PairsMatchAllPairsWithTheSameFilters) {
  Rng rng(21);
  World world({.fat_margin = 0.05});
  for (int k = 0; k < 200; ++k) {
    const Filter filter = random_filter(rng);
    world.add(random_shape(rng, 12.0), {.user_id = static_cast<std::uint64_t>(k), .filter = filter});
  }
  world.set_pair_predicate([&world](BodyId a, BodyId b) { return (world.user_id(a) + world.user_id(b)) % 5 != 0; });
  std::vector<ShapePair> previous;
  std::size_t refused = 0, ended_by_filters = 0;
  for (int frame = 0; frame < 20; ++frame) {
    std::vector<BodyPair> moved_apart;
    if (frame == 10) {
      for (const BodyId id : world.bodies()) {
        if (id.index % 3 == 0) world.set_filter(id, random_filter(rng));
      }
    } else {
      for (const BodyId id : world.bodies()) world.move_by(id, uniform_point(rng, -0.1, 0.1), 0.03);
    }
    world.update();
    const std::vector<BodyId> ids = world.bodies();
    std::vector<ShapePair> expected;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      for (std::size_t j = i + 1; j < ids.size(); ++j) {
        if (!overlaps(world.shape(ids[i]), world.shape(ids[j]))) continue;
        const bool pass = should_pair(world.filter(ids[i]), world.filter(ids[j])) &&
                          (world.user_id(ids[i]) + world.user_id(ids[j])) % 5 != 0;
        if (pass) {
          expected.push_back(solo_pair(world, ids[i], ids[j]));
        } else {
          ++refused;
        }
      }
    }
    ASSERT_EQ(world.overlapping(), expected) << "frame " << frame;
    expect_changes(previous, expected, world.began(), world.ended(), "frame " + std::to_string(frame));
    if (HasFatalFailure()) return;
    if (frame == 10) ended_by_filters = world.ended().size();
    EXPECT_GT(world.last_frame().filtered, 0u);
    previous = expected;
  }
  EXPECT_GT(refused, 100u);
  EXPECT_GT(ended_by_filters, 0u);  // no body moved in frame 10: those pairs ended by their filters
  std::printf("[world] filters: %zu overlapping pairs refused over 20 frames, %zu ended by a filter change\n", refused,
              ended_by_filters);
}

// Every query reports exactly the bodies brute force finds among those the query filter lets
// through.
TEST(WorldFilter, QueriesSkipWhatTheFilterRefuses) {
  Rng rng(22);
  World world;
  for (int k = 0; k < 200; ++k) {
    const Filter filter = random_filter(rng);
    world.add(random_shape(rng, 10.0), {.filter = filter});
  }
  const auto through = [](const QueryFilter& q, const Filter& f) {
    return (f.category & q.mask) && (f.mask & q.category);
  };
  for (int k = 0; k < 60; ++k) {
    const QueryFilter q{.category = std::uint64_t{1} << static_cast<int>(uniform(rng, 0, 3)),
                        .mask = static_cast<std::uint64_t>(uniform(rng, 1, 8))};
    const Shape probe = random_shape(rng, 10.0);
    const Vec2 origin = uniform_point(rng, -1, 11);
    const double angle = uniform(rng, 0, 6.3);
    const Vec2 dir(std::cos(angle), std::sin(angle));
    std::vector<BodyId> hit, near;
    std::optional<RayHit> first;
    for (const BodyId id : world.bodies()) {
      if (!through(q, world.filter(id))) continue;
      if (overlaps(probe, world.shape(id))) hit.push_back(id);
      if (distance(probe, world.shape(id)).distance <= 0.5) near.push_back(id);
      const auto r = ray_cast(world.shape(id), origin, Vec2(dir / dir.norm()), 30.0);  // as the World scales it
      if (r && !contains(world.shape(id), origin) && (!first || r->distance < first->distance))
        first = RayHit{id, world.shapes(id)[0], r->distance, r->point, r->normal};
    }
    ASSERT_EQ(world.overlapping(probe, q), hit) << k;
    ASSERT_EQ(world.within(probe, 0.5, q), near) << k;
    const auto got = world.ray_cast(origin, dir, 30.0, q);
    ASSERT_EQ(got.has_value(), first.has_value()) << k;
    if (got) ASSERT_EQ(got->distance, first->distance) << k;
  }
}

}  // namespace
}  // namespace collide2d
