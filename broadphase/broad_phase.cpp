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

#include <collide2d/broad_phase.h>

#include "broadphase/internal.h"
#include "shapes/internal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace collide2d {
namespace {

// A removed proxy's fat box: empty, its min above its max.
const Aabb kRemoved{Vec2::Constant(std::numeric_limits<double>::infinity()),
                    Vec2::Constant(-std::numeric_limits<double>::infinity())};

void validate_box(const Aabb& box) {
  const char* names[] = {"x", "y"};
  for (int k = 0; k < 2; ++k) {
    if (!std::isfinite(box.min[k]) || !std::isfinite(box.max[k])) {
      throw std::invalid_argument(std::string("box ") + names[k] + " bounds must be finite");
    }
    if (box.min[k] > box.max[k]) {
      throw std::invalid_argument(std::string("box min.") + names[k] + " > max." + names[k] + " (" +
                                  detail::shortest(box.min[k]) + " > " + detail::shortest(box.max[k]) + ')');
    }
  }
}

// Endpoint tags: proxy id << 1, low bit set for a box's max end. At equal keys a min sorts first, so
// touching boxes overlap.
constexpr std::uint32_t tag(ProxyId id, bool is_max) { return id << 1 | static_cast<std::uint32_t>(is_max); }
constexpr ProxyId id_of(std::uint32_t t) { return t >> 1; }
constexpr bool is_max(std::uint32_t t) { return (t & 1u) != 0; }

bool before(double ka, std::uint32_t ta, double kb, std::uint32_t tb) {
  return ka < kb || (ka == kb && !is_max(ta) && is_max(tb));
}

// An unsigned key with the order of the doubles (-0.0 is folded into +0.0 by the caller).
std::uint64_t ordered_bits(double x) {
  const auto u = detail::bit_copy<std::uint64_t>(x);
  return (u >> 63) != 0 ? ~u : u | (std::uint64_t{1} << 63);
}

}  // namespace

BroadPhaseBase::BroadPhaseBase(double fat_margin) : margin_(fat_margin) {
  if (!std::isfinite(fat_margin) || fat_margin < 0.0) {
    throw std::invalid_argument("fat margin must be finite and non-negative");
  }
}

ProxyId BroadPhaseBase::take_id() {
  if (free_.empty()) {
    detail::resize_room(fat_, fat_.size() + 1, kRemoved);
    return static_cast<ProxyId>(fat_.size() - 1);
  }
  const ProxyId id = free_.back();
  free_.pop_back();
  return id;
}

void BroadPhaseBase::check(ProxyId id) const {
  if (!contains(id)) throw std::out_of_range("unknown proxy " + std::to_string(id));
}

bool BroadPhaseBase::contains(ProxyId id) const { return id < fat_.size() && alive(id); }

const Aabb& BroadPhaseBase::fat_box(ProxyId id) const {
  check(id);
  return fat_[id];
}

ProxyId BroadPhaseBase::insert(const Aabb& box) { return insert_batch(std::span<const Aabb>(&box, 1)).front(); }

std::vector<ProxyId> BroadPhaseBase::insert_batch(std::span<const Aabb> boxes) {
  for (const Aabb& box : boxes) validate_box(box);
  std::vector<ProxyId> ids;
  ids.reserve(boxes.size());
  for (const Aabb& box : boxes) {
    const ProxyId id = take_id();
    const Vec2 grow = Vec2::Constant(margin_);
    fat_[id] = {box.min - grow, box.max + grow};
    ids.push_back(id);
  }
  live_ += boxes.size();
  return ids;
}

bool BroadPhaseBase::move(ProxyId id, const Aabb& box) {
  check(id);
  validate_box(box);
  Aabb& fat = fat_[id];
  if (encloses(fat, box)) return false;
  const Vec2 grow = Vec2::Constant(margin_);
  fat = {box.min - grow, box.max + grow};
  return true;
}

void BroadPhaseBase::remove(ProxyId id) {
  check(id);
  fat_[id] = kRemoved;
  removed_.push_back(id);
  --live_;
}

void BroadPhaseBase::finish_update(std::vector<ProxyPair>& now) {
  detail::replace_pairs(pairs_, now, began_, ended_);
  free_.insert(free_.end(), removed_.begin(), removed_.end());
  removed_.clear();
}

// ---- sweep and prune ----

// A strip's count wanders by a few boxes from frame to frame: growing it with room to spare lets it
// do so without allocating.
void SweepAndPrune::Strip::resize(std::size_t n) {
  if (n > keys.capacity()) {
    const std::size_t room = n + n / 8 + 8;
    keys.reserve(room);
    tags.reserve(room);
    lo.reserve(room);
    hi.reserve(room);
    starts.reserve(room);
  }
  keys.resize(n);
  tags.resize(n);
  lo.resize(n);
  hi.resize(n);
  starts.resize(n);
}

// Chooses the sweep axis and the strip width from the boxes; true when the strips must be rebuilt.
bool SweepAndPrune::lay_out() {
  double sum[2] = {0, 0}, sum2[2] = {0, 0}, extent[2] = {0, 0};
  std::size_t n = 0;
  for (ProxyId id = 0; id < fat_.size(); ++id) {
    if (!alive(id)) continue;
    const Aabb& fat = fat_[id];
    for (int k = 0; k < 2; ++k) {
      const double c = 0.5 * (fat.min[k] + fat.max[k]);
      sum[k] += c;
      sum2[k] += c * c;
      extent[k] += fat.max[k] - fat.min[k];
    }
    ++n;
  }
  if (n == 0) return strip_width_ == 0.0;
  double var[2];
  for (int k = 0; k < 2; ++k) var[k] = std::max(0.0, sum2[k] / n - (sum[k] / n) * (sum[k] / n));
  int axis = sweep_axis_;
  if (var[1 - axis] > 1.5 * var[axis]) axis = 1 - axis;
  const int across = 1 - axis;
  // Four mean boxes wide; for points, about one box per strip of the spread; for one point, 1.
  double width = 4.0 * extent[across] / n;
  if (!(width > 0.0)) width = 4.0 * std::sqrt(var[across] / n);
  if (!(width > 0.0) || !std::isfinite(width)) width = 1.0;
  const bool rebuild =
      strip_width_ == 0.0 || axis != sweep_axis_ || width > 2 * strip_width_ || width < 0.5 * strip_width_;
  if (rebuild) {
    sweep_axis_ = axis;
    strip_width_ = width;
  }
  return rebuild;
}

SweepAndPrune::StripRange SweepAndPrune::strips_of(const Aabb& box) const {
  const int across = 1 - sweep_axis_;
  const auto index = [this](double x) {
    const double q = std::floor(x / strip_width_);
    constexpr double kLimit = 2.0e9;  // beyond int32: such boxes share the outermost strips
    return static_cast<std::int32_t>(std::clamp(q, -kLimit, kLimit));
  };
  return {index(box.min[across]), index(box.max[across])};
}

// Moves each box into the strips its fat box now reaches; entries of strips it left are dropped
// when those strips are refreshed.
void SweepAndPrune::assign_strips() {
  detail::resize_room(range_, fat_.size());
  for (ProxyId id = 0; id < fat_.size(); ++id) {
    const StripRange old = range_[id];
    const StripRange now = alive(id) ? strips_of(fat_[id]) : StripRange{};
    if (now.first == old.first && now.last == old.last) continue;
    for (std::int32_t k = now.first; k <= now.last; ++k) {
      if (k >= old.first && k <= old.last) continue;
      std::vector<std::uint32_t>& in = strips_[k].incoming;
      in.push_back(tag(id, false));
      in.push_back(tag(id, true));
    }
    range_[id] = now;
  }
}

// Endpoint i of strip `index` from its box as it is now.
void SweepAndPrune::load(Strip& s, std::size_t i, std::uint32_t t, std::int32_t index) const {
  const Aabb& b = fat_[id_of(t)];
  s.keys[i] = (is_max(t) ? b.max[sweep_axis_] : b.min[sweep_axis_]) + 0.0;  // -0.0 -> +0.0 for the radix keys
  s.tags[i] = t;
  s.lo[i] = b.min[1 - sweep_axis_];
  s.hi[i] = b.max[1 - sweep_axis_];
  s.starts[i] = range_[id_of(t)].first == index ? 1 : 0;
}

// Current coordinates for the strip's entries; entries of removed boxes, or of boxes that left the
// strip, go.
void SweepAndPrune::refresh(std::int32_t index, Strip& s) const {
  std::size_t out = 0;
  for (std::size_t i = 0; i < s.tags.size(); ++i) {
    const ProxyId id = id_of(s.tags[i]);
    if (alive(id) && range_[id].first <= index && index <= range_[id].last) load(s, out++, s.tags[i], index);
  }
  s.resize(out);
}

bool SweepAndPrune::insertion_sort(Strip& s, std::size_t budget, std::size_t& swaps) const {
  for (std::size_t i = 1; i < s.keys.size(); ++i) {
    const double k = s.keys[i], lo = s.lo[i], hi = s.hi[i];
    const std::uint8_t starts = s.starts[i];
    const std::uint32_t t = s.tags[i];
    std::size_t j = i;
    while (j > 0 && before(k, t, s.keys[j - 1], s.tags[j - 1])) {
      s.keys[j] = s.keys[j - 1];
      s.tags[j] = s.tags[j - 1];
      s.lo[j] = s.lo[j - 1];
      s.hi[j] = s.hi[j - 1];
      s.starts[j] = s.starts[j - 1];
      --j;
      if (++swaps > budget) break;
    }
    s.keys[j] = k;
    s.tags[j] = t;
    s.lo[j] = lo;
    s.hi[j] = hi;
    s.starts[j] = starts;
    if (swaps > budget) return false;
  }
  return true;
}

// LSD radix sort on (key, is_max): one pass on the max bit, then eight on the key's bytes; every
// pass is stable, so equal keys keep mins first.
void SweepAndPrune::radix_sort(Strip& s, std::int32_t index) const {
  const std::size_t n = s.keys.size();
  thread_local std::vector<std::uint64_t> bits, bits_tmp;
  thread_local std::vector<std::uint32_t> tags_tmp;
  bits.resize(n);
  bits_tmp.resize(n);
  tags_tmp.resize(n);
  for (std::size_t i = 0; i < n; ++i) bits[i] = ordered_bits(s.keys[i]);
  const auto pass = [&](auto digit, std::size_t buckets) {
    std::size_t start[257] = {};
    for (std::size_t i = 0; i < n; ++i) ++start[digit(bits[i], s.tags[i]) + 1];
    for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t to = start[digit(bits[i], s.tags[i])]++;
      bits_tmp[to] = bits[i];
      tags_tmp[to] = s.tags[i];
    }
    bits.swap(bits_tmp);
    s.tags.swap(tags_tmp);
  };
  pass([](std::uint64_t, std::uint32_t t) { return static_cast<std::size_t>(t & 1u); }, 2);
  for (int shift = 0; shift < 64; shift += 8) {
    pass([shift](std::uint64_t b, std::uint32_t) { return static_cast<std::size_t>((b >> shift) & 0xffu); }, 256);
  }
  for (std::size_t i = 0; i < n; ++i) load(s, i, s.tags[i], index);
}

// The endpoints of boxes that entered the strip, sorted among themselves, merged in. The scratch
// lists are the thread's, kept from frame to frame: a steady frame allocates nothing.
void SweepAndPrune::merge_incoming(Strip& s, std::int32_t index) const {
  if (s.incoming.empty()) return;
  thread_local Strip fresh;
  thread_local std::vector<std::uint32_t> order, tags;
  fresh.resize(s.incoming.size());
  for (std::size_t i = 0; i < s.incoming.size(); ++i) load(fresh, i, s.incoming[i], index);
  s.incoming.clear();
  order.resize(fresh.keys.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [](std::uint32_t a, std::uint32_t b) {
    return before(fresh.keys[a], fresh.tags[a], fresh.keys[b], fresh.tags[b]);
  });
  tags.clear();
  std::size_t i = 0, j = 0;
  while (i < s.tags.size() || j < order.size()) {
    const bool take_old = j == order.size() || (i < s.tags.size() && !before(fresh.keys[order[j]], fresh.tags[order[j]],
                                                                             s.keys[i], s.tags[i]));
    tags.push_back(take_old ? s.tags[i++] : fresh.tags[order[j++]]);
  }
  s.resize(tags.size());
  for (std::size_t k = 0; k < tags.size(); ++k) load(s, k, tags[k], index);
  // A strip filled at once (the first frame, or new strips) gives back the room its arrivals took.
  if (2 * fresh.keys.size() > tags.size()) std::vector<std::uint32_t>().swap(s.incoming);
}

// The pairs of the strip: overlapping along the sweep axis (both in the active list) and across it,
// reported only in the first strip both boxes reach.
void SweepAndPrune::sweep(StripWork& w) const {
  struct Active {
    ProxyId id;
    double lo;
    double hi;
    std::uint8_t starts;
  };
  // A proxy's place in the active list, and the list, per thread: tasks on other threads sweep
  // other strips. Kept from frame to frame: a steady frame allocates nothing.
  thread_local std::vector<std::uint32_t> active_slot;
  thread_local std::vector<Active> active;
  if (active_slot.size() < fat_.size()) active_slot.resize(fat_.size());
  const Strip& s = *w.strip;
  active.clear();
  for (std::size_t i = 0; i < s.tags.size(); ++i) {
    const ProxyId id = id_of(s.tags[i]);
    if (is_max(s.tags[i])) {
      const std::uint32_t slot = active_slot[id];
      active[slot] = active.back();
      active_slot[active[slot].id] = slot;
      active.pop_back();
      continue;
    }
    w.axis_overlaps += active.size();
    for (const Active& q : active) {
      if (s.lo[i] <= q.hi && q.lo <= s.hi[i] && (s.starts[i] | q.starts) != 0) {
        w.found.push_back(id < q.id ? ProxyPair{id, q.id} : ProxyPair{q.id, id});
      }
    }
    active_slot[id] = static_cast<std::uint32_t>(active.size());
    active.push_back({id, s.lo[i], s.hi[i], s.starts[i]});
  }
}

// One strip's frame: current coordinates, sorted again (by insertion while that is cheap: a budget
// of swaps near the cost of the radix sort, beyond which the boxes did not move coherently), the
// boxes that entered merged in, and its pairs.
void SweepAndPrune::process(StripWork& w) const {
  Strip& strip = *w.strip;
  w.found.clear();
  w.swaps = 0;
  w.axis_overlaps = 0;
  refresh(w.index, strip);
  w.full_sort = !insertion_sort(strip, 8 * strip.keys.size() + 64, w.swaps);
  if (w.full_sort) radix_sort(strip, w.index);
  merge_incoming(strip, w.index);
  sweep(w);
}

// found_: the first `strips` tasks' pairs in order, by a counting sort on each pair's first proxy,
// then each proxy's few pairs sorted on the second. A pair is found in one strip only, so the result
// is the sorted union whatever the order of the strips. It runs on the calling thread: two passes
// over the pairs and one over the proxies take less time there than sorting each strip's list and
// merging the lists in passes took on two threads.
void SweepAndPrune::join(std::size_t strips) {
  ends_.assign(fat_.size() + 1, 0);
  for (std::size_t k = 0; k < strips; ++k) {
    for (const ProxyPair& p : work_[k].found) ++ends_[p.a + 1];
  }
  std::partial_sum(ends_.begin(), ends_.end(), ends_.begin());  // where each proxy's pairs start
  found_.resize(ends_.back());
  for (std::size_t k = 0; k < strips; ++k) {
    for (const ProxyPair& p : work_[k].found) found_[ends_[p.a]++] = p;  // ends_[a] moves to a's end
  }
  const auto at = [this](std::uint32_t i) { return found_.begin() + static_cast<std::ptrdiff_t>(i); };
  std::uint32_t begin = 0;
  for (ProxyId id = 0; id < fat_.size(); ++id) {
    if (ends_[id] - begin > 1) std::sort(at(begin), at(ends_[id]));
    begin = ends_[id];
  }
}

void SweepAndPrune::update(const ParallelFor& parallel) {
  stats_ = {};
  if (lay_out()) {
    strips_.clear();
    range_.assign(fat_.size(), StripRange{});
    stats_.full_sort = true;
  }
  assign_strips();
  work_.resize(strips_.size());
  std::size_t n = 0;
  for (auto& [index, strip] : strips_) {
    work_[n].index = index;
    work_[n++].strip = &strip;
  }
  const auto task = [this](std::size_t k) { process(work_[k]); };
  if (parallel) {
    parallel(n, task);
  } else {
    for (std::size_t k = 0; k < n; ++k) task(k);
  }
  std::size_t empty = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const StripWork& w = work_[k];
    stats_.swaps += w.swaps;
    stats_.axis_overlaps += w.axis_overlaps;
    stats_.full_sort = stats_.full_sort || w.full_sort;
    empty += w.strip->tags.empty() ? 1 : 0;
  }
  join(n);
  // Empty strips are dropped together once they are half of all: a strip that empties and fills
  // again frame after frame (a body crossing its edge) keeps its storage.
  if (2 * empty > n) std::erase_if(strips_, [](const auto& entry) { return entry.second.tags.empty(); });
  stats_.axis = sweep_axis_;
  stats_.strips = n - empty;
  finish_update(found_);
}

// ---- brute force ----

void BruteForceBroadPhase::update() {
  std::vector<ProxyPair> found;
  for (ProxyId i = 0; i < fat_.size(); ++i) {
    if (!alive(i)) continue;
    for (ProxyId j = i + 1; j < fat_.size(); ++j) {
      if (alive(j) && intersects(fat_[i], fat_[j])) found.push_back({i, j});
    }
  }
  finish_update(found);
}

}  // namespace collide2d
