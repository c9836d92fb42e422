// A bounding-volume tree of axis-aligned boxes, for queries that should visit only the boxes they
// meet: the boxes that overlap a box, and the boxes a ray crosses, nearest first.
//
//   AabbTree tree;
//   AabbTree::Leaf leaf = tree.insert(box, value);  // value: the caller's index, reported by queries
//   tree.move(leaf, new_box);                       // remove(leaf) too; leaves stay valid until removed
//   tree.query(box, [](std::uint32_t value) { ... });
//   tree.ray_cast(origin, unit_direction, max_distance, [](std::uint32_t value, double reach) {
//     return reach;  // or the distance of a hit nearer than reach: boxes beyond it are then skipped
//   });
//   tree.rebuild();                                 // a better tree for boxes that will stay put
//
// Boxes are stored in single precision, rounded outward and then one more step out (a node takes 36
// bytes instead of 52, so more of the tree stays in cache; the extra step keeps a box that a ray
// grazes in double precision inside the stored one). A query therefore reports a superset of the
// boxes that meet it in double precision: callers test their exact shapes next.
//
// insert() descends to the sibling that least grows the tree's total perimeter (Box2D's
// b2DynamicTree, after Goldsmith and Salmon) and AVL rotations on the way back up keep the height
// within 1.44 log2(n) + 2. rebuild() builds the inner nodes again top-down, splitting the boxes at the
// median of their centres along the longer side of the centres' bounds: O(n log n), a height of
// ceil(log2 n), and boxes grouped by place rather than by the order they came in. Leaves keep their
// handles across rebuild().
//
// Boxes must be valid (finite, min <= max): the tree does not check; its callers do.
#pragma once

#include "shapes/shapes.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace collide2d {

class AabbTree {
 public:
  using Leaf = std::int32_t;

  Leaf insert(const Aabb& box, std::uint32_t value);
  void move(Leaf leaf, const Aabb& box);
  void remove(Leaf leaf);
  void rebuild();
  void clear();

  std::size_t size() const { return leaves_; }
  int height() const { return root_ < 0 ? -1 : nodes_[root_].height; }

  // visit(value) for each stored box that meets `box` (closed boxes: touching counts).
  template <class Visit>
  void query(const Aabb& box, Visit&& visit) const;

  // visit(value, reach) -> new reach, for each stored box the ray origin + t * direction, t in
  // [0, reach], meets. The reach returned bounds the rest of the walk, and the nearer child of each
  // node is walked first, so that a near hit skips the boxes behind it (the order is not sorted
  // overall). The direction need not be a unit vector: t is in its lengths.
  template <class Visit>
  void ray_cast(const Vec2& origin, const Vec2& direction, double reach, Visit&& visit) const;

 private:
  struct Node {
    float lo[2];
    float hi[2];
    std::int32_t child[2];  // -1: a leaf
    std::int32_t parent;    // -1: the root
    std::int32_t height;    // 0: a leaf, -1: free
    std::uint32_t value;
    bool leaf() const { return child[0] < 0; }
  };
  // The stack of a traversal never holds more than the height plus one nodes, and the AVL bound
  // keeps the height under 1.44 log2(2^32) + 2 < 48; the top-down build's is at most 32.
  static constexpr std::size_t kStack = 64;

  std::vector<Node> nodes_;
  std::vector<std::int32_t> free_;
  std::int32_t root_ = -1;
  std::size_t leaves_ = 0;

  std::int32_t allocate();
  void release(std::int32_t node);
  void insert_leaf(std::int32_t leaf);
  void remove_leaf(std::int32_t leaf);
  void replace_child(std::int32_t parent, std::int32_t from, std::int32_t to);
  void refit(std::int32_t node);
  std::int32_t balance(std::int32_t node);
  void refit_up(std::int32_t node);
  std::int32_t build(std::int32_t* first, std::int32_t* last);
  static bool overlap(const Node& n, const float lo[2], const float hi[2]) {
    return n.lo[0] <= hi[0] && lo[0] <= n.hi[0] && n.lo[1] <= hi[1] && lo[1] <= n.hi[1];
  }
  static void store(const Aabb& box, float lo[2], float hi[2]);
};

template <class Visit>
void AabbTree::query(const Aabb& box, Visit&& visit) const {
  if (root_ < 0) return;
  float lo[2], hi[2];
  store(box, lo, hi);
  std::array<std::int32_t, kStack> stack;
  std::size_t top = 0;
  stack[top++] = root_;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (!overlap(n, lo, hi)) continue;
    if (n.leaf()) {
      visit(n.value);
    } else {
      stack[top++] = n.child[0];
      stack[top++] = n.child[1];
    }
  }
}

template <class Visit>
void AabbTree::ray_cast(const Vec2& origin, const Vec2& direction, double reach, Visit&& visit) const {
  if (root_ < 0) return;
  const double o[2] = {origin.x(), origin.y()};
  const double d[2] = {direction.x(), direction.y()};
  const double inv[2] = {1.0 / d[0], 1.0 / d[1]};
  // The parameter at which the ray enters the node's box, or -1 when it misses it within reach.
  const auto entry = [&](const Node& n) {
    double t0 = 0.0, t1 = reach;
    for (int k = 0; k < 2; ++k) {
      if (d[k] == 0.0) {  // parallel to the slab: 0 * inf would be NaN
        if (o[k] < n.lo[k] || o[k] > n.hi[k]) return -1.0;
        continue;
      }
      double a = (n.lo[k] - o[k]) * inv[k], b = (n.hi[k] - o[k]) * inv[k];
      if (a > b) std::swap(a, b);
      t0 = a > t0 ? a : t0;
      t1 = b < t1 ? b : t1;
    }
    return t0 <= t1 ? t0 : -1.0;
  };
  struct Entry {
    std::int32_t node;
    double t;
  };
  std::array<Entry, kStack> stack;
  std::size_t top = 0;
  const double t_root = entry(nodes_[root_]);
  if (t_root < 0.0) return;
  stack[top++] = {root_, t_root};
  while (top > 0) {
    const Entry e = stack[--top];
    if (e.t > reach) continue;  // a nearer hit came after it was pushed
    const Node& n = nodes_[e.node];
    if (n.leaf()) {
      reach = visit(n.value, reach);
      continue;
    }
    const Entry near{n.child[0], entry(nodes_[n.child[0]])};
    const Entry far{n.child[1], entry(nodes_[n.child[1]])};
    const bool swap = near.t >= 0.0 && far.t >= 0.0 && far.t < near.t;
    for (const Entry& c : swap ? std::array{near, far} : std::array{far, near}) {  // nearer popped first
      if (c.t >= 0.0) stack[top++] = c;
    }
  }
}

}  // namespace collide2d
