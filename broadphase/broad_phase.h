// Broad phase: which axis-aligned boxes overlap, kept up to date as boxes move.
//
//   SweepAndPrune sp(0.1);               // fat margin: boxes grow by 0.1 so small motions cost nothing
//   ProxyId id = sp.insert(box);         // or insert_batch(boxes): one sort for all of them
//   sp.move(id, new_box);                // remove(id) too; ids stay valid until removed
//   sp.update();                         // once per frame
//   sp.pairs();                          // every overlapping pair (a < b), sorted
//   sp.began(); sp.ended();              // pairs that started or stopped overlapping at this update
//
// Boxes are closed: touching boxes overlap, and a zero-size box is a point. Pairs are reported on the
// fat boxes (the tight box grown by the margin when it last left its fat box), so they are a superset
// of the tight overlaps; a narrow phase confirms them. A box with NaN, infinity or min > max is
// rejected with std::invalid_argument, an unknown id with std::out_of_range; either leaves the broad
// phase as it was.
//
// SweepAndPrune keeps the box endpoints along both axes sorted from frame to frame (structure of
// arrays: keys and tags apart) and repairs the order by insertion sort, near linear when motion is
// coherent. The swaps themselves maintain the pair set (Baraff; Cohen et al., I-COLLIDE): when a
// box's min passes another's max, the two may have begun to overlap (both axes are checked); when a
// max passes a min, they have ended. A frame of coherent motion thus costs O(n + swaps), whatever
// the density along either axis. When the repair would exceed a budget of swaps (most boxes moved
// far), each axis is sorted once instead by an LSD radix sort, and the pair set is rebuilt by one
// sweep, so a scene that jumps costs O(n + pairs on the sweep axis) rather than O(n^2); frames
// with inserted boxes are swept too (their endpoints are sorted among themselves and merged in).
// The sweep runs along the axis where the box centres spread more (their variance), re-chosen when
// the other axis spreads 1.5 times more, so that a scene laid out along a line sweeps along it.
//
// BruteForceBroadPhase has the same interface and tests every pair: the reference for tests.
#pragma once

#include "shapes/shapes.h"

#include <compare>
#include <cstddef>
#include <cstdint>
#include <span>
#include <unordered_set>
#include <vector>

namespace collide2d {

using ProxyId = std::uint32_t;

struct ProxyPair {
  ProxyId a = 0;  // a < b
  ProxyId b = 0;
  friend auto operator<=>(const ProxyPair&, const ProxyPair&) = default;
};

// Proxy storage, fat boxes and the pair sets shared by both broad phases.
class BroadPhaseBase {
 public:
  explicit BroadPhaseBase(double fat_margin = 0.0);

  ProxyId insert(const Aabb& box);
  std::vector<ProxyId> insert_batch(std::span<const Aabb> boxes);
  void move(ProxyId id, const Aabb& box);
  void remove(ProxyId id);

  bool contains(ProxyId id) const;
  const Aabb& fat_box(ProxyId id) const;
  std::size_t size() const { return live_; }
  double fat_margin() const { return margin_; }

  const std::vector<ProxyPair>& pairs() const { return pairs_; }
  const std::vector<ProxyPair>& began() const { return began_; }
  const std::vector<ProxyPair>& ended() const { return ended_; }

 protected:
  struct Proxy {
    Aabb fat;
    bool alive = false;
  };
  std::vector<Proxy> proxies_;
  std::vector<ProxyId> inserted_;  // since the last update
  std::vector<ProxyId> removed_;   // since the last update; their ids are reused after it

  // Installs the new pair set (sorted) and derives began/ended; recycles removed ids.
  void finish_update(std::vector<ProxyPair>&& now);

 private:
  double margin_;
  std::size_t live_ = 0;
  std::vector<ProxyId> free_;
  std::vector<ProxyPair> pairs_;
  std::vector<ProxyPair> began_;
  std::vector<ProxyPair> ended_;

  ProxyId take_id();
  void check(ProxyId id) const;
};

class SweepAndPrune : public BroadPhaseBase {
 public:
  using BroadPhaseBase::BroadPhaseBase;

  void update();

  // What the last update did, for benchmarks and tests.
  struct UpdateStats {
    std::size_t swaps = 0;          // insertion-sort swaps, both axes
    bool full_sort = false;         // the radix sort replaced the insertion sort
    bool swept = false;             // the pair set was rebuilt by a sweep (inserts, full sorts)
    int axis = 0;                   // the sweep axis, 0: x, 1: y
    std::size_t axis_overlaps = 0;  // in a sweep: pairs overlapping on the sweep axis
  };
  const UpdateStats& last_update() const { return stats_; }

 private:
  struct Endpoints {
    std::vector<double> keys;         // coordinates along the axis, sorted
    std::vector<std::uint32_t> tags;  // id << 1 | is_max, parallel to keys
  };
  Endpoints axes_[2];
  int sweep_axis_ = 0;
  std::unordered_set<std::uint64_t> overlapping_;  // a << 32 | b, kept by the insertion sorts
  std::vector<std::uint32_t> active_slot_;        // sweep scratch: a proxy's place in the active list
  UpdateStats stats_;

  double key_of(std::uint32_t tag, int axis) const;
  void choose_axis();
  void refresh_keys(int axis);
  bool insertion_sort(int axis, std::size_t budget);
  void radix_sort(int axis);
  void merge_inserted(int axis);
  std::vector<ProxyPair> sweep();
};

class BruteForceBroadPhase : public BroadPhaseBase {
 public:
  using BroadPhaseBase::BroadPhaseBase;
  void update();
};

}  // namespace collide2d
