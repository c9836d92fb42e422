// The box tree against a scan of every box in double precision: queries report every box that
// meets them and no box farther than float rounding, rays find the nearest hit, through random
// inserts, moves, removals and rebuilds; the height stays within the traversals' bound.
#include <collide2d/aabb_tree.h>

#include "tools/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

namespace collide2d {
namespace {

using Rng = std::mt19937_64;

using tool::uniform;
using tool::uniform_point;

Aabb random_box(Rng& rng, double side) {
  const Vec2 c = uniform_point(rng, 0, side);
  const Vec2 half = uniform_point(rng, 0.0, 2.0);
  return {c - half, c + half};
}

Aabb grown(const Aabb& b, double by) { return {b.min.array() - by, b.max.array() + by}; }

// Where the ray enters the box within [0, reach], in double precision; -1 when it misses.
double entry(const Aabb& b, const Vec2& o, const Vec2& d, double reach) {
  double t0 = 0.0, t1 = reach;
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0) {
      if (o[k] < b.min[k] || o[k] > b.max[k]) return -1.0;
      continue;
    }
    double a = (b.min[k] - o[k]) / d[k], c = (b.max[k] - o[k]) / d[k];
    if (a > c) std::swap(a, c);
    t0 = std::max(t0, a);
    t1 = std::min(t1, c);
  }
  return t0 <= t1 ? t0 : -1.0;
}

// The tree and the boxes it should hold, driven by the same calls.
struct Mirror {
  AabbTree tree;
  std::map<std::uint32_t, std::pair<AabbTree::Leaf, Aabb>> boxes;  // value -> leaf, box
  std::uint32_t next = 0;

  void insert(const Aabb& b) {
    boxes[next] = {tree.insert(b, next), b};
    ++next;
  }
  void check_query(const Aabb& q, double rounding) const {
    std::multiset<std::uint32_t> got;
    tree.query(q, [&](std::uint32_t v) { got.insert(v); });
    for (const auto& [value, entry] : boxes) {
      const bool meets = intersects(entry.second, q);
      const bool near = intersects(grown(entry.second, rounding), q);
      if (!near) EXPECT_EQ(got.count(value), 0u) << "box " << value << " is far from the query";
      if (meets) EXPECT_EQ(got.count(value), 1u) << "box " << value << " meets the query and was not reported";
    }
    EXPECT_EQ(got.size(), std::set<std::uint32_t>(got.begin(), got.end()).size()) << "a box reported twice";
  }
  // Every third box is solid and hit where the ray enters it: the walk must find the nearest such
  // hit, visit every box the ray meets before the reach drops below it, and none beyond the reach.
  void check_ray(const Vec2& o, const Vec2& d, double reach) const {
    std::set<std::uint32_t> seen;
    double nearest = reach;
    tree.ray_cast(o, d, reach, [&](std::uint32_t v, double r) {
      const double t = entry(grown(boxes.at(v).second, 1e-4), o, d, r + 1e-4);
      EXPECT_GE(t, 0.0) << "box " << v << " reported but the ray misses it within the reach";
      seen.insert(v);
      if (v % 3 != 0) return r;
      const double hit = entry(boxes.at(v).second, o, d, r);
      return hit >= 0.0 ? hit : r;
    });
    for (const auto& [value, entry_of] : boxes) {
      const double t = entry(entry_of.second, o, d, reach);
      if (value % 3 == 0 && t >= 0.0) nearest = std::min(nearest, t);
    }
    for (const auto& [value, entry_of] : boxes) {
      const double t = entry(entry_of.second, o, d, nearest);
      if (t >= 0.0 && t < nearest) EXPECT_TRUE(seen.count(value)) << "ray missed box " << value << " at " << t;
    }
    const double found = [&] {
      double best = reach;
      for (const std::uint32_t v : seen) {
        const double t = entry(boxes.at(v).second, o, d, reach);
        if (v % 3 == 0 && t >= 0.0) best = std::min(best, t);
      }
      return best;
    }();
    EXPECT_EQ(found, nearest) << "the nearest solid box was not reached";
  }
};

TEST(AabbTree, QueriesMatchAScanThroughChurn) {
  Rng rng(5);
  Mirror m;
  const double side = 60.0;
  for (int k = 0; k < 400; ++k) m.insert(random_box(rng, side));
  for (int round = 0; round < 60; ++round) {
    for (int k = 0; k < 20; ++k) {  // moves
      auto it = std::next(m.boxes.begin(), static_cast<long>(rng() % m.boxes.size()));
      it->second.second = random_box(rng, side);
      m.tree.move(it->second.first, it->second.second);
    }
    for (int k = 0; k < 8; ++k) {  // removals, then as many inserts
      auto it = std::next(m.boxes.begin(), static_cast<long>(rng() % m.boxes.size()));
      m.tree.remove(it->second.first);
      m.boxes.erase(it);
      m.insert(random_box(rng, side));
    }
    // Small moves with the shape kept: a few leaves (each walks up) or most of them (one refit).
    std::vector<std::pair<AabbTree::Leaf, Aabb>> moved;
    for (auto& [value, entry] : m.boxes) {
      if (rng() % (round % 2 == 0 ? 40 : 2) != 0) continue;
      const Vec2 shift = uniform_point(rng, -0.5, 0.5);
      entry.second = {entry.second.min + shift, entry.second.max + shift};
      moved.emplace_back(entry.first, entry.second);
    }
    m.tree.set_boxes(moved);
    if (round % 15 == 14) m.tree.rebuild();
    ASSERT_EQ(m.tree.size(), m.boxes.size());
    for (int q = 0; q < 10; ++q) m.check_query(random_box(rng, side), 1e-4);
    const Vec2 o = uniform_point(rng, -5, side + 5);
    const double a = uniform(rng, 0, 6.3);
    m.check_ray(o, Vec2(std::cos(a), std::sin(a)), uniform(rng, 0, side));
    m.check_ray(o, Vec2(0.0, 1.0), side);  // parallel to the x slabs
  }
}

// Built at once from a span, the tree is the one that inserting the boxes and rebuilding gives: the
// same height, inner perimeter, and values met by each query in the same order; a leaf is its box's
// index, which move() and remove() take.
TEST(AabbTree, BuiltAtOnceAsInsertedAndRebuilt) {
  for (const std::size_t n : {0u, 1u, 2u, 3u, 1000u}) {
    Rng rng(n);
    std::vector<Aabb> boxes;
    for (std::size_t k = 0; k < n; ++k) boxes.push_back(random_box(rng, 30));
    AabbTree inserted;
    for (std::size_t k = 0; k < n; ++k) inserted.insert(boxes[k], static_cast<std::uint32_t>(k));
    inserted.rebuild();
    AabbTree built(boxes);
    ASSERT_EQ(built.size(), n);
    EXPECT_EQ(built.height(), inserted.height()) << n;
    EXPECT_EQ(built.inner_perimeter(), inserted.inner_perimeter()) << n;
    EXPECT_EQ(built.inserted_since_rebuild(), 0u);
    for (int q = 0; q < 50; ++q) {
      const Aabb box = random_box(rng, 30);
      std::vector<std::uint32_t> a, b;
      inserted.query(box, [&a](std::uint32_t v) { a.push_back(v); });
      built.query(box, [&b](std::uint32_t v) { b.push_back(v); });
      ASSERT_EQ(a, b) << n << " query " << q;
    }
    if (n < 2) continue;
    built.move(0, {Vec2(100, 100), Vec2(101, 101)});
    std::vector<std::uint32_t> found;
    built.query({Vec2(100.5, 100.5), Vec2(100.5, 100.5)}, [&found](std::uint32_t v) { found.push_back(v); });
    EXPECT_EQ(found, std::vector<std::uint32_t>{0});
    built.remove(1);
    EXPECT_EQ(built.size(), n - 1);
  }
}

TEST(AabbTree, HeightStaysWithinTheBounds) {
  Rng rng(9);
  AabbTree tree;
  // Inserted in sorted order, the worst case for a tree that only lowers its perimeter: each new
  // box is cheapest beside the last, and a tree grown past 48 is rebuilt.
  for (std::uint32_t k = 0; k < 4096; ++k) {
    tree.insert({Vec2(k, 0), Vec2(k + 0.5, 1)}, k);
    ASSERT_LE(tree.height(), 48) << k;
  }
  tree.rebuild();
  EXPECT_EQ(tree.height(), 12);
  tree.insert(random_box(rng, 10), 4096);
  tree.rebuild();
  EXPECT_EQ(tree.height(), 13);
}

// inner_perimeter() kept through rebuild, set_box and removal: for unit boxes in a row, split at
// the median, each inner node spans boxes i..j and has half perimeter 2 (j - i) + 2; a box moved
// away and back restores the sum; with every leaf removed it is 0.
TEST(AabbTree, InnerPerimeterIsKeptExactly) {
  AabbTree tree;
  std::vector<AabbTree::Leaf> leaves;
  const auto box = [](int k, double up) { return Aabb{Vec2(2.0 * k, up), Vec2(2.0 * k + 1, up + 1)}; };
  for (int k = 0; k < 64; ++k) leaves.push_back(tree.insert(box(k, 0.0), static_cast<std::uint32_t>(k)));
  tree.rebuild();
  const auto expected = [](auto&& self, int first, int count) -> double {  // float rounding of the boxes aside
    if (count == 1) return 0.0;
    return 2.0 * (count - 1) + 2.0 + self(self, first, count / 2) + self(self, first + count / 2, count - count / 2);
  };
  EXPECT_NEAR(tree.inner_perimeter(), expected(expected, 0, 64), 1e-3);
  const double built = tree.inner_perimeter();
  tree.set_box(leaves[5], box(5, 10.0));
  EXPECT_GT(tree.inner_perimeter(), built + 10.0);
  tree.set_box(leaves[5], box(5, 0.0));
  EXPECT_EQ(tree.inner_perimeter(), built);
  for (const AabbTree::Leaf leaf : leaves) tree.remove(leaf);
  EXPECT_EQ(tree.inner_perimeter(), 0.0);
}

TEST(AabbTree, NearestHitPrunesFartherBoxes) {
  // Boxes in a row along x: a visitor that stops at each box's near side visits only the first.
  AabbTree tree;
  for (std::uint32_t k = 0; k < 100; ++k) tree.insert({Vec2(2.0 * k + 1, -1), Vec2(2.0 * k + 2, 1)}, k);
  std::vector<std::uint32_t> visited;
  tree.ray_cast(Vec2(0, 0), Vec2(1, 0), 1000.0, [&](std::uint32_t v, double) {
    visited.push_back(v);
    return 2.0 * v + 1;
  });
  EXPECT_EQ(visited, std::vector<std::uint32_t>{0});
}

TEST(AabbTree, VisitorsStopTheWalk) {
  // A 10 x 10 grid of boxes that all meet the query box and the ray's slab: a query visitor that
  // returns false and a ray visitor that returns a negative reach are each called once, where
  // visitors that go on are called for every box met.
  AabbTree tree;
  for (std::uint32_t k = 0; k < 100; ++k) {
    const Vec2 corner(k % 10, k / 10 * 0.01);
    tree.insert({corner, corner + Vec2(0.5, 0.005)}, k);
  }
  int calls = 0;
  tree.query({Vec2(0, 0), Vec2(10, 1)}, [&calls](std::uint32_t) { return ++calls < 1; });
  EXPECT_EQ(calls, 1);
  calls = 0;
  tree.query({Vec2(0, 0), Vec2(10, 1)}, [&calls](std::uint32_t) { return ++calls > 0; });
  EXPECT_EQ(calls, 100);
  calls = 0;
  tree.ray_cast(Vec2(-1, 0.002), Vec2(1, 0), 100.0, [&calls](std::uint32_t, double) { return ++calls, -1.0; });
  EXPECT_EQ(calls, 1);
  calls = 0;
  tree.ray_cast(Vec2(-1, 0.002), Vec2(1, 0), 100.0, [&calls](std::uint32_t, double r) { return ++calls, r; });
  EXPECT_EQ(calls, 10);
}

TEST(AabbTree, CoordinatesBeyondFloatStayConservative) {
  AabbTree tree;
  tree.insert({Vec2(1e45, 1e45), Vec2(2e45, 2e45)}, 0);
  tree.insert({Vec2(-1e45, -1e45), Vec2(1e45, 1e45)}, 1);
  tree.insert({Vec2(1, 1), Vec2(1 + 1e-12, 1 + 1e-12)}, 2);
  tree.rebuild();
  std::set<std::uint32_t> got;
  tree.query({Vec2(1.5e45, 1.5e45), Vec2(1.6e45, 1.6e45)}, [&](std::uint32_t v) { got.insert(v); });
  EXPECT_TRUE(got.count(0));
  got.clear();
  tree.query({Vec2(1 + 1e-12, 1 + 1e-12), Vec2(3, 3)}, [&](std::uint32_t v) { got.insert(v); });
  EXPECT_TRUE(got.count(2));  // touching in double: kept by the outward rounding
  EXPECT_TRUE(got.count(1));
}

}  // namespace
}  // namespace collide2d
