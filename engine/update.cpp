// The World's update: the broad phase (the sweep and prune of the moving shapes, and each moving
// shape's static neighbours), then the narrow phase over the candidate pairs of shapes in chunks,
// each chunk's overlap tests batched by pair kind, on the thread pool.
#include "engine/world_state.h"

#include "broadphase/internal.h"
#include "narrowphase/internal.h"

#include <collide2d/kernels.h>

#include <algorithm>
#include <chrono>
#include <numeric>
#include <tuple>
#include <type_traits>
#include <utility>

namespace collide2d::detail {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A tree with a quarter or more of its leaves inserted since its last rebuild.
bool fresh(const AabbTree& tree) { return tree.size() >= 64 && 4 * tree.inserted_since_rebuild() >= tree.size(); }

}  // namespace

// The moving bodies' tree catches up: each stale leaf takes its shape's fat box (its ancestors
// refitted), and the tree is rebuilt when a quarter of it is new since its last rebuild or its inner
// perimeters have grown 1.5 times since. It runs alongside the narrow phase, which does not use it.
void WorldState::refresh_moving_tree() {
  if (!moving_tree_on_.load(std::memory_order_relaxed)) return;  // no leaf is stale before it is built
  tree_boxes_.clear();
  for (const std::uint32_t index : stale_leaves_) {
    ShapeEntry& p = entries_[index];
    tree_boxes_.emplace_back(moving_leaves_[p.proxy], broad_.fat_box(p.proxy));
    p.stale_at = -1;
  }
  moving_tree_.set_boxes(tree_boxes_);
  const bool moved = !stale_leaves_.empty();
  stale_leaves_.clear();
  const bool worn = moved && moving_tree_.size() >= 64 && moving_tree_.inner_perimeter() > 1.5 * moving_perimeter_;
  if (fresh(moving_tree_) || worn) {
    moving_tree_.rebuild();
    moving_perimeter_ = moving_tree_.inner_perimeter();
  }
}

// The pairs of moving shapes from the sweep and prune, and each moving shape's pairs with the static
// shapes it keeps, looked up again where its fat box or the statics changed; never two shapes of one
// body. Each pair comes with the shape of the lower body first.
void WorldState::find_candidates() {
  // A few thousand moving shapes sort and sweep in less time than waking the pool takes.
  constexpr std::size_t kParallelBodies = 4096;
  const auto parallel = [this](std::size_t count, const std::function<void(std::size_t)>& task) {
    pool_->run(
        count, [&task](std::size_t k, unsigned) { task(k); }, broad_.size() >= kParallelBodies);
  };
  broad_.update(parallel);
  if (fresh(static_tree_)) static_tree_.rebuild();
  // Two shapes in the order of their bodies, or (kNone, kNone) for two shapes of one body. Static,
  // so that the task below captures no more than std::function holds without allocating.
  static constexpr auto in_body_order = [](const Pages<ShapeEntry>& parts, std::uint32_t x, std::uint32_t y) {
    const std::uint32_t bx = parts[x].body.index, by = parts[y].body.index;
    return bx == by ? std::pair(kNone, kNone) : bx < by ? std::pair(x, y) : std::pair(y, x);
  };
  // The moving pairs' shapes, in blocks on the pool (each pair reads two shapes far apart in
  // memory), a pair of one body's shapes marked and then dropped.
  constexpr std::size_t kBlock = 4096;
  const std::vector<ProxyPair>& moving = broad_.pairs();
  candidates_.resize(moving.size());
  parallel((moving.size() + kBlock - 1) / kBlock, [this, &moving](std::size_t block) {
    for (std::size_t k = block * kBlock; k < std::min(moving.size(), (block + 1) * kBlock); ++k)
      candidates_[k] = in_body_order(entries_, part_of_[moving[k].a], part_of_[moving[k].b]);
  });
  std::erase_if(candidates_, [](const auto& c) { return c.first == kNone; });
  const auto add = [&](std::uint32_t x, std::uint32_t y) {
    if (const auto pair = in_body_order(entries_, x, y); pair.first != kNone) candidates_.push_back(pair);
  };
  const bool statics = static_tree_.size() > 0 || statics_changed_;  // else every shape's list is empty
  for (ProxyId proxy = 0; statics && proxy < part_of_.size(); ++proxy) {
    const std::uint32_t index = part_of_[proxy];
    if (index == kNone) continue;
    ShapeEntry& b = entries_[index];
    const Aabb& fat = broad_.fat_box(proxy);
    if (statics_changed_ || !encloses(as_aabb(b.queried), fat)) {
      // Looked up around the fat box, half its larger side further, so that the next few frames'
      // fat boxes stay within it and need no look-up: the statics kept are a superset, and the test
      // below keeps those the fat box meets.
      b.queried = outward(grown(fat, 0.5 * (fat.max - fat.min).maxCoeff()));
      const Aabb around = as_aabb(b.queried);
      // A shape keeps its list once it has had a neighbour, so that a steady frame allocates nothing.
      const bool had_list = b.statics != kNone;
      std::vector<std::uint32_t>& list = static_list(b);
      static_tree_.query(around, [&](std::uint32_t s) {
        if (intersects(broad_box(entries_[s]), around)) list.push_back(s);
      });
      if (!had_list && list.empty()) release_statics(b);
      ++stats_.requeried;
    }
    if (b.statics == kNone) continue;
    for (const std::uint32_t s : static_lists_[b.statics]) {
      if (intersects(broad_box(entries_[s]), fat)) add(index, s);
    }
  }
  statics_changed_ = false;
}

void WorldState::ChunkResults::clear() {
  overlapping.clear();
  sensing.clear();
  proximity.clear();
  contacts.clear();
  impacts.clear();
  filtered = 0;
}

void WorldState::ChunkScratch::clear() {
  verdicts.clear();
  std::apply([](auto&... batch) { (batch.clear(), ...); }, batches);
}

template <class A, class B>
void WorldState::Batch<A, B>::add(std::uint32_t place, std::uint32_t a_part, std::uint32_t b_part) {
  if (places.capacity() < kPairsPerChunk) {
    places.reserve(kPairsPerChunk);
    a.reserve(kPairsPerChunk);
    b.reserve(kPairsPerChunk);
    verdicts.reserve(kPairsPerChunk);
  }
  places.push_back(place);
  a.push_back(a_part);
  b.push_back(b_part);
}

template <class A, class B>
void WorldState::Batch<A, B>::run(const Pages<ShapeEntry>& parts, std::vector<Verdict>& chunk_verdicts) {
  verdicts.resize(places.size());
  overlap_pairs<A, B>(
      [&](std::size_t k) {
        const ShapeEntry& x = parts[a[k]];
        const ShapeEntry& y = parts[b[k]];
        return PairRef<A, B>{std::get<A>(x.shape), x.orientation, std::get<B>(y.shape), y.orientation};
      },
      verdicts);
  for (std::size_t j = 0; j < places.size(); ++j)
    chunk_verdicts[places[j]] = verdicts[j] != 0 ? Verdict::touching : Verdict::apart;
}

template <class A, class B>
void WorldState::Batch<A, B>::clear() {
  places.clear();
  a.clear();
  b.clear();
}

void WorldState::update() {
  require_not_querying("update");
  const auto start = std::chrono::steady_clock::now();
  stats_ = {};
  find_candidates();
  stats_.broad_seconds = seconds_since(start);
  const auto narrow_start = std::chrono::steady_clock::now();
  narrow_phase();
  begin_steps();
  stats_.narrow_seconds = seconds_since(narrow_start);
  stats_.candidates = candidates_.size();
  stats_.overlapping = overlapping_.size();
  stats_.proximity = proximity_.size();
  stats_.contacts = contacts_.size();
  stats_.impacts = impacts_.size();
  stats_.sensing = sensing_.size();
  ++updates_;
}

// The candidate pairs in chunks, in order, on the pool with the moving tree's refresh beside them;
// then each result list joined in chunk order and sorted by pair, which makes it the same for any
// thread count.
void WorldState::narrow_phase() {
  const std::size_t chunks = std::max<std::size_t>(1, (candidates_.size() + kPairsPerChunk - 1) / kPairsPerChunk);
  if (chunks_.size() < chunks) chunks_.resize(chunks);
  const ThreadPool::Task task = [this](std::size_t task, unsigned worker) {
    if (task == 0) {  // the longest task, so first
      refresh_moving_tree();
      return;
    }
    const std::size_t k = task - 1;
    narrow_chunk(k * kPairsPerChunk, std::min(candidates_.size(), (k + 1) * kPairsPerChunk), chunks_[k],
                 scratch_[worker]);
  };
  // Several thousand pairs take less time than waking the pool and then fetching back the cache
  // lines its threads took (the next frame's poses write the shapes they read).
  const bool worth_waking = chunks >= 32;
  pool_->run(chunks + 1, task, worth_waking);
  // Each list emptied, with room for the chunks' results joined.
  const auto make_room = [&](auto& list, const auto ChunkResults::*results) {
    std::size_t n = 0;
    for (std::size_t k = 0; k < chunks; ++k) n += (chunks_[k].*results).size();
    list.clear();
    reserve_room(list, n);
  };
  make_room(proximity_, &ChunkResults::proximity);
  make_room(contacts_, &ChunkResults::contacts);
  make_room(impacts_, &ChunkResults::impacts);
  // The overlapping pairs' ids, each chunk's at its place, on the pool: the shapes they read lie far
  // apart.
  std::size_t pairs = 0;
  for (std::size_t k = 0; k < chunks; ++k) {
    chunks_[k].first_pair = pairs;
    pairs += chunks_[k].overlapping.size();
  }
  // Not emptied first: the pool writes every pair, and the last frame's elements need no filling.
  resize_room(frame_pairs_, pairs);
  pool_->run(
      chunks,
      [this](std::size_t k, unsigned) {
        ShapePair* out = frame_pairs_.data() + chunks_[k].first_pair;
        for (const auto& [a, b] : chunks_[k].overlapping) *out++ = ShapePair{ids_of(a, b)};
      },
      worth_waking);
  for (std::size_t k = 0; k < chunks; ++k) {
    const ChunkResults& f = chunks_[k];
    proximity_.insert(proximity_.end(), f.proximity.begin(), f.proximity.end());
    contacts_.insert(contacts_.end(), f.contacts.begin(), f.contacts.end());
    impacts_.insert(impacts_.end(), f.impacts.begin(), f.impacts.end());
    stats_.filtered += f.filtered;
  }
  // By bodies, then shapes: this frame's handles are live, so their slots alone order them as the
  // handles do, in two integer comparisons.
  const auto by_pair = [](const auto& p, const auto& q) {
    const auto key = [](const auto& r) {
      return std::pair(std::uint64_t{r.a.index} << 32 | r.b.index,
                       std::uint64_t{r.shape_a.index} << 32 | r.shape_b.index);
    };
    return key(p) < key(q);
  };
  // The sweep and prune gives its pairs in the order of its proxies, which is often the shapes'
  // order already: a list found sorted is not sorted again.
  const auto sort = [&by_pair](auto& list) {
    if (!std::is_sorted(list.begin(), list.end(), by_pair)) std::sort(list.begin(), list.end(), by_pair);
  };
  sort(frame_pairs_);
  sort(proximity_);
  sort(contacts_);
  sort(impacts_);
  keep_earliest_impacts();
  replace_pairs(overlapping_, frame_pairs_, began_, ended_);
  update_body_pairs();
  index_contacts();
  update_sensing(chunks);
  mark_removed();
}

std::vector<ShapePair> WorldState::candidates() const {
  std::vector<ShapePair> out;
  out.reserve(candidates_.size());
  for (const auto& [a, b] : candidates_) {
    if (entries_[a].alive && entries_[b].alive) out.push_back(ShapePair{ids_of(a, b)});
  }
  return out;
}

// The overlapping pairs by bodies: each pair of bodies once (the shape pairs are sorted by bodies).
void WorldState::update_body_pairs() {
  frame_body_pairs_.clear();
  reserve_room(frame_body_pairs_, overlapping_.size());
  for (const ShapePair& p : overlapping_) {
    if (frame_body_pairs_.empty() || frame_body_pairs_.back().a != p.a || frame_body_pairs_.back().b != p.b)
      frame_body_pairs_.push_back({p.a, p.b, p.user_a, p.user_b});
  }
  replace_pairs(body_overlapping_, frame_body_pairs_, body_began_, body_ended_);
}

// Each body's contacts in contacts()' order, by a counting sort on the body slots: the counts go
// one slot up, their running sum gives each slot's start, filling moves each start to the next
// slot's, and one shift puts them back.
void WorldState::index_contacts() {
  contact_start_.assign(contacts_.empty() ? 0 : bodies_.size() + 1, 0);
  contact_list_.resize(2 * contacts_.size());
  if (contacts_.empty()) return;
  for (const BodyContact& c : contacts_) ++contact_start_[c.a.index + 1], ++contact_start_[c.b.index + 1];
  std::partial_sum(contact_start_.begin(), contact_start_.end(), contact_start_.begin());
  for (std::uint32_t k = 0; k < contacts_.size(); ++k) {
    contact_list_[contact_start_[contacts_[k].a.index]++] = k;
    contact_list_[contact_start_[contacts_[k].b.index]++] = k;
  }
  std::copy_backward(contact_start_.begin(), contact_start_.end() - 1, contact_start_.end());
  contact_start_[0] = 0;
}

std::span<const std::uint32_t> WorldState::contacts_of(BodyId id) const {
  (void)body(id);
  if (std::size_t{id.index} + 1 >= contact_start_.size()) return {};
  const std::span<const std::uint32_t> list(contact_list_.data() + contact_start_[id.index],
                                            contact_list_.data() + contact_start_[id.index + 1]);
  // The slot may hold another body than at the update (removed, and its slot taken since).
  if (list.empty() || (contacts_[list[0]].a != id && contacts_[list[0]].b != id)) return {};
  return list;
}

void WorldState::mark_removed() {
  for (ShapePair& p : ended_)
    p.removed = !contains(p.a) || !contains(p.b) || !contains(p.shape_a) || !contains(p.shape_b);
  for (BodyPair& p : body_ended_) p.removed = !contains(p.a) || !contains(p.b);
  for (SensorPair& p : sensor_ended_) {
    p.removed = !contains(p.sensor) || !contains(p.visitor) || !contains(p.sensor_shape) || !contains(p.visitor_shape);
  }
  for (SensorVisit& p : body_sensor_ended_) {
    p.removed = !contains(p.sensor) || !contains(p.visitor) || !contains(p.sensor_shape);
  }
}

// The candidate pairs [begin, end): first every overlap test, the chunk's pairs in batches by kind
// (the same verdicts as one by one, 2 to 8 pairs at a time), then each pair's results in order.
void WorldState::narrow_chunk(std::size_t begin, std::size_t end, ChunkResults& out, ChunkScratch& scratch) const {
  out.clear();
  scratch.clear();
  for (std::size_t i = begin; i < end; ++i)
    scratch.verdicts.push_back(overlap_verdict(candidates_[i].first, candidates_[i].second, out, scratch));
  std::apply([&](auto&... batch) { (batch.run(entries_, scratch.verdicts), ...); }, scratch.batches);
  for (std::size_t i = begin; i < end; ++i) {
    const Verdict v = scratch.verdicts[i - begin];
    if (v != Verdict::skipped) narrow(candidates_[i].first, candidates_[i].second, v == Verdict::touching, out);
  }
}

// A pair of two ghosts, dropped by the filters or made of two sensors is skipped; a pair whose boxes meet joins the
// batch of its kind, in kernel order.
WorldState::Verdict WorldState::overlap_verdict(std::uint32_t a, std::uint32_t b, ChunkResults& out,
                                                ChunkScratch& scratch) const {
  const ShapeEntry& x = entries_[a];
  const ShapeEntry& y = entries_[b];
  if (x.ghost && y.ghost) return Verdict::skipped;  // another World's pair, not filtered here
  if (!passes(a, b)) {
    ++out.filtered;
    return Verdict::skipped;
  }
  if (x.sensor && y.sensor) return Verdict::skipped;
  if (!intersects(x.box, y.box)) return Verdict::apart;
  const auto place = static_cast<std::uint32_t>(scratch.verdicts.size());
  return std::visit(
      [&](const auto& xs, const auto& ys) {
        using X = std::decay_t<decltype(xs)>;
        using Y = std::decay_t<decltype(ys)>;
        if constexpr (!batched<X, Y>) {
          return overlaps(x.shape, x.orientation, y.shape, y.orientation) ? Verdict::touching : Verdict::apart;
        } else if constexpr (rank<X>() <= rank<Y>()) {
          std::get<Batch<X, Y>>(scratch.batches).add(place, a, b);
          return Verdict::batched;
        } else {
          std::get<Batch<Y, X>>(scratch.batches).add(place, b, a);
          return Verdict::batched;
        }
      },
      x.shape, y.shape);
}

Contact WorldState::pair_contact(std::uint32_t a, std::uint32_t b, const ContactOptions& options) const {
  const ShapeEntry& x = entries_[a];
  const ShapeEntry& y = entries_[b];
  if (x.chain) return contact(chain_of(a), x.orientation, y.shape, y.orientation, options);
  if (y.chain) return contact(chain_of(b), y.orientation, x.shape, x.orientation, options).swapped();
  return contact(x.shape, x.orientation, y.shape, y.orientation, options);
}

OverlapArea WorldState::pair_overlap(std::uint32_t a, std::uint32_t b) const {
  const Shape& x = entries_[a].shape;
  const Shape& y = entries_[b].shape;
  if (!overlap_areas_ || std::holds_alternative<Segment>(x) || std::holds_alternative<Segment>(y)) return {};
  const OverlapArea o = areas::overlap_of(x, y);
  return o.area > 0.0 ? o : OverlapArea{};
}

// One candidate pair that passed the filters, given its overlap verdict: a sensor's overlap, or the
// solid pair's overlap, proximity, contact and time of impact, as far as they were asked for.
void WorldState::narrow(std::uint32_t a, std::uint32_t b, bool touching, ChunkResults& out) const {
  const ShapeEntry& x = entries_[a];
  const ShapeEntry& y = entries_[b];
  if (x.sensor || y.sensor) {
    sense(a, b, touching, out);
    return;
  }
  const ContactOptions manifold{.margin = speculative_margin_, .tolerance = contact_tolerance_};
  if (x.continuous || y.continuous) impact(a, b, out);
  const auto record = [&](bool solids_touch, const Contact& c) {
    BodyContact& r = out.contacts.emplace_back(BodyContact{ids_of(a, b)});
    r.touching = solids_touch;
    r.contact = c;
    if (solids_touch) r.overlap = pair_overlap(a, b);
  };
  if (touching) {
    // A chain's segment touches only where its rules give a contact (chain.h): its contact comes
    // first.
    const bool chained = x.chain || y.chain;
    const Contact c = chained || contacts_on_ ? pair_contact(a, b, manifold) : Contact{};
    if (!chained || !c.empty()) {
      out.overlapping.emplace_back(a, b);
      if (contacts_on_) record(true, c);
      return;
    }
  }
  if (proximity_margin_ > 0.0) {
    const DistanceResult d = distance(x.shape, y.shape);
    if (!d.overlapping && d.distance <= proximity_margin_)
      out.proximity.emplace_back(Proximity{ids_of(a, b)}).result = d;
  }
  if (speculative_margin_ > 0.0 &&
      intersects(grown(x.box, 0.5 * speculative_margin_), grown(y.box, 0.5 * speculative_margin_))) {
    // Only the pairs within the margin are recorded: the kernels stop as soon as a pair is beyond.
    const ContactOptions speculative{
        .margin = speculative_margin_, .max_separation = speculative_margin_, .tolerance = contact_tolerance_};
    const Contact c = pair_contact(a, b, speculative);
    if (!c.empty() && c.separation <= speculative_margin_) record(false, c);
  }
}

}  // namespace collide2d::detail
