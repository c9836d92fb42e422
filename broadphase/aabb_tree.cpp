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

// The next float up (or down) from a finite f; std::nextafter, but inline: boxes are stored at every
// update, and a library call each would be a noticeable part of a frame.
float step(float f, bool up) {
  if (f == 0.0f) return up ? std::numeric_limits<float>::denorm_min() : -std::numeric_limits<float>::denorm_min();
  const auto bits = detail::bit_copy<std::uint32_t>(f);
  return detail::bit_copy<float>((f > 0.0f) == up ? bits + 1 : bits - 1);
}

// A float at or below x (at or above, for up), one more step out: see the header.
float outward(double x, bool up) {
  if (x > kMax) return up ? kInf : kMax;
  if (x < -kMax) return up ? -kMax : -kInf;
  float f = static_cast<float>(x);
  if (up ? f < x : f > x) f = step(f, up);
  return step(f, up);
}

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
  for (int k = 0; k < 2; ++k) {
    lo[k] = outward(box.min[k], false);
    hi[k] = outward(box.max[k], true);
  }
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
void AabbTree::insert_leaf(std::int32_t leaf) {
  if (root_ < 0) {
    root_ = leaf;
    nodes_[leaf].parent = -1;
    return;
  }
  const Node& l = nodes_[leaf];
  std::int32_t at = root_;
  while (!nodes_[at].leaf()) {
    const Node& n = nodes_[at];
    const float joined = joined_perimeter(n, l);
    const float here = 2.0f * joined;
    const float inherited = 2.0f * (joined - perimeter(n.lo, n.hi));
    float down[2];
    for (int k = 0; k < 2; ++k) {
      const Node& c = nodes_[n.child[k]];
      down[k] = joined_perimeter(c, l) + inherited - (c.leaf() ? 0.0f : perimeter(c.lo, c.hi));
    }
    if (here < down[0] && here < down[1]) break;
    at = n.child[down[0] < down[1] ? 0 : 1];
  }
  const std::int32_t parent = allocate();
  Node& p = nodes_[parent];
  p.child[0] = at;
  p.child[1] = leaf;
  replace_child(nodes_[at].parent, at, parent);
  nodes_[at].parent = parent;
  nodes_[leaf].parent = parent;
  refit_up(parent);
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
    at = balance(at);
    refit(at);
  }
}

// An AVL rotation at `node` when one child is taller by 2 or more: that child takes its place, with
// `node` and its own taller child below it, and its shorter child moved under `node`. Returns the
// subtree's root, refitted.
std::int32_t AabbTree::balance(std::int32_t node) {
  Node& a = nodes_[node];
  if (a.leaf()) return node;
  const int tall = nodes_[a.child[1]].height > nodes_[a.child[0]].height ? 1 : 0;
  const std::int32_t up = a.child[tall];
  if (nodes_[up].height - nodes_[a.child[1 - tall]].height < 2) return node;
  Node& u = nodes_[up];
  const int u_tall = nodes_[u.child[0]].height > nodes_[u.child[1]].height ? 0 : 1;
  const std::int32_t keep = u.child[u_tall];
  const std::int32_t give = u.child[1 - u_tall];
  replace_child(a.parent, node, up);
  u.child[0] = node;
  u.child[1] = keep;
  a.parent = up;
  a.child[tall] = give;
  nodes_[give].parent = node;
  refit(node);
  refit(up);
  return up;
}

void AabbTree::rebuild() {
  inserted_ = 0;
  if (leaves_ < 2) return;
  leaf_list_.clear();
  for (std::int32_t i = 0; i < static_cast<std::int32_t>(nodes_.size()); ++i) {
    if (nodes_[i].height > 0) release(i);
    if (nodes_[i].height == 0) leaf_list_.push_back(i);
  }
  root_ = build(leaf_list_.data(), leaf_list_.data() + leaf_list_.size());
  nodes_[root_].parent = -1;
}

std::int32_t AabbTree::build(std::int32_t* first, std::int32_t* last) {
  if (last - first == 1) return *first;
  double lo[2] = {kInf, kInf}, hi[2] = {-kInf, -kInf};
  // Twice the centre; a box unbounded both ways (coordinates beyond float's range) counts as at 0.
  const auto centre = [this](std::int32_t i, int k) {
    const double c = static_cast<double>(nodes_[i].lo[k]) + nodes_[i].hi[k];
    return std::isnan(c) ? 0.0 : c;
  };
  for (const std::int32_t* i = first; i != last; ++i) {
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], centre(*i, k));
      hi[k] = std::max(hi[k], centre(*i, k));
    }
  }
  const int axis = hi[1] - lo[1] > hi[0] - lo[0] ? 1 : 0;
  std::int32_t* mid = first + (last - first) / 2;
  std::nth_element(first, mid, last, [&](std::int32_t p, std::int32_t q) { return centre(p, axis) < centre(q, axis); });
  const std::int32_t left = build(first, mid);
  const std::int32_t right = build(mid, last);
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
