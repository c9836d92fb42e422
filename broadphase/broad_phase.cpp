#include "broadphase/broad_phase.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

namespace collide2d {
namespace {

void validate_box(const Aabb& box) {
  const char* names[] = {"x", "y"};
  for (int k = 0; k < 2; ++k) {
    if (!std::isfinite(box.min[k]) || !std::isfinite(box.max[k])) {
      throw std::invalid_argument(std::string("box ") + names[k] + " bounds must be finite");
    }
    if (box.min[k] > box.max[k]) {
      std::ostringstream msg;
      msg.precision(17);
      msg << "box min." << names[k] << " > max." << names[k] << " (" << box.min[k] << " > " << box.max[k] << ')';
      throw std::invalid_argument(msg.str());
    }
  }
}

bool inside(const Aabb& inner, const Aabb& outer) {
  return (outer.min.array() <= inner.min.array()).all() && (inner.max.array() <= outer.max.array()).all();
}

bool overlap_on(const Aabb& p, const Aabb& q, int axis) {
  return p.min[axis] <= q.max[axis] && q.min[axis] <= p.max[axis];
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
  const auto u = std::bit_cast<std::uint64_t>(x);
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
    proxies_.emplace_back();
    return static_cast<ProxyId>(proxies_.size() - 1);
  }
  const ProxyId id = free_.back();
  free_.pop_back();
  return id;
}

void BroadPhaseBase::check(ProxyId id) const {
  if (!contains(id)) throw std::out_of_range("unknown proxy " + std::to_string(id));
}

bool BroadPhaseBase::contains(ProxyId id) const { return id < proxies_.size() && proxies_[id].alive; }

const Aabb& BroadPhaseBase::fat_box(ProxyId id) const {
  check(id);
  return proxies_[id].fat;
}

ProxyId BroadPhaseBase::insert(const Aabb& box) { return insert_batch(std::span<const Aabb>(&box, 1)).front(); }

std::vector<ProxyId> BroadPhaseBase::insert_batch(std::span<const Aabb> boxes) {
  for (const Aabb& box : boxes) validate_box(box);
  std::vector<ProxyId> ids;
  ids.reserve(boxes.size());
  for (const Aabb& box : boxes) {
    const ProxyId id = take_id();
    const Vec2 grow = Vec2::Constant(margin_);
    proxies_[id] = {{box.min - grow, box.max + grow}, true};
    inserted_.push_back(id);
    ids.push_back(id);
  }
  live_ += boxes.size();
  return ids;
}

void BroadPhaseBase::move(ProxyId id, const Aabb& box) {
  check(id);
  validate_box(box);
  Aabb& fat = proxies_[id].fat;
  if (inside(box, fat)) return;
  const Vec2 grow = Vec2::Constant(margin_);
  fat = {box.min - grow, box.max + grow};
}

void BroadPhaseBase::remove(ProxyId id) {
  check(id);
  proxies_[id].alive = false;
  removed_.push_back(id);
  --live_;
}

void BroadPhaseBase::finish_update(std::vector<ProxyPair>&& now) {
  began_.clear();
  ended_.clear();
  std::set_difference(now.begin(), now.end(), pairs_.begin(), pairs_.end(), std::back_inserter(began_));
  std::set_difference(pairs_.begin(), pairs_.end(), now.begin(), now.end(), std::back_inserter(ended_));
  pairs_ = std::move(now);
  free_.insert(free_.end(), removed_.begin(), removed_.end());
  removed_.clear();
  inserted_.clear();
}

// ---- sweep and prune ----

void SweepAndPrune::choose_axis() {
  double sum[2] = {0, 0}, sum2[2] = {0, 0};
  std::size_t n = 0;
  for (const Proxy& p : proxies_) {
    if (!p.alive) continue;
    for (int k = 0; k < 2; ++k) {
      const double c = 0.5 * (p.fat.min[k] + p.fat.max[k]);
      sum[k] += c;
      sum2[k] += c * c;
    }
    ++n;
  }
  if (n < 2) return;
  double var[2];
  for (int k = 0; k < 2; ++k) var[k] = sum2[k] / n - (sum[k] / n) * (sum[k] / n);
  if (var[1 - sweep_axis_] > 1.5 * var[sweep_axis_]) sweep_axis_ = 1 - sweep_axis_;
}

double SweepAndPrune::key_of(std::uint32_t t, int axis) const {
  const Aabb& b = proxies_[id_of(t)].fat;
  return (is_max(t) ? b.max[axis] : b.min[axis]) + 0.0;  // -0.0 -> +0.0 for the radix keys
}

// New coordinates for every endpoint on the axis; endpoints of removed boxes go.
void SweepAndPrune::refresh_keys(int axis) {
  Endpoints& e = axes_[axis];
  std::size_t out = 0;
  for (std::size_t i = 0; i < e.keys.size(); ++i) {
    if (!proxies_[id_of(e.tags[i])].alive) continue;
    e.keys[out] = key_of(e.tags[i], axis);
    e.tags[out] = e.tags[i];
    ++out;
  }
  e.keys.resize(out);
  e.tags.resize(out);
}

// Insertion sort whose swaps update the pair set: an element moving left past another's max with
// its min may begin a pair; with its max past another's min it ends one. Gives up (false) past
// `budget` swaps, leaving a permutation.
bool SweepAndPrune::insertion_sort(int axis, std::size_t budget) {
  Endpoints& e = axes_[axis];
  for (std::size_t i = 1; i < e.keys.size(); ++i) {
    const double k = e.keys[i];
    const std::uint32_t t = e.tags[i];
    std::size_t j = i;
    while (j > 0 && before(k, t, e.keys[j - 1], e.tags[j - 1])) {
      const std::uint32_t passed = e.tags[j - 1];
      if (is_max(t) != is_max(passed)) {
        const ProxyId p = id_of(t), q = id_of(passed);
        const std::uint64_t key = p < q ? std::uint64_t{p} << 32 | q : std::uint64_t{q} << 32 | p;
        if (is_max(t)) {
          overlapping_.erase(key);
        } else if (overlap_on(proxies_[p].fat, proxies_[q].fat, 0) && overlap_on(proxies_[p].fat, proxies_[q].fat, 1)) {
          overlapping_.insert(key);
        }
      }
      e.keys[j] = e.keys[j - 1];
      e.tags[j] = passed;
      --j;
      if (++stats_.swaps > budget) {
        e.keys[j] = k;
        e.tags[j] = t;
        return false;
      }
    }
    e.keys[j] = k;
    e.tags[j] = t;
  }
  return true;
}

// LSD radix sort on (key, is_max): one pass on the max bit, then eight on the key's bytes; every
// pass is stable, so equal keys keep mins first.
void SweepAndPrune::radix_sort(int axis) {
  Endpoints& e = axes_[axis];
  const std::size_t n = e.keys.size();
  std::vector<std::uint64_t> bits(n), bits_tmp(n);
  std::vector<std::uint32_t> tags_tmp(n);
  std::vector<double> keys_tmp(n);
  for (std::size_t i = 0; i < n; ++i) bits[i] = ordered_bits(e.keys[i]);
  const auto pass = [&](auto digit, std::size_t buckets) {
    std::vector<std::size_t> start(buckets + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++start[digit(bits[i], e.tags[i]) + 1];
    for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t to = start[digit(bits[i], e.tags[i])]++;
      bits_tmp[to] = bits[i];
      tags_tmp[to] = e.tags[i];
      keys_tmp[to] = e.keys[i];
    }
    bits.swap(bits_tmp);
    e.tags.swap(tags_tmp);
    e.keys.swap(keys_tmp);
  };
  pass([](std::uint64_t, std::uint32_t t) { return static_cast<std::size_t>(t & 1u); }, 2);
  for (int shift = 0; shift < 64; shift += 8) {
    pass([shift](std::uint64_t b, std::uint32_t) { return static_cast<std::size_t>((b >> shift) & 0xffu); }, 256);
  }
}

// The endpoints of boxes inserted since the last update, sorted among themselves, merged in.
void SweepAndPrune::merge_inserted(int axis) {
  std::vector<std::uint32_t> fresh;
  for (const ProxyId id : inserted_) {
    if (!proxies_[id].alive) continue;
    fresh.push_back(tag(id, false));
    fresh.push_back(tag(id, true));
  }
  if (fresh.empty()) return;
  const auto key = [this, axis](std::uint32_t t) { return key_of(t, axis); };
  std::sort(fresh.begin(), fresh.end(), [&](std::uint32_t a, std::uint32_t b) { return before(key(a), a, key(b), b); });
  Endpoints& e = axes_[axis];
  Endpoints merged;
  merged.keys.reserve(e.keys.size() + fresh.size());
  merged.tags.reserve(e.keys.size() + fresh.size());
  std::size_t i = 0, j = 0;
  while (i < e.keys.size() || j < fresh.size()) {
    const bool take_old = j == fresh.size() || (i < e.keys.size() && !before(key(fresh[j]), fresh[j], e.keys[i], e.tags[i]));
    merged.keys.push_back(take_old ? e.keys[i] : key(fresh[j]));
    merged.tags.push_back(take_old ? e.tags[i++] : fresh[j++]);
  }
  e = std::move(merged);
}

std::vector<ProxyPair> SweepAndPrune::sweep() {
  const int other = 1 - sweep_axis_;
  std::vector<ProxyId> active;
  active_slot_.resize(proxies_.size());
  std::vector<ProxyPair> found;
  for (const std::uint32_t t : axes_[sweep_axis_].tags) {
    const ProxyId id = id_of(t);
    if (is_max(t)) {
      const std::uint32_t slot = active_slot_[id];
      active[slot] = active.back();
      active_slot_[active[slot]] = slot;
      active.pop_back();
      continue;
    }
    const Aabb& box = proxies_[id].fat;
    stats_.axis_overlaps += active.size();
    for (const ProxyId q : active) {
      if (overlap_on(box, proxies_[q].fat, other)) found.push_back(id < q ? ProxyPair{id, q} : ProxyPair{q, id});
    }
    active_slot_[id] = static_cast<std::uint32_t>(active.size());
    active.push_back(id);
  }
  std::sort(found.begin(), found.end());
  return found;
}

void SweepAndPrune::update() {
  stats_ = {};
  choose_axis();
  for (int k = 0; k < 2; ++k) refresh_keys(k);
  if (!removed_.empty()) {
    std::erase_if(overlapping_, [this](std::uint64_t key) {
      return !proxies_[static_cast<ProxyId>(key >> 32)].alive || !proxies_[static_cast<ProxyId>(key & 0xffffffffu)].alive;
    });
  }
  // A budget of swaps near the cost of the radix sort: beyond it the scene has not moved coherently.
  for (int k = 0; k < 2; ++k) {
    const std::size_t budget = stats_.swaps + 8 * axes_[k].keys.size() + 64;
    if (stats_.full_sort || !insertion_sort(k, budget)) {
      stats_.full_sort = true;
      radix_sort(k);
    }
  }
  for (int k = 0; k < 2; ++k) merge_inserted(k);
  stats_.axis = sweep_axis_;
  std::vector<ProxyPair> now;
  if (stats_.full_sort || !inserted_.empty()) {
    stats_.swept = true;
    now = sweep();
    overlapping_.clear();
    for (const ProxyPair& p : now) overlapping_.insert(std::uint64_t{p.a} << 32 | p.b);
  } else {
    now.reserve(overlapping_.size());
    for (const std::uint64_t key : overlapping_) {
      now.push_back({static_cast<ProxyId>(key >> 32), static_cast<ProxyId>(key & 0xffffffffu)});
    }
    std::sort(now.begin(), now.end());
  }
  finish_update(std::move(now));
}

// ---- brute force ----

void BruteForceBroadPhase::update() {
  std::vector<ProxyPair> found;
  for (ProxyId i = 0; i < proxies_.size(); ++i) {
    if (!proxies_[i].alive) continue;
    for (ProxyId j = i + 1; j < proxies_.size(); ++j) {
      const Aabb& p = proxies_[i].fat;
      const Aabb& q = proxies_[j].fat;
      if (proxies_[j].alive && overlap_on(p, q, 0) && overlap_on(p, q, 1)) found.push_back({i, j});
    }
  }
  finish_update(std::move(found));
}

}  // namespace collide2d
