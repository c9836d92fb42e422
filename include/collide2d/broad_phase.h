/// @file
/// Broad phase: which axis-aligned boxes overlap, kept up to date as boxes move.
///
///   SweepAndPrune sp(0.1);               // fat margin: boxes grow by 0.1 so small motions cost nothing
///   ProxyId id = sp.insert(box);         // or insert_batch(boxes): one sort for all of them
///   sp.move(id, new_box);                // remove(id) too; ids stay valid until removed
///   sp.update();                         // once per frame
///   sp.pairs();                          // every overlapping pair (a < b), sorted
///   sp.began(); sp.ended();              // pairs that started or stopped overlapping at this update
///
/// Boxes are closed: touching boxes overlap, and a zero-size box is a point. Pairs are reported on
/// the fat boxes (the tight box grown by the margin when it last left its fat box), so they are a
/// superset of the tight overlaps; a narrow phase confirms them. A box with NaN, infinity or
/// min > max is refused with std::invalid_argument, an unknown id with std::out_of_range; either
/// leaves the broad phase as it was. SweepAndPrune keeps the plane in strips across its sweep axis,
/// each sorted incrementally (docs/algorithms/broad-phase.md); BruteForceBroadPhase tests every pair, the
/// reference for tests.
#pragma once

#include <collide2d/shapes.h>

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

namespace collide2d {

/// A box's handle in a broad phase; ids of removed boxes are reused after the next update.
using ProxyId = std::uint32_t;

/// Two boxes whose fat boxes overlap.
struct ProxyPair {
  ProxyId a = 0;  ///< a < b
  ProxyId b = 0;
  friend auto operator<=>(const ProxyPair&, const ProxyPair&) = default;
};

/// Proxy storage, fat boxes and the pair sets shared by both broad phases.
class BroadPhaseBase {
 public:
  /// Boxes grow by `fat_margin` (>= 0) when they enter or leave their fat box.
  explicit BroadPhaseBase(double fat_margin = 0.0);

  /// Adds a box; it pairs from the next update.
  ProxyId insert(const Aabb& box);
  /// Adds many boxes at once (one sort at the next update instead of one merge each).
  std::vector<ProxyId> insert_batch(std::span<const Aabb> boxes);
  /// A new box for a proxy. True when it left its fat box, which then grew around it again.
  bool move(ProxyId id, const Aabb& box);
  /// Removes a proxy; its pairs end at the next update.
  void remove(ProxyId id);

  /// Whether the id names a live proxy.
  bool contains(ProxyId id) const;
  /// The proxy's fat box.
  const Aabb& fat_box(ProxyId id) const;
  /// Live proxies.
  std::size_t size() const { return live_; }
  /// The margin given to the constructor.
  double fat_margin() const { return margin_; }

  /// Every pair whose fat boxes overlap at the last update, sorted.
  const std::vector<ProxyPair>& pairs() const { return pairs_; }
  /// The pairs the last update gained and lost, sorted.
  const std::vector<ProxyPair>& began() const { return began_; }
  const std::vector<ProxyPair>& ended() const { return ended_; }

 protected:
  // The fat boxes by id; a removed proxy's is empty, its min above its max (a live one's never is).
  std::vector<Aabb> fat_;
  bool alive(ProxyId id) const { return fat_[id].min.x() <= fat_[id].max.x(); }
  std::vector<ProxyId> removed_;  // since the last update; their ids are reused after it

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

/// Runs task(k) for every k in [0, count) and returns when all are done.
/// The tasks may run at once on several threads (the World passes its thread pool's).
using ParallelFor = std::function<void(std::size_t count, const std::function<void(std::size_t)>& task)>;

/// The incremental sweep and prune over strips of the plane.
class SweepAndPrune : public BroadPhaseBase {
 public:
  using BroadPhaseBase::BroadPhaseBase;

  /// Brings pairs(), began() and ended() up to date. Each strip's sorting and sweep is a task for
  /// `parallel` (none: one after another); the pairs are the same, in the same order, however the
  /// tasks run.
  void update(const ParallelFor& parallel = {});

  /// What the last update did, for benchmarks and tests.
  struct UpdateStats {
    std::size_t swaps = 0;          ///< insertion-sort swaps over all strips
    bool full_sort = false;         ///< some strip was radix-sorted (or all were rebuilt)
    int axis = 0;                   ///< the sweep axis, 0: x, 1: y
    std::size_t strips = 0;         ///< strips holding boxes
    std::size_t axis_overlaps = 0;  ///< pairs overlapping on the sweep axis within a strip (checked across)
  };
  /// What the last update() did.
  const UpdateStats& last_update() const { return stats_; }

 private:
  // One strip, structure of arrays sorted by key along the sweep axis.
  struct Strip {
    std::vector<double> keys;
    std::vector<std::uint32_t> tags;  // id << 1 | is_max
    std::vector<double> lo;           // the box's interval across the sweep axis
    std::vector<double> hi;
    // 1 where this is the first strip the box reaches: a pair is reported in the first strip both
    // boxes reach, the one where either starts.
    std::vector<std::uint8_t> starts;
    std::vector<std::uint32_t> incoming;  // tags of boxes that entered since the last update
    void resize(std::size_t n);
  };
  // Strip indices are clamped to 32 bits (strips_of()): the range is kept for every proxy.
  struct StripRange {
    std::int32_t first = 0;
    std::int32_t last = -1;  // empty
  };
  // What one strip's task did. Each on cache lines of its own: two threads writing neighbouring
  // records would pass the lines back and forth on every pair found and every swap.
  struct alignas(64) StripWork {
    std::int32_t index = 0;
    Strip* strip = nullptr;
    std::vector<ProxyPair> found;
    std::size_t swaps = 0;
    std::size_t axis_overlaps = 0;
    bool full_sort = false;
  };

  int sweep_axis_ = 0;
  double strip_width_ = 0.0;  // 0: not laid out yet
  std::unordered_map<std::int32_t, Strip> strips_;
  std::vector<StripRange> range_;    // per proxy
  std::vector<StripWork> work_;      // per strip, kept from frame to frame
  std::vector<ProxyPair> found_;     // the strips' pairs joined; its storage is kept from frame to frame
  std::vector<std::uint32_t> ends_;  // join()'s counting sort: per proxy, where its pairs end
  UpdateStats stats_;

  bool lay_out();
  StripRange strips_of(const Aabb& box) const;
  void assign_strips();
  void load(Strip& s, std::size_t i, std::uint32_t tag, std::int32_t index) const;
  void refresh(std::int32_t index, Strip& s) const;
  bool insertion_sort(Strip& s, std::size_t budget, std::size_t& swaps) const;
  void radix_sort(Strip& s, std::int32_t index) const;
  void merge_incoming(Strip& s, std::int32_t index) const;
  void sweep(StripWork& w) const;
  void process(StripWork& w) const;
  void join(std::size_t strips);
};

/// Every pair tested: the reference the tests hold the sweep and prune to.
class BruteForceBroadPhase : public BroadPhaseBase {
 public:
  using BroadPhaseBase::BroadPhaseBase;
  /// Brings pairs(), began() and ended() up to date.
  void update();
};

}  // namespace collide2d
