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
  if (var[1 - axis_] > 1.5 * var[axis_]) axis_ = 1 - axis_;
}

double SweepAndPrune::key_of(std::uint32_t t) const {
  const Aabb& b = proxies_[id_of(t)].fat;
  return (is_max(t) ? b.max[axis_] : b.min[axis_]) + 0.0;  // -0.0 -> +0.0 for the radix keys
}

// New coordinates for every endpoint on the current axis; endpoints of removed boxes go.
void SweepAndPrune::refresh_keys() {
  std::size_t out = 0;
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    if (!proxies_[id_of(tags_[i])].alive) continue;
    keys_[out] = key_of(tags_[i]);
    tags_[out] = tags_[i];
    ++out;
  }
  keys_.resize(out);
  tags_.resize(out);
}

bool SweepAndPrune::insertion_sort(std::size_t budget) {
  for (std::size_t i = 1; i < keys_.size(); ++i) {
    const double k = keys_[i];
    const std::uint32_t t = tags_[i];
    std::size_t j = i;
    while (j > 0 && before(k, t, keys_[j - 1], tags_[j - 1])) {
      keys_[j] = keys_[j - 1];
      tags_[j] = tags_[j - 1];
      --j;
      if (++stats_.swaps > budget) {
        keys_[j] = k;
        tags_[j] = t;
        return false;
      }
    }
    keys_[j] = k;
    tags_[j] = t;
  }
  return true;
}

// LSD radix sort on (key, is_max): one pass on the max bit, then eight on the key's bytes; every
// pass is stable, so equal keys keep mins first.
void SweepAndPrune::radix_sort() {
  const std::size_t n = keys_.size();
  std::vector<std::uint64_t> bits(n), bits_tmp(n);
  std::vector<std::uint32_t> tags_tmp(n);
  std::vector<double> keys_tmp(n);
  for (std::size_t i = 0; i < n; ++i) bits[i] = ordered_bits(keys_[i]);
  const auto pass = [&](auto digit, std::size_t buckets) {
    std::vector<std::size_t> start(buckets + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++start[digit(bits[i], tags_[i]) + 1];
    for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t to = start[digit(bits[i], tags_[i])]++;
      bits_tmp[to] = bits[i];
      tags_tmp[to] = tags_[i];
      keys_tmp[to] = keys_[i];
    }
    bits.swap(bits_tmp);
    tags_.swap(tags_tmp);
    keys_.swap(keys_tmp);
  };
  pass([](std::uint64_t, std::uint32_t t) { return static_cast<std::size_t>(t & 1u); }, 2);
  for (int shift = 0; shift < 64; shift += 8) {
    pass([shift](std::uint64_t b, std::uint32_t) { return static_cast<std::size_t>((b >> shift) & 0xffu); }, 256);
  }
}

// The endpoints of boxes inserted since the last update, sorted among themselves, merged in.
void SweepAndPrune::merge_inserted() {
  std::vector<std::uint32_t> fresh;
  for (const ProxyId id : inserted_) {
    if (!proxies_[id].alive) continue;
    fresh.push_back(tag(id, false));
    fresh.push_back(tag(id, true));
  }
  if (fresh.empty()) return;
  const auto key = [this](std::uint32_t t) { return key_of(t); };
  std::sort(fresh.begin(), fresh.end(), [&](std::uint32_t a, std::uint32_t b) { return before(key(a), a, key(b), b); });
  std::vector<double> keys;
  std::vector<std::uint32_t> tags;
  keys.reserve(keys_.size() + fresh.size());
  tags.reserve(keys_.size() + fresh.size());
  std::size_t i = 0, j = 0;
  while (i < keys_.size() || j < fresh.size()) {
    const bool take_old = j == fresh.size() || (i < keys_.size() && !before(key(fresh[j]), fresh[j], keys_[i], tags_[i]));
    keys.push_back(take_old ? keys_[i] : key(fresh[j]));
    tags.push_back(take_old ? tags_[i++] : fresh[j++]);
  }
  keys_.swap(keys);
  tags_.swap(tags);
}

std::vector<ProxyPair> SweepAndPrune::sweep() {
  const int other = 1 - axis_;
  std::vector<ProxyId> active;
  active_slot_.resize(proxies_.size());
  std::vector<ProxyPair> found;
  for (const std::uint32_t t : tags_) {
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
  const int before_axis = axis_;
  choose_axis();
  refresh_keys();
  // A budget of swaps near the cost of the radix sort: beyond it the scene has not moved coherently.
  const std::size_t budget = 8 * keys_.size() + 64;
  if (axis_ != before_axis || !insertion_sort(budget)) {
    stats_.full_sort = true;
    radix_sort();
  }
  merge_inserted();
  stats_.axis = axis_;
  finish_update(sweep());
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
