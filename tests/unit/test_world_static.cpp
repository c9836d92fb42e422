// Static bodies and sensors: never paired with each other, found by queries through their tree.
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
// A level: static bodies (overlapping each other, never paired), moving bodies and sensors of both
// kinds, with filters. Over frames of motion, static churn, a static body moved, bodies changing
// kind, a filter change and moving churn, everything the World reports matches all pairs under the
// same rules, and the began and ended lists (solid and sensor) are the differences from the frame
// before. A frame where nothing moves looks up no static neighbours.
TEST(WorldStatic, PairsMatchAllPairsWithStaticsAndSensors) {
  for (const double margin : {0.0, 0.25}) {
    Rng rng(31);
    World world({.fat_margin = 0.1, .proximity_margin = margin});
    const auto add = [&](bool is_static, bool sensor) {
      const Filter f = uniform(rng, 0, 1) < 0.2 ? random_filter(rng) : Filter{};
      return world.add(random_shape(rng, 15.0), {.user_id = 0, .filter = f, .is_static = is_static, .sensor = sensor});
    };
    for (int k = 0; k < 150; ++k) add(true, k % 15 == 0);
    for (int k = 0; k < 120; ++k) add(false, k % 20 == 0);
    std::vector<ShapePair> previous;
    std::vector<SensorPair> previous_sensing;
    std::size_t static_overlaps = 0, sensor_began = 0, sensor_ended = 0;
    for (int frame = 0; frame < 30; ++frame) {
      const std::vector<BodyId> ids = world.bodies();
      if (frame != 29) {
        for (const BodyId id : ids) {
          if (!world.is_static(id)) world.move_by(id, uniform_point(rng, -0.15, 0.15), 0.05);
        }
      }
      if (frame == 7) {
        for (std::size_t k = 0; k < ids.size(); k += 11) {
          if (world.is_static(ids[k])) world.remove(ids[k]);
        }
        for (int k = 0; k < 12; ++k) add(true, k % 4 == 0);
      }
      if (frame == 12) {
        for (std::size_t k = 1; k < ids.size(); k += 13) {
          if (world.is_static(ids[k])) world.move_by(ids[k], Vec2(0.7, -0.4), 0.3);
        }
      }
      if (frame == 15) {
        for (std::size_t k = 2; k < ids.size(); k += 9) world.set_static(ids[k], !world.is_static(ids[k]));
      }
      if (frame == 20) {
        for (std::size_t k = 3; k < ids.size(); k += 7) world.set_filter(ids[k], random_filter(rng));
      }
      if (frame == 25) {
        for (std::size_t k = 4; k < ids.size(); k += 10) {
          if (!world.is_static(ids[k])) world.remove(ids[k]);
        }
        for (int k = 0; k < 10; ++k) add(false, k % 5 == 0);
      }
      world.update();
      const std::string what = "margin " + std::to_string(margin) + ", frame " + std::to_string(frame);
      expect_matches_all_pairs(world, margin, what);
      if (HasFatalFailure()) return;
      expect_changes(previous, world.overlapping(), world.began(), world.ended(), what);
      expect_changes(previous_sensing, world.sensing(), world.sensor_began(), world.sensor_ended(), what);
      if (HasFatalFailure()) return;
      if (frame == 29) EXPECT_EQ(world.last_frame().requeried, 0u) << "nothing moved, nothing static changed";
      previous = world.overlapping();
      previous_sensing = world.sensing();
      sensor_began += world.sensor_began().size();
      sensor_ended += world.sensor_ended().size();
    }
    const std::vector<BodyId> ids = world.bodies();
    for (std::size_t i = 0; i < ids.size(); ++i) {
      for (std::size_t j = i + 1; j < ids.size(); ++j) {
        const bool both = world.is_static(ids[i]) && world.is_static(ids[j]);
        if (both && overlaps(world.shape(ids[i]), world.shape(ids[j]))) ++static_overlaps;
      }
    }
    EXPECT_GT(static_overlaps, 10u);  // overlapping static pairs exist and were left out
    EXPECT_GT(sensor_began, 10u);
    EXPECT_GT(sensor_ended, 5u);
    EXPECT_GT(world.overlapping().size(), 20u);
    std::printf("[world] statics: %zu overlapping static pairs left out, %zu sensor entries, %zu exits\n",
                static_overlaps, sensor_began, sensor_ended);
  }
}

// Queries through the trees: the solid bodies, moving and static (never sensors), that a scan of
// every body finds, also right after bodies moved (no update in between).
TEST(WorldStatic, QueriesSeeSolidBodiesOfBothKinds) {
  Rng rng(32);
  World world({.fat_margin = 0.1});
  for (int k = 0; k < 450; ++k) {
    const Filter filter = random_filter(rng);
    world.add(random_shape(rng, 12.0),
              {.user_id = 0, .filter = filter, .is_static = k % 3 != 0, .sensor = k % 10 == 0});
  }
  world.update();
  const auto through = [](const QueryFilter& q, const Filter& f) {
    return (f.category & q.mask) && (f.mask & q.category);
  };
  for (int k = 0; k < 80; ++k) {
    if (k == 40) {
      for (const BodyId id : world.bodies()) world.move_by(id, uniform_point(rng, -0.5, 0.5), 0.2);
    }
    const QueryFilter q =
        k % 2 == 0 ? QueryFilter{} : QueryFilter{.category = 1, .mask = static_cast<std::uint64_t>(uniform(rng, 1, 8))};
    const Shape probe = random_shape(rng, 12.0);
    const Vec2 point = uniform_point(rng, 0, 12);
    const Aabb box{point, point + uniform_point(rng, 0, 3)};
    const Vec2 origin = uniform_point(rng, -1, 13);
    const double angle = uniform(rng, 0, 6.3);
    const Vec2 dir(2.0 * std::cos(angle), 2.0 * std::sin(angle));
    const Vec2 unit = dir / dir.norm();
    const Vec2 shift = uniform_point(rng, -4, 4);
    std::vector<BodyId> hit, near, in_box;
    std::vector<RayHit> all;
    std::optional<BodyCastHit> cast;
    for (const BodyId id : world.bodies()) {
      if (world.is_sensor(id) || !through(q, world.filter(id))) continue;
      const Shape& s = world.shape(id);
      if (overlaps(probe, s)) hit.push_back(id);
      if (distance(probe, s).distance <= 0.4) near.push_back(id);
      if (overlaps(s, box)) in_box.push_back(id);
      const auto r = contains(s, origin) ? std::nullopt : ray_cast(s, origin, unit, 15.0);
      const ShapeId only = world.shapes(id)[0];
      if (r) all.push_back({id, only, r->distance, r->point, r->normal});
      const auto c = shape_cast(probe, shift, s);
      if (c && (!cast || c->fraction < cast->fraction)) cast = BodyCastHit{id, only, c->fraction, c->point, c->normal};
    }
    std::stable_sort(all.begin(), all.end(), [](const RayHit& a, const RayHit& b) { return a.distance < b.distance; });
    ASSERT_EQ(world.overlapping(probe, q), hit) << k;
    ASSERT_EQ(world.within(probe, 0.4, q), near) << k;
    ASSERT_EQ(world.overlapping(box, q), in_box) << k;
    const std::vector<RayHit> got = world.ray_cast_all(origin, dir, 15.0, q);
    ASSERT_EQ(got.size(), all.size()) << k;
    for (std::size_t i = 0; i < all.size(); ++i) {
      ASSERT_EQ(got[i].body, all[i].body) << k;
      ASSERT_EQ(got[i].distance, all[i].distance) << k;
    }
    const auto first = world.ray_cast(origin, dir, 15.0, q);
    ASSERT_EQ(first.has_value(), !all.empty()) << k;
    if (first) ASSERT_EQ(first->body, all.front().body) << k;
    const auto got_cast = world.cast(probe, shift, q);
    ASSERT_EQ(got_cast.has_value(), cast.has_value()) << k;
    if (got_cast) ASSERT_EQ(got_cast->body, cast->body) << k;
  }
}

TEST(WorldStatic, StaticBodiesCannotBeContinuous) {
  World world;
  const BodyId wall =
      world.add(Rect{{0, 0}, {1, 5}, 0}, {.user_id = 4, .filter = {}, .is_static = true, .sensor = false});
  const BodyId ball = world.add(Circle{{0.5, 0}, 1});
  world.update();
  const auto pairs = world.overlapping();
  try {
    world.set_continuous(wall);
    ADD_FAILURE() << "a static body was made continuous";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "body 0 is static: only moving bodies can be continuous");
  }
  world.set_continuous(ball);
  world.set_static(ball, true);  // stops being continuous
  world.set_pose(ball, Vec2(0.5, 0.2), 0.0);
  world.update();
  EXPECT_TRUE(world.impacts().empty());
  EXPECT_TRUE(world.overlapping().empty());  // two static bodies
  world.set_static(ball, false);
  world.update();
  EXPECT_EQ(world.overlapping().size(), pairs.size());
  EXPECT_THROW(world.set_static(BodyId{9, 1}, true), std::out_of_range);
}

}  // namespace
}  // namespace collide2d
