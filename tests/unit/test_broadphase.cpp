// Sweep and prune against brute force: after every update, the same pairs, began and ended lists,
// on random, clustered, collinear, identical, zero-size and churning scenes.
#include <collide2d/broad_phase.h>
#include "engine/thread_pool.h"
#include "tools/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace collide2d {
namespace {

using Rng = std::mt19937_64;

using tool::uniform;
using tool::uniform_point;

Aabb box_at(const Vec2& c, const Vec2& half) { return {c - half, c + half}; }

// The broad phases driven by the same calls; ids agree because all allocate them alike. The second
// sweep and prune runs its strips on three threads and must do exactly what the first does.
struct Twin {
  SweepAndPrune sap;
  SweepAndPrune threaded;
  BruteForceBroadPhase brute;
  detail::ThreadPool pool{3};
  std::vector<ProxyId> ids;
  int updates = 0;

  explicit Twin(double margin) : sap(margin), threaded(margin), brute(margin) {}

  void insert(const Aabb& b) {
    const ProxyId id = sap.insert(b);
    ASSERT_EQ(brute.insert(b), id);
    ASSERT_EQ(threaded.insert(b), id);
    ids.push_back(id);
  }
  void insert_batch(const std::vector<Aabb>& boxes) {
    const auto a = sap.insert_batch(boxes);
    ASSERT_EQ(brute.insert_batch(boxes), a);
    ASSERT_EQ(threaded.insert_batch(boxes), a);
    ids.insert(ids.end(), a.begin(), a.end());
  }
  void move(std::size_t k, const Aabb& b) {
    sap.move(ids[k], b);
    threaded.move(ids[k], b);
    brute.move(ids[k], b);
  }
  void remove(std::size_t k) {
    sap.remove(ids[k]);
    threaded.remove(ids[k]);
    brute.remove(ids[k]);
    ids[k] = ids.back();
    ids.pop_back();
  }
  void update_and_compare(const std::string& what) {
    sap.update();
    threaded.update([this](std::size_t n, const std::function<void(std::size_t)>& task) {
      pool.run(n, [&task](std::size_t k, unsigned) { task(k); });
    });
    brute.update();
    ++updates;
    ASSERT_EQ(sap.pairs(), brute.pairs()) << what << " update " << updates;
    ASSERT_EQ(sap.began(), brute.began()) << what << " update " << updates;
    ASSERT_EQ(sap.ended(), brute.ended()) << what << " update " << updates;
    ASSERT_EQ(sap.size(), ids.size());
    ASSERT_EQ(threaded.pairs(), sap.pairs()) << what << " update " << updates;
    ASSERT_EQ(threaded.began(), sap.began()) << what << " update " << updates;
    ASSERT_EQ(threaded.last_update().swaps, sap.last_update().swaps) << what << " update " << updates;
    ASSERT_EQ(threaded.last_update().axis_overlaps, sap.last_update().axis_overlaps) << what << " update " << updates;
  }
};

TEST(SweepAndPrune, RandomMotionMatchesBruteForce) {
  for (const double margin : {0.0, 0.05}) {
    Rng rng(1);
    Twin t(margin);
    std::vector<Vec2> centre, half, velocity;
    std::vector<Aabb> boxes;
    for (int k = 0; k < 400; ++k) {
      centre.push_back(uniform_point(rng, 0, 20));
      half.push_back(uniform_point(rng, 0.05, 0.6));
      velocity.push_back(uniform_point(rng, -0.1, 0.1));
      boxes.push_back(box_at(centre.back(), half.back()));
    }
    t.insert_batch(boxes);
    for (int frame = 0; frame < 100; ++frame) {
      for (std::size_t k = 0; k < t.ids.size(); ++k) {
        centre[k] += velocity[k];
        if (frame % 25 == 24 && k % 7 == 0) centre[k] = uniform_point(rng, 0, 20);  // jumps
        t.move(k, box_at(centre[k], half[k]));
      }
      t.update_and_compare("random margin " + std::to_string(margin));
      if (HasFatalFailure()) return;
    }
    EXPECT_GT(t.sap.pairs().size(), 0u);
  }
}

// Every box jumps to a random place along the sweep axis, staying in its strips: the insertion sorts
// give up and the radix sort takes over, exactly.
TEST(SweepAndPrune, TeleportingSceneTakesTheRadixSortAndStaysExact) {
  Rng rng(2);
  Twin t(0.0);
  std::vector<Vec2> centre;
  for (int k = 0; k < 2000; ++k) centre.push_back(uniform_point(rng, 0, 50));
  std::vector<Aabb> boxes;
  for (const Vec2& c : centre) boxes.push_back(box_at(c, Vec2(0.4, 0.4)));
  t.insert_batch(boxes);
  t.update_and_compare("teleport start");
  const int axis = t.sap.last_update().axis;
  int full_sorts = 0;
  for (int frame = 0; frame < 5; ++frame) {
    for (std::size_t k = 0; k < t.ids.size(); ++k) {
      centre[k][axis] = uniform(rng, 0, 50);
      t.move(k, box_at(centre[k], Vec2(0.4, 0.4)));
    }
    t.update_and_compare("teleport");
    full_sorts += t.sap.last_update().full_sort;
  }
  EXPECT_EQ(full_sorts, 5);
  // Small coherent motion goes back to the insertion sort.
  for (std::size_t k = 0; k < t.ids.size(); ++k) {
    centre[k][axis] += 0.01;
    t.move(k, box_at(centre[k], Vec2(0.4, 0.4)));
  }
  t.update_and_compare("coherent");
  EXPECT_FALSE(t.sap.last_update().full_sort);
}

TEST(SweepAndPrune, ClusteredScene) {
  Rng rng(3);
  Twin t(0.01);
  std::vector<Vec2> centre;
  for (int k = 0; k < 600; ++k) {
    const Vec2 cluster(5.0 * (k % 4), 7.0 * (k % 3));
    centre.push_back(cluster + uniform_point(rng, -0.5, 0.5));
    t.insert(box_at(centre.back(), Vec2(0.1, 0.1)));
  }
  for (int frame = 0; frame < 30; ++frame) {
    for (std::size_t k = 0; k < t.ids.size(); ++k) {
      centre[k] += uniform_point(rng, -0.02, 0.02);
      t.move(k, box_at(centre[k], Vec2(0.1, 0.1)));
    }
    t.update_and_compare("clustered");
    if (HasFatalFailure()) return;
  }
}

// All boxes on one vertical line: the sweep must run along y to avoid n^2 axis overlaps.
TEST(SweepAndPrune, CollinearSceneSweepsAlongTheLine) {
  Twin t(0.0);
  for (int k = 0; k < 1000; ++k) t.insert(box_at(Vec2(3.0, 0.5 * k), Vec2(0.3, 0.3)));
  t.update_and_compare("collinear");
  EXPECT_EQ(t.sap.last_update().axis, 1);
  EXPECT_EQ(t.sap.pairs().size(), 999u);
  EXPECT_LT(t.sap.last_update().axis_overlaps, 2000u);
  EXPECT_LE(t.sap.last_update().strips, 2u);
  // The scene turns to lie along x: the axis follows.
  for (std::size_t k = 0; k < t.ids.size(); ++k)
    t.move(k, box_at(Vec2(0.5 * static_cast<double>(k), 3.0), Vec2(0.3, 0.3)));
  t.update_and_compare("collinear turned");
  EXPECT_EQ(t.sap.last_update().axis, 0);
  EXPECT_TRUE(t.sap.last_update().full_sort);
}

TEST(SweepAndPrune, IdenticalAndZeroSizeBoxes) {
  Twin t(0.0);
  for (int k = 0; k < 40; ++k) t.insert(box_at(Vec2(1, 1), Vec2(0.5, 0.5)));  // identical
  for (int k = 0; k < 20; ++k) t.insert({Vec2(5, 5), Vec2(5, 5)});            // coincident points
  t.insert({Vec2(5.5, 5), Vec2(5.5, 5)});                                     // a point apart
  t.insert({Vec2(4, 4), Vec2(5, 5)});                                         // touches the points
  t.insert({Vec2(-0.0, 0.0), Vec2(0.0, 0.0)});                                // -0 and +0 meet
  t.insert({Vec2(-1.0, 0.0), Vec2(-0.0, 0.0)});
  t.update_and_compare("identical and zero-size");
  const std::size_t expected = 40 * 39 / 2 + 20 * 19 / 2 + 20 + 1;
  EXPECT_EQ(t.sap.pairs().size(), expected);
}

// A box spanning every strip, boxes far out (their strip numbers clamp) and a moving crowd.
TEST(SweepAndPrune, HugeAndFarBoxes) {
  Rng rng(5);
  Twin t(0.0);
  std::vector<Vec2> centre;
  for (int k = 0; k < 200; ++k) {
    centre.push_back(uniform_point(rng, 0, 30));
    t.insert(box_at(centre.back(), Vec2(0.5, 0.5)));
  }
  t.insert({Vec2(-1, -1), Vec2(31, 31)});
  t.insert({Vec2(-1e300, -1e300), Vec2(-1e300, -1e300)});
  t.insert({Vec2(1e300, 1e300), Vec2(1e300, 1e300)});
  t.insert({Vec2(1e300, 1e300), Vec2(1e300, 1e300)});
  // Past 2e9 strips (a strip is about four boxes wide): these share the outermost strip, the last
  // two overlapping and the first apart from them.
  t.insert(box_at(Vec2(1e10, 3e10), Vec2(0.5, 0.5)));
  t.insert(box_at(Vec2(3e10, 3e10), Vec2(0.5, 0.5)));
  t.insert(box_at(Vec2(3e10 + 0.5, 3e10 + 0.5), Vec2(0.5, 0.5)));
  for (int frame = 0; frame < 20; ++frame) {
    for (std::size_t k = 0; k < 200; ++k) {
      centre[k] += uniform_point(rng, -0.3, 0.3);
      t.move(k, box_at(centre[k], Vec2(0.5, 0.5)));
    }
    t.update_and_compare("huge and far");
    if (HasFatalFailure()) return;
  }
  EXPECT_GT(t.sap.pairs().size(), 200u);
}

TEST(SweepAndPrune, HeavyChurnMatchesBruteForce) {
  Rng rng(4);
  Twin t(0.02);
  std::vector<Vec2> centre;
  const auto fresh = [&] { return box_at(uniform_point(rng, 0, 10), Vec2(0.2, 0.2)); };
  for (int k = 0; k < 300; ++k) t.insert(fresh());
  for (int frame = 0; frame < 60; ++frame) {
    for (int k = 0; k < 30 && !t.ids.empty(); ++k)
      t.remove(static_cast<std::size_t>(uniform(rng, 0, 1) * t.ids.size()));
    if (frame % 2 == 0) {  // odd frames only remove and move: the incremental path with removals
      std::vector<Aabb> batch;
      for (int k = 0; k < 25; ++k) batch.push_back(fresh());
      t.insert_batch(batch);
      for (int k = 0; k < 5; ++k) t.insert(fresh());
      for (std::size_t k = 0; k < t.ids.size(); k += 3) t.move(k, fresh());
    } else {
      for (std::size_t k = 0; k < t.ids.size(); ++k) {
        const Aabb& b = t.sap.fat_box(t.ids[k]);
        t.move(k, {b.min + Vec2(0.03, -0.02), b.max + Vec2(0.03, -0.02)});
      }
    }
    t.update_and_compare("churn");
    if (HasFatalFailure()) return;
  }
}

TEST(SweepAndPrune, BadInputIsRejectedAndChangesNothing) {
  SweepAndPrune sp(0.1);
  const ProxyId a = sp.insert(box_at(Vec2(0, 0), Vec2(1, 1)));
  const ProxyId b = sp.insert(box_at(Vec2(1.5, 0), Vec2(1, 1)));
  sp.update();
  const auto pairs = sp.pairs();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(sp.insert({Vec2(nan, 0), Vec2(1, 1)}), std::invalid_argument);
  EXPECT_THROW(sp.insert({Vec2(2, 0), Vec2(1, 1)}), std::invalid_argument);
  const std::vector<Aabb> half_bad = {box_at(Vec2(9, 9), Vec2(1, 1)), {Vec2(0, INFINITY), Vec2(1, 1)}};
  EXPECT_THROW(sp.insert_batch(half_bad), std::invalid_argument);
  EXPECT_THROW(sp.move(a, {Vec2(0, 0), Vec2(nan, 1)}), std::invalid_argument);
  EXPECT_THROW(sp.move(99, box_at(Vec2(0, 0), Vec2(1, 1))), std::out_of_range);
  sp.remove(b);
  EXPECT_THROW(sp.remove(b), std::out_of_range);
  EXPECT_THROW(SweepAndPrune(-1.0), std::invalid_argument);
  try {
    sp.insert({Vec2(2, 0), Vec2(1, 1)});
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("min.x > max.x"), std::string::npos) << e.what();
  }
  EXPECT_EQ(sp.size(), 1u);
  EXPECT_EQ(sp.fat_box(a).max.x(), 1.1);
  sp.update();
  EXPECT_TRUE(sp.pairs().empty());
  EXPECT_EQ(sp.ended(), pairs);
}

}  // namespace
}  // namespace collide2d
