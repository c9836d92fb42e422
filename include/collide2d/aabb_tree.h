/// @file
/// A bounding-volume tree of axis-aligned boxes, for queries that should visit only the boxes they
/// meet: the boxes that overlap a box, and the boxes a ray crosses, nearest first.
///
///   AabbTree tree;
///   AabbTree::Leaf leaf = tree.insert(box, value);  // value: the caller's index, reported by queries
///   tree.move(leaf, new_box);                       // remove(leaf) too; leaves stay valid until removed
///   tree.query(box, [](std::uint32_t value) { ... });
///   tree.ray_cast(origin, unit_direction, max_distance, [](std::uint32_t value, double reach) {
///     return reach;  // or the distance of a hit nearer than reach: boxes beyond it are then skipped
///   });
///   tree.rebuild();                                 // a better tree for boxes that will stay put
///   AabbTree built(boxes);                          // or all at once: boxes[i] with value i
///
/// Boxes are stored in single precision, rounded outward and then one more step out (a node takes 36
/// bytes instead of 52, so more of the tree stays in cache; the extra step keeps a box that a ray
/// grazes in double precision inside the stored one). A query therefore reports a superset of the
/// boxes that meet it in double precision: callers test their exact shapes next.
///
/// insert() takes the sibling that least grows the tree's total perimeter: one descent that keeps
/// the cheapest node seen and stops where a lower bound shows no node below can beat it (Bittner,
/// Hapala and Havran, "Fast Insertion-Based Optimization of Bounding Volume Hierarchies", as Box2D
/// v3's b2DynamicTree). On the way back up, each ancestor swaps a child with a grandchild where that
/// lowers the perimeter of the inner node between them (Kopta et al., "Fast, Effective BVH Updates
/// for Animated Scenes"); a tree grown taller than 48 is rebuilt. rebuild() builds the inner nodes again top-down,
/// grouping the boxes by place rather than by the order they came in: each split cuts along the longer side of the
/// centres' bounds where the binned surface area heuristic (I. Wald, "On fast Construction of SAH-based Bounding
/// Volume Hierarchies", with perimeters for areas; Box2D v3's rebuild bins too) puts it, or, from depth 16 on and where
/// the bins cannot divide the boxes, at the median centre, so that the height stays at most 48. O(n log n).
/// Leaves keep their handles across rebuild().
///
/// Boxes must be valid (finite, min <= max): the tree does not check; its callers do.
#pragma once

#include <collide2d/shapes.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace collide2d {

/// A bounding-volume tree of boxes, each with a value of the caller's.
class AabbTree {
 public:
  /// A stored box's handle; valid until removed, across rebuild().
  using Leaf = std::int32_t;

  /// An empty tree.
  AabbTree() = default;
  /// A tree of the boxes (each valid), boxes[i] with value i and leaf i.
  /// Built top-down at once as rebuild() builds: the same tree as inserting them and rebuilding,
  /// without the insertions.
  explicit AabbTree(std::span<const Aabb> boxes);

  /// Stores a box (valid: finite, min <= max) with `value`, which queries report.
  Leaf insert(const Aabb& box, std::uint32_t value);
  /// A new box for a leaf, re-inserted where it now fits best.
  void move(Leaf leaf, const Aabb& box);
  /// Removes a leaf; its handle may be reused by a later insert().
  void remove(Leaf leaf);
  /// Builds the inner nodes again top-down (see the file comment).
  void rebuild();
  /// A new box for a leaf with the tree's shape kept: its ancestors' boxes are refitted up to the
  /// first that does not change. Cheaper than move() (no search, no rotation) for leaves that moved
  /// a little; the tree gets worse as they drift from where insertion or rebuild() put them, which
  /// inner_perimeter() measures.
  void set_box(Leaf leaf, const Aabb& box);
  /// set_box() for many leaves: when they are many enough that their walks up would refit more nodes
  /// than the tree has, the boxes are stored and every inner node refitted once, bottom up.
  void set_boxes(std::span<const std::pair<Leaf, Aabb>> boxes);
  /// The sum of the inner boxes' half perimeters (width plus height), kept up to date: the cost of a
  /// query grows with it.
  double inner_perimeter() const { return inner_perimeter_; }

  /// Stored boxes.
  std::size_t size() const { return leaves_; }
  /// Leaves inserted since the last rebuild() (moves do not count): how much of the tree is in the
  /// order boxes came in rather than grouped by place.
  std::size_t inserted_since_rebuild() const { return inserted_; }
  /// The longest path from the root to a leaf; -1 for an empty tree.
  int height() const { return root_ < 0 ? -1 : nodes_[root_].height; }

  /// visit(value) for each stored box that meets `box` (closed boxes: touching counts), in the
  /// order of the walk; a visit that returns a bool stops the walk by returning false.
  template <class Visit>
  void query(const Aabb& box, Visit&& visit) const;

  /// visit(value, reach) -> new reach for each stored box the ray meets, nearer boxes first.
  /// The ray is origin + t * direction, t in [0, reach]. The reach returned bounds the rest of the
  /// walk, and the nearer child of each node is walked first, so that a near hit skips the boxes
  /// behind it (the order is not sorted overall); a negative reach stops the walk. The direction
  /// need not be a unit vector: t is in its lengths.
  template <class Visit>
  void ray_cast(const Vec2& origin, const Vec2& direction, double reach, Visit&& visit) const;

 private:
  struct Node {
    float lo[2];
    float hi[2];
    std::int32_t child[2];  // -1: a leaf
    std::int32_t parent;    // -1: the root
    std::int32_t height;    // 0: a leaf, -1: free (its box then empty: see release())
    std::uint32_t value;
    bool leaf() const { return child[0] < 0; }
  };
  // The stack of a traversal never holds more than the height plus one nodes: insert() rebuilds a
  // tree taller than kMaxHeight, and the top-down build's height is at most 48 (kSahDepth, then
  // median splits).
  static constexpr int kMaxHeight = 48;
  static constexpr std::size_t kStack = kMaxHeight + 2;

  std::vector<Node> nodes_;
  std::vector<std::int32_t> free_;
  std::vector<std::int32_t> leaf_list_;  // rebuild()'s scratch, kept so that a rebuild allocates nothing
  std::int32_t root_ = -1;
  std::size_t leaves_ = 0;
  std::size_t inserted_ = 0;
  double inner_perimeter_ = 0.0;

  std::int32_t allocate();
  void release(std::int32_t node);
  void insert_leaf(std::int32_t leaf);
  std::int32_t best_sibling(const Node& leaf) const;
  void rotate(std::int32_t node);
  void remove_leaf(std::int32_t leaf);
  void replace_child(std::int32_t parent, std::int32_t from, std::int32_t to);
  void refit(std::int32_t node);
  void refit_up(std::int32_t node);
  std::int32_t build(std::int32_t* first, std::int32_t* last, int depth);
  std::int32_t* sah_split(std::int32_t* first, std::int32_t* last, int axis, double lo, double hi) const;
  double centre(std::int32_t node, int axis) const;
  void refit_below(std::int32_t node);
  // All four comparisons, then one branch: which of them fails first varies from node to node, and
  // a branch on each would often be mispredicted.
  static bool overlap(const Node& n, const float lo[2], const float hi[2]) {
    return (n.lo[0] <= hi[0]) & (lo[0] <= n.hi[0]) & (n.lo[1] <= hi[1]) & (lo[1] <= n.hi[1]);
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
      if constexpr (std::is_same_v<std::invoke_result_t<Visit&, std::uint32_t>, bool>) {
        if (!visit(n.value)) return;
      } else {
        visit(n.value);
      }
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
  // A zero component gets a huge finite inverse instead of an infinite one: 0 * inf would be NaN
  // for a box side through the origin, while 0 * 1e300 = 0 keeps the slab test branch-free and exact
  // (its slab then spans everything or nothing, as it should).
  const auto inverse = [](double d) {
    const double inv = 1.0 / d;
    return std::isfinite(inv) ? inv : std::copysign(1e300, d);
  };
  const double inv[2] = {inverse(direction.x()), inverse(direction.y())};
  // The segment's box, rounded outward, rejects most nodes with four comparisons before the slab test.
  float lo[2], hi[2];
  store({origin.cwiseMin(origin + reach * direction), origin.cwiseMax(origin + reach * direction)}, lo, hi);
  // The parameter at which the ray enters the node's box, or -1 when it misses it within reach.
  const auto entry = [&](const Node& n) {
    if (!overlap(n, lo, hi)) return -1.0;
    const double ax = (n.lo[0] - o[0]) * inv[0], bx = (n.hi[0] - o[0]) * inv[0];
    const double ay = (n.lo[1] - o[1]) * inv[1], by = (n.hi[1] - o[1]) * inv[1];
    const double t0 = std::max(std::max(0.0, std::min(ax, bx)), std::min(ay, by));
    const double t1 = std::min(std::min(reach, std::max(ax, bx)), std::max(ay, by));
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
      if (reach < 0.0) return;
      continue;
    }
    const Entry first{n.child[0], entry(nodes_[n.child[0]])};
    const Entry second{n.child[1], entry(nodes_[n.child[1]])};
    const bool in_first = first.t >= 0.0, in_second = second.t >= 0.0;
    if (in_first && in_second) {  // the nearer one on top
      const bool first_nearer = first.t <= second.t;
      stack[top++] = first_nearer ? second : first;
      stack[top++] = first_nearer ? first : second;
    } else if (in_first || in_second) {
      stack[top++] = in_first ? first : second;
    }
  }
}

}  // namespace collide2d
