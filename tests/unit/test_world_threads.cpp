// The World on several threads, and its thread pool.
#include <collide2d/world.h>
#include "engine/thread_pool.h"
#include "world_testing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace collide2d {
namespace {

using namespace testing;
// The same World on 1, 2 and 3 threads: every list it reports identical, in the same order, frame
// after frame, with static bodies, sensors, bullets, proximity and contacts (thousands of candidate
// pairs, so the narrow phase runs in more chunks than it leaves to the calling thread alone).
TEST(WorldThreads, EveryThreadCountReportsTheSame) {
  std::vector<World> worlds;
  for (const unsigned threads : {1u, 2u, 3u}) {
    worlds.emplace_back(WorldOptions{
        .fat_margin = 0.1, .proximity_margin = 0.3, .contacts = true, .speculative_margin = 0.1, .threads = threads});
  }
  Rng rng(51);
  for (int k = 0; k < 3000; ++k) {
    const Shape shape = random_shape(rng, 30.0);
    const BodyDef def{.user_id = 0, .filter = {}, .is_static = k % 5 == 0, .sensor = k % 37 == 0};
    for (World& w : worlds) {
      const BodyId id = w.add(shape, def);
      if (k % 97 == 1 && !def.is_static) w.set_continuous(id);
    }
  }
  std::size_t candidates = 0;
  for (int frame = 0; frame < 10; ++frame) {
    std::vector<std::pair<Vec2, double>> moves;
    for (const BodyId id : worlds[0].bodies()) moves.emplace_back(uniform_point(rng, -0.3, 0.3), 0.05);
    for (World& w : worlds) {
      std::size_t m = 0;
      for (const BodyId id : w.bodies()) {
        if (!w.is_static(id)) w.move_by(id, moves[m].first, moves[m].second);
        ++m;
      }
      w.update();
    }
    candidates += worlds[0].last_frame().candidates;
    for (std::size_t t = 1; t < worlds.size(); ++t) {
      const World& a = worlds[0];
      const World& b = worlds[t];
      ASSERT_EQ(a.overlapping(), b.overlapping()) << frame;
      ASSERT_EQ(a.began(), b.began()) << frame;
      ASSERT_EQ(a.ended(), b.ended()) << frame;
      ASSERT_EQ(a.sensing(), b.sensing()) << frame;
      ASSERT_EQ(a.sensor_began(), b.sensor_began()) << frame;
      ASSERT_EQ(a.last_frame().filtered, b.last_frame().filtered) << frame;
      ASSERT_EQ(a.proximity().size(), b.proximity().size()) << frame;
      for (std::size_t i = 0; i < a.proximity().size(); ++i) {
        ASSERT_TRUE(a.proximity()[i].a == b.proximity()[i].a && a.proximity()[i].b == b.proximity()[i].b);
        ASSERT_EQ(a.proximity()[i].result.distance, b.proximity()[i].result.distance);
      }
      ASSERT_EQ(a.contacts().size(), b.contacts().size()) << frame;
      for (std::size_t i = 0; i < a.contacts().size(); ++i) {
        ASSERT_TRUE(a.contacts()[i].a == b.contacts()[i].a && a.contacts()[i].b == b.contacts()[i].b);
        ASSERT_EQ(a.contacts()[i].contact.separation, b.contacts()[i].contact.separation);
        ASSERT_EQ(a.contacts()[i].contact.normal, b.contacts()[i].contact.normal);
      }
      ASSERT_EQ(a.impacts().size(), b.impacts().size()) << frame;
      for (std::size_t i = 0; i < a.impacts().size(); ++i) {
        ASSERT_TRUE(a.impacts()[i].a == b.impacts()[i].a && a.impacts()[i].b == b.impacts()[i].b);
        ASSERT_EQ(a.impacts()[i].t, b.impacts()[i].t);
      }
    }
  }
  EXPECT_GT(candidates / 10, 9000u);  // more than 32 chunks of 256 pairs
  EXPECT_GT(worlds[0].contacts().size(), 100u);
  EXPECT_GT(worlds[0].sensing().size(), 10u);
}

// The pool calls every task exactly once per run, over many runs, with 1 to 4 threads.
// threads() is the count asked for, or the hardware's where none is.
TEST(WorldThreads, SaysHowManyThreadsItRunsOn) {
  EXPECT_EQ(World({.threads = 3}).threads(), 3u);
  EXPECT_EQ(World({.threads = 1}).threads(), 1u);
  EXPECT_EQ(World().threads(), std::max(1u, std::thread::hardware_concurrency()));
}

TEST(WorldThreads, ThePoolRunsEveryTaskOnce) {
  for (const unsigned threads : {1u, 2u, 4u}) {
    detail::ThreadPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    std::vector<std::atomic<int>> calls(1000);
    for (int run = 0; run < 200; ++run)
      pool.run(run % 2 == 0 ? calls.size() : 7, [&](std::size_t k, unsigned) { ++calls[k]; });
    for (std::size_t k = 0; k < calls.size(); ++k)
      ASSERT_EQ(calls[k].load(), k < 7 ? 200 : 100) << threads << " threads, task " << k;
  }
}

// A task's worker index names its thread, the calling thread 0, so that no two tasks running at once
// share one (the World's scratch space is by worker).
TEST(WorldThreads, EachWorkerIndexIsOneThread) {
  for (const unsigned threads : {1u, 2u, 4u}) {
    detail::ThreadPool pool(threads);
    std::vector<std::atomic<int>> running(threads);
    std::vector<std::thread::id> owner(threads);
    owner[0] = std::this_thread::get_id();
    std::mutex owners;
    std::atomic<int> wrong{0};
    for (int run = 0; run < 50; ++run) {
      pool.run(500, [&](std::size_t, unsigned worker) {
        if (worker >= threads || running[worker].exchange(1) != 0) {
          ++wrong;
          return;
        }
        {
          const std::lock_guard lock(owners);
          if (owner[worker] == std::thread::id{}) owner[worker] = std::this_thread::get_id();
          if (owner[worker] != std::this_thread::get_id()) ++wrong;
        }
        running[worker].store(0);
      });
    }
    EXPECT_EQ(wrong.load(), 0) << threads << " threads";
  }
}

}  // namespace
}  // namespace collide2d
