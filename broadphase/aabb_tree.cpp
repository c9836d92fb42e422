#include <collide2d/aabb_tree.h>

#include "shapes/internal.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace collide2d {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kMax = std::numeric_limits<float>::max();

float perimeter(const float lo[2], const float hi[2]) { return (hi[0] - lo[0]) + (hi[1] - lo[1]); }
// For inner_perimeter(): in double, and 0 for a box that reaches past float's range (an infinite
// term would make the sum NaN for good).
double counted_perimeter(const float lo[2], const float hi[2]) {
  const double p = (static_cast<double>(hi[0]) - lo[0]) + (static_cast<double>(hi[1]) - lo[1]);
  return std::isfinite(p) ? p : 0.0;
}

// The perimeter of the union of two nodes' boxes.
template <class Node>
float joined_perimeter(const Node& p, const Node& q) {
  return (std::max(p.hi[0], q.hi[0]) - std::min(p.lo[0], q.lo[0])) +
         (std::max(p.hi[1], q.hi[1]) - std::min(p.lo[1], q.lo[1]));
}

}  // namespace

void AabbTree::store(const Aabb& box, float lo[2], float hi[2]) {
  const detail::FloatBox f = detail::outward(box);
  std::copy(f.lo, f.lo + 2, lo);
  std::copy(f.hi, f.hi + 2, hi);
}

std::int32_t AabbTree::allocate() {
  if (free_.empty()) {
    nodes_.emplace_back();
    return static_cast<std::int32_t>(nodes_.size() - 1);
  }
  const std::int32_t node = free_.back();
  free_.pop_back();
  return node;
}

// A free node's box is emptied (perimeter 0), so that refit() can account for the perimeter an inner
// node had before, whatever the node was in an earlier life.
void AabbTree::release(std::int32_t node) {
  Node& n = nodes_[node];
  if (!n.leaf()) inner_perimeter_ -= counted_perimeter(n.lo, n.hi);
  n.lo[0] = n.lo[1] = n.hi[0] = n.hi[1] = 0.0f;
  n.child[0] = n.child[1] = -1;
  n.height = -1;
  free_.push_back(node);
}

AabbTree::AabbTree(std::span<const Aabb> boxes) {
  nodes_.reserve(2 * boxes.size());
  for (const Aabb& box : boxes) {
    Node& n = nodes_.emplace_back();
    store(box, n.lo, n.hi);
    n.child[0] = n.child[1] = n.parent = -1;
    n.height = 0;
    n.value = static_cast<std::uint32_t>(leaves_++);
  }
  if (leaves_ == 1) root_ = 0;
  rebuild();
}

AabbTree::Leaf AabbTree::insert(const Aabb& box, std::uint32_t value) {
  const std::int32_t leaf = allocate();
  Node& n = nodes_[leaf];
  store(box, n.lo, n.hi);
  n.child[0] = n.child[1] = -1;
  n.height = 0;
  n.value = value;
  insert_leaf(leaf);
  ++leaves_;
  ++inserted_;
  return leaf;
}

void AabbTree::move(Leaf leaf, const Aabb& box) {
  remove_leaf(leaf);
  store(box, nodes_[leaf].lo, nodes_[leaf].hi);
  insert_leaf(leaf);
}

void AabbTree::remove(Leaf leaf) {
  remove_leaf(leaf);
  release(leaf);
  --leaves_;
}

void AabbTree::set_boxes(std::span<const std::pair<Leaf, Aabb>> boxes) {
  if (boxes.size() * static_cast<std::size_t>(std::max(1, height())) < leaves_) {
    for (const auto& [leaf, box] : boxes) set_box(leaf, box);
    return;
  }
  for (const auto& [leaf, box] : boxes) store(box, nodes_[leaf].lo, nodes_[leaf].hi);
  if (root_ >= 0) refit_below(root_);
}

void AabbTree::refit_below(std::int32_t node) {
  if (nodes_[node].leaf()) return;
  refit_below(nodes_[node].child[0]);
  refit_below(nodes_[node].child[1]);
  refit(node);
}

void AabbTree::refit(std::int32_t node) {
  Node& n = nodes_[node];
  const Node& a = nodes_[n.child[0]];
  const Node& b = nodes_[n.child[1]];
  inner_perimeter_ -= counted_perimeter(n.lo, n.hi);
  for (int k = 0; k < 2; ++k) {
    n.lo[k] = std::min(a.lo[k], b.lo[k]);
    n.hi[k] = std::max(a.hi[k], b.hi[k]);
  }
  inner_perimeter_ += counted_perimeter(n.lo, n.hi);
  n.height = 1 + std::max(a.height, b.height);
}

void AabbTree::set_box(Leaf leaf, const Aabb& box) {
  store(box, nodes_[leaf].lo, nodes_[leaf].hi);
  for (std::int32_t at = nodes_[leaf].parent; at >= 0; at = nodes_[at].parent) {
    const Node before = nodes_[at];
    refit(at);
    const Node& now = nodes_[at];
    if (now.lo[0] == before.lo[0] && now.lo[1] == before.lo[1] && now.hi[0] == before.hi[0] &&
        now.hi[1] == before.hi[1])
      break;
  }
}

void AabbTree::replace_child(std::int32_t parent, std::int32_t from, std::int32_t to) {
  nodes_[to].parent = parent;
  if (parent < 0) {
    root_ = to;
    return;
  }
  Node& p = nodes_[parent];
  p.child[p.child[0] == from ? 0 : 1] = to;
}

// The sibling whose union with the leaf costs the tree least: at each inner node, stopping there
// costs the perimeter of a new parent over it, and going down costs the child's growth plus the
// growth every ancestor inherits. On a tie (the leaf inside both children's boxes, common near the
// root) it takes child[1], as Box2D does: taking child[0], or the shorter child, leaves the inner
// nodes' total perimeter larger on uniform boxes.
std::int32_t AabbTree::best_sibling(const Node& l) const {
  const float leaf_area = perimeter(l.lo, l.hi);
  std::int32_t at = root_;
  float direct = joined_perimeter(nodes_[at], l);
  float base = perimeter(nodes_[at].lo, nodes_[at].hi);
  float inherited = 0.0f;
  std::int32_t best = at;
  float best_cost = direct;
  while (!nodes_[at].leaf()) {
    const Node& n = nodes_[at];
    if (direct + inherited < best_cost) best = at, best_cost = direct + inherited;
    inherited += direct - base;
    float lower[2], directs[2], areas[2] = {0.0f, 0.0f};
    bool leaf[2];
    for (int k = 0; k < 2; ++k) {
      const Node& c = nodes_[n.child[k]];
      directs[k] = joined_perimeter(c, l);
      leaf[k] = c.leaf();
      if (leaf[k]) {
        lower[k] = kMax;
        if (directs[k] + inherited < best_cost) best = n.child[k], best_cost = directs[k] + inherited;
      } else {
        areas[k] = perimeter(c.lo, c.hi);
        lower[k] = inherited + directs[k] + std::min(leaf_area - areas[k], 0.0f);
      }
    }
    if (leaf[0] && leaf[1]) break;
    if (best_cost <= lower[0] && best_cost <= lower[1]) break;
    if (lower[0] == lower[1] && !leaf[0]) {
      for (int k = 0; k < 2; ++k) {
        const Node& c = nodes_[n.child[k]];
        const float dx = (c.lo[0] + c.hi[0]) - (l.lo[0] + l.hi[0]), dy = (c.lo[1] + c.hi[1]) - (l.lo[1] + l.hi[1]);
        lower[k] = dx * dx + dy * dy;
      }
    }
    const int k = lower[0] < lower[1] && !leaf[0] ? 0 : 1;
    at = n.child[k];
    base = areas[k];
    direct = directs[k];
  }
  return best;
}

void AabbTree::insert_leaf(std::int32_t leaf) {
  if (root_ < 0) {
    root_ = leaf;
    nodes_[leaf].parent = -1;
    return;
  }
  const std::int32_t at = best_sibling(nodes_[leaf]);
  const std::int32_t parent = allocate();
  Node& p = nodes_[parent];
  p.child[0] = at;
  p.child[1] = leaf;
  replace_child(nodes_[at].parent, at, parent);
  nodes_[at].parent = parent;
  nodes_[leaf].parent = parent;
  refit_up(parent);
  // The rotations lower the perimeter, not the height: a tree grown past the traversals' stack is
  // built again top-down, which halves it at every level.
  if (nodes_[root_].height > kMaxHeight) rebuild();
}

void AabbTree::remove_leaf(std::int32_t leaf) {
  const std::int32_t parent = nodes_[leaf].parent;
  if (parent < 0) {
    root_ = -1;
    return;
  }
  const Node& p = nodes_[parent];
  const std::int32_t sibling = p.child[p.child[0] == leaf ? 1 : 0];
  const std::int32_t above = p.parent;
  replace_child(above, parent, sibling);
  release(parent);
  if (above >= 0) refit_up(above);
}

void AabbTree::refit_up(std::int32_t node) {
  for (std::int32_t at = node; at >= 0; at = nodes_[at].parent) {
    refit(at);
    rotate(at);
  }
}

void AabbTree::rotate(std::int32_t node) {
  const Node& a = nodes_[node];
  if (a.height < 2) return;
  float best = 0.0f;
  int best_k = -1, best_j = -1;
  for (int k = 0; k < 2; ++k) {
    const Node& small = nodes_[a.child[k]];
    const Node& big = nodes_[a.child[1 - k]];
    if (big.leaf()) continue;
    const float base = perimeter(big.lo, big.hi);
    for (int j = 0; j < 2; ++j) {
      const float delta = joined_perimeter(small, nodes_[big.child[1 - j]]) - base;
      if (delta < best) best = delta, best_k = k, best_j = j;
    }
  }
  if (best_k < 0) return;
  const std::int32_t small = a.child[best_k], big = a.child[1 - best_k], up = nodes_[big].child[best_j];
  nodes_[node].child[best_k] = up;
  nodes_[up].parent = node;
  nodes_[big].child[best_j] = small;
  nodes_[small].parent = big;
  refit(big);
  refit(node);
}

void AabbTree::rebuild() {
  inserted_ = 0;
  if (leaves_ < 2) return;
  leaf_list_.clear();
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(nodes_.size()); ++i) {
    if (nodes_[i].height > 0) release(i);
    if (nodes_[i].height == 0) leaf_list_.push_back(i);
  }
  root_ = build(leaf_list_.data(), leaf_list_.data() + leaf_list_.size(), 0);
  nodes_[root_].parent = -1;
}

// Twice the node's centre; a box unbounded both ways (coordinates beyond float's range) counts as at 0.
double AabbTree::centre(std::int32_t node, int axis) const {
  const double c = static_cast<double>(nodes_[node].lo[axis]) + nodes_[node].hi[axis];
  return std::isnan(c) ? 0.0 : c;
}

// The split of least cost, perimeter times count on each side, among the bounds of kBins bins of
// the centres along the axis, whose centres span [lo, hi]; null where no bin boundary divides the
// boxes.
std::int32_t* AabbTree::sah_split(std::int32_t* first, std::int32_t* last, int axis, double lo, double hi) const {
  constexpr int kBins = 16;
  const double extent = hi - lo;
  if (!(extent > 0.0) || !std::isfinite(extent)) return nullptr;
  const double scale = kBins / extent;
  const auto bin_of = [&](std::int32_t i) {
    return std::min(kBins - 1, static_cast<int>((centre(i, axis) - lo) * scale));
  };
  struct Bin {
    float lo[2] = {kInf, kInf};
    float hi[2] = {-kInf, -kInf};
    double count = 0;
    void join(const float (&box_lo)[2], const float (&box_hi)[2], double boxes) {
      for (int k = 0; k < 2; ++k) lo[k] = std::min(lo[k], box_lo[k]), hi[k] = std::max(hi[k], box_hi[k]);
      count += boxes;
    }
    double cost() const { return count > 0 ? counted_perimeter(lo, hi) * count : kInf; }
  };
  Bin bins[kBins];
  for (const std::int32_t* i = first; i != last; ++i) bins[bin_of(*i)].join(nodes_[*i].lo, nodes_[*i].hi, 1);
  double right_cost[kBins];  // of bins [j, kBins)
  Bin side;
  for (int j = kBins - 1; j > 0; --j) {
    side.join(bins[j].lo, bins[j].hi, bins[j].count);
    right_cost[j] = side.cost();
  }
  side = Bin{};
  double best = kInf;
  int best_bin = 0;
  for (int j = 1; j < kBins; ++j) {
    side.join(bins[j - 1].lo, bins[j - 1].hi, bins[j - 1].count);
    const double cost = side.cost() + right_cost[j];
    if (cost < best) best = cost, best_bin = j;
  }
  if (best_bin == 0) return nullptr;
  return std::partition(first, last, [&](std::int32_t i) { return bin_of(i) < best_bin; });
}

std::int32_t AabbTree::build(std::int32_t* first, std::int32_t* last, int depth) {
  if (last - first == 1) return *first;
  double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
  for (const std::int32_t* i = first; i != last; ++i) {
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], centre(*i, k));
      hi[k] = std::max(hi[k], centre(*i, k));
    }
  }
  const int axis = hi[1] - lo[1] > hi[0] - lo[0] ? 1 : 0;
  constexpr int kSahDepth = 16;
  std::int32_t* mid = depth < kSahDepth ? sah_split(first, last, axis, lo[axis], hi[axis]) : nullptr;
  if (mid == nullptr || mid == first || mid == last) {
    mid = first + (last - first) / 2;
    std::nth_element(first, mid, last,
                     [&](std::int32_t p, std::int32_t q) { return centre(p, axis) < centre(q, axis); });
  }
  const std::int32_t left = build(first, mid, depth + 1);
  const std::int32_t right = build(mid, last, depth + 1);
  const std::int32_t node = allocate();
  Node& n = nodes_[node];
  n.child[0] = left;
  n.child[1] = right;
  nodes_[left].parent = node;
  nodes_[right].parent = node;
  refit(node);
  return node;
}

}  // namespace collide2d
