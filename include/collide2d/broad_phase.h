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
// SweepAndPrune cuts the plane into strips across the sweep axis (as wide as four mean boxes) and
// keeps, for each strip, the endpoints of the boxes that reach into it sorted along the sweep axis
// from frame to frame (structure of arrays: keys, tags, and each box's interval across the strip).
// Insertion sort repairs each strip, near linear when motion is coherent; past a budget of swaps
// (most boxes jumped) the strip is radix-sorted instead (LSD on the key bytes), so a scene that
// jumps costs O(n) sorting rather than O(n^2). Boxes entering a strip are sorted among themselves
// and merged in. A sweep over each strip then lists its pairs; a pair met in several strips is
// reported only in the first strip both boxes reach. Cutting into strips is what keeps the cost
// near linear: in one list per axis, as in classic sweep and prune, the endpoints get denser as a
// 2D scene grows (about sqrt(n) boxes stack over each point of the axis), and so do the swaps and
// the pairs to check. Pairs that began and ended are the difference from the previous frame.
// The sweep axis is the one along which the box centres spread more (their variance), re-chosen
// when the other axis spreads 1.5 times more, so that a scene laid out along a line sweeps along
// it; the strips are rebuilt when the axis or the mean box size changes by 2x.
//
// BruteForceBroadPhase has the same interface and tests every pair: the reference for tests.
#pragma once

#include <collide2d/shapes.h>

#include <algorithm>
#include <compare>
#include <functional>
#include <iterator>
#include <cstddef>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

namespace collide2d {

using ProxyId = std::uint32_t;

// A sorted pair list becomes `now` (sorted too); began and ended get what it gained and lost. The
// broad phases keep their pairs so, and the World its overlapping and sensor pairs. The lists trade
// places: `now` is left holding the old pairs, whose storage the caller's next frame fills again, so
// that a steady frame allocates nothing.
template <class Pair>
void replace_pairs(std::vector<Pair>& pairs, std::vector<Pair>& now, std::vector<Pair>& began, std::vector<Pair>& ended) {
  began.clear();
  ended.clear();
  std::set_difference(now.begin(), now.end(), pairs.begin(), pairs.end(), std::back_inserter(began));
  std::set_difference(pairs.begin(), pairs.end(), now.begin(), now.end(), std::back_inserter(ended));
  pairs.swap(now);
}

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
  // True when the box left its fat box, which then grew around it again.
  bool move(ProxyId id, const Aabb& box);
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

  // Installs the new pair set (sorted) and derives began/ended; recycles removed ids. `now` is left
  // holding the old pairs (replace_pairs).
  void finish_update(std::vector<ProxyPair>& now);

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

// Runs task(k) for every k in [0, count), possibly at once on several threads, and returns when all
// are done (the World passes its thread pool's).
using ParallelFor = std::function<void(std::size_t count, const std::function<void(std::size_t)>& task)>;

class SweepAndPrune : public BroadPhaseBase {
 public:
  using BroadPhaseBase::BroadPhaseBase;

  // The strips are independent once boxes are assigned to them: each one's sorting and sweep is a
  // task for `parallel`; the pairs are the same, in the same order, however the tasks run.
  void update(const ParallelFor& parallel = {});

  // What the last update did, for benchmarks and tests.
  struct UpdateStats {
    std::size_t swaps = 0;          // insertion-sort swaps over all strips
    bool full_sort = false;         // some strip was radix-sorted (or all were rebuilt)
    int axis = 0;                   // the sweep axis, 0: x, 1: y
    std::size_t strips = 0;         // strips holding boxes
    std::size_t axis_overlaps = 0;  // pairs overlapping on the sweep axis within a strip (checked across)
  };
  const UpdateStats& last_update() const { return stats_; }

 private:
  // One strip, structure of arrays sorted by key along the sweep axis.
  struct Strip {
    std::vector<double> keys;
    std::vector<std::uint32_t> tags;  // id << 1 | is_max
    std::vector<double> lo;           // the box's interval across the sweep axis
    std::vector<double> hi;
    std::vector<std::int64_t> first;  // the first strip the box reaches (where its pairs are reported)
    std::vector<std::uint32_t> incoming;  // tags of boxes that entered since the last update
    void resize(std::size_t n);
  };
  struct StripRange {
    std::int64_t first = 0;
    std::int64_t last = -1;  // empty
  };
  // What one strip's task did.
  struct StripWork {
    std::int64_t index = 0;
    Strip* strip = nullptr;
    std::vector<ProxyPair> found;
    std::size_t swaps = 0;
    std::size_t axis_overlaps = 0;
    bool full_sort = false;
  };

  int sweep_axis_ = 0;
  double strip_width_ = 0.0;  // 0: not laid out yet
  std::unordered_map<std::int64_t, Strip> strips_;
  std::vector<StripRange> range_;  // per proxy
  std::vector<StripWork> work_;    // per strip, kept from frame to frame
  std::vector<ProxyPair> found_;   // the strips' pairs joined; its storage is kept from frame to frame
  UpdateStats stats_;

  bool lay_out();
  StripRange strips_of(const Aabb& box) const;
  void assign_strips();
  void load(Strip& s, std::size_t i, std::uint32_t tag) const;
  void refresh(std::int64_t index, Strip& s) const;
  bool insertion_sort(Strip& s, std::size_t budget, std::size_t& swaps) const;
  void radix_sort(Strip& s) const;
  void merge_incoming(Strip& s) const;
  void sweep(StripWork& w) const;
  void process(StripWork& w) const;
};

class BruteForceBroadPhase : public BroadPhaseBase {
 public:
  using BroadPhaseBase::BroadPhaseBase;
  void update();
};

}  // namespace collide2d
