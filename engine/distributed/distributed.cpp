// The World over MPI ranks (distributed.h, docs/distributed.md): each update hands bodies that
// crossed into another slab to its rank and sends ghosts where reach boxes meet other slabs (one
// all-to-all exchange), runs the rank's RegionWorld, and settles the pairs that changed hands (two
// more, small): a pair new to a rank asks the rank that reported the frame before, found from the
// bodies' previous reach boxes and slabs, whether it was overlapping then.
#include <collide2d/distributed.h>

#include "engine/internal.h"
#include "shapes/internal.h"
#include "shapes/kinds.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace collide2d {
namespace {

// A body on the wire: its record, fixed size, and its reach box at the last update if it had one.
struct Wire {
  std::uint64_t id = 0;
  std::uint64_t category = 0;
  std::uint64_t mask = 0;
  std::int32_t group = 0;
  std::uint8_t kind = 0;
  std::uint8_t count = 0;  // a polygon's vertices
  std::uint8_t flags = 0;
  std::uint8_t pad = 0;
  std::array<double, 3> start{};   // x, y, angle
  std::array<double, 5> fields{};  // the shape's centre, sizes (shapes/kinds.h) and angle
  std::array<double, 2 * kMaxPolygonVertices> vertices{};
  std::array<double, 4> previous{};  // min x, min y, max x, max y
};
constexpr std::uint8_t kStatic = 1, kSensor = 2, kContinuous = 4, kHadReach = 8, kOwned = 16;

Wire wire_of(const BodyRecord& r, const std::optional<Aabb>& previous, bool owned) {
  Wire w;
  w.id = r.id;
  w.category = r.filter.category;
  w.mask = r.filter.mask;
  w.group = r.filter.group;
  w.kind = static_cast<std::uint8_t>(detail::kind_number(r.shape));
  w.flags =
      static_cast<std::uint8_t>((r.is_static ? kStatic : 0) | (r.sensor ? kSensor : 0) |
                                (r.continuous ? kContinuous : 0) | (previous ? kHadReach : 0) | (owned ? kOwned : 0));
  w.start = {r.start.position.x(), r.start.position.y(), r.start.angle};
  if (previous) w.previous = {previous->min.x(), previous->min.y(), previous->max.x(), previous->max.y()};
  const Vec2 c = center_of(r.shape);
  detail::with_kind(r.shape, [&](const auto& x, auto kind) {
    using K = decltype(kind);
    const detail::Sizes sizes = K::sizes(x);
    w.fields = {c.x(), c.y(), sizes[0], sizes[1], angle_of(r.shape)};
    if constexpr (requires { K::outline(x); }) {
      w.count = static_cast<std::uint8_t>(K::outline(x).size());
      for (std::size_t k = 0; k < K::outline(x).size(); ++k) {
        w.vertices[2 * k] = K::outline(x)[k].x();
        w.vertices[2 * k + 1] = K::outline(x)[k].y();
      }
    }
  });
  return w;
}

Shape shape_of(const Wire& w) {
  const auto& f = w.fields;
  std::array<Vec2, kMaxPolygonVertices> outline;
  for (int k = 0; k < w.count; ++k)
    outline[static_cast<std::size_t>(k)] = Vec2(w.vertices[2 * k], w.vertices[2 * k + 1]);
  return detail::made(w.kind, Vec2(f[0], f[1]), f[4], {f[2], f[3]}, std::span(outline.data(), w.count));
}

BodyRecord record_of(const Wire& w) {
  return {.id = w.id,
          .shape = shape_of(w),
          .start = {Vec2(w.start[0], w.start[1]), w.start[2]},
          .filter = {w.category, w.mask, w.group},
          .is_static = (w.flags & kStatic) != 0,
          .sensor = (w.flags & kSensor) != 0,
          .continuous = (w.flags & kContinuous) != 0};
}

std::optional<Aabb> previous_of(const Wire& w) {
  if ((w.flags & kHadReach) == 0) return std::nullopt;
  return Aabb{Vec2(w.previous[0], w.previous[1]), Vec2(w.previous[2], w.previous[3])};
}

std::vector<double> default_bounds(int ranks) {
  std::vector<double> out;
  for (int k = 0; k + 1 < ranks; ++k) out.push_back(100.0 * (k - 0.5 * (ranks - 2)));
  return out;
}

// A hash of what must be the same on every rank, to compare by its least and greatest over them.
std::uint64_t fingerprint(const DistributedOptions& o) {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < size; ++k) h = (h ^ bytes[k]) * 1099511628211ull;
  };
  const WorldOptions& w = o.world;
  for (const double x : {w.fat_margin, w.proximity_margin, w.speculative_margin, w.contact_tolerance})
    mix(&x, sizeof x);
  mix(&w.contacts, sizeof w.contacts);
  mix(&w.overlap_areas, sizeof w.overlap_areas);
  mix(&o.rebalance_every, sizeof o.rebalance_every);
  for (const double b : o.bounds) mix(&b, sizeof b);
  return h;
}

bool same_everywhere(MPI_Comm comm, std::uint64_t value) {
  std::uint64_t low = 0, high = 0;
  MPI_Allreduce(&value, &low, 1, MPI_UINT64_T, MPI_MIN, comm);
  MPI_Allreduce(&value, &high, 1, MPI_UINT64_T, MPI_MAX, comm);
  return low == high;
}

// One all-to-all exchange of fixed-size items: out[r] to rank r; returns what each rank sent here,
// and adds the bytes sent to other ranks to `bytes`.
template <class T>
std::vector<std::vector<T>> exchange(MPI_Comm comm, const std::vector<std::vector<T>>& out, std::size_t& bytes) {
  const int ranks = static_cast<int>(out.size());
  int self = 0;
  MPI_Comm_rank(comm, &self);
  std::vector<int> send_counts(out.size()), receive_counts(out.size()), send_at(out.size()), receive_at(out.size());
  std::vector<T> sending;
  for (int r = 0; r < ranks; ++r) {
    send_at[static_cast<std::size_t>(r)] = static_cast<int>(sending.size() * sizeof(T));
    send_counts[static_cast<std::size_t>(r)] = static_cast<int>(out[static_cast<std::size_t>(r)].size() * sizeof(T));
    sending.insert(sending.end(), out[static_cast<std::size_t>(r)].begin(), out[static_cast<std::size_t>(r)].end());
    if (r != self) bytes += out[static_cast<std::size_t>(r)].size() * sizeof(T);
  }
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int r = 0; r < ranks; ++r) {
    receive_at[static_cast<std::size_t>(r)] = total;
    total += receive_counts[static_cast<std::size_t>(r)];
  }
  std::vector<T> received(static_cast<std::size_t>(total) / sizeof(T));
  MPI_Alltoallv(sending.data(), send_counts.data(), send_at.data(), MPI_BYTE, received.data(), receive_counts.data(),
                receive_at.data(), MPI_BYTE, comm);
  std::vector<std::vector<T>> in(out.size());
  for (int r = 0; r < ranks; ++r) {
    const auto* first = received.data() + receive_at[static_cast<std::size_t>(r)] / static_cast<int>(sizeof(T));
    in[static_cast<std::size_t>(r)].assign(
        first, first + receive_counts[static_cast<std::size_t>(r)] / static_cast<int>(sizeof(T)));
  }
  return in;
}

// Every rank's items, on every rank, in rank order.
template <class T>
std::vector<T> gathered(MPI_Comm comm, const std::vector<T>& mine) {
  int ranks = 0;
  MPI_Comm_size(comm, &ranks);
  const int bytes = static_cast<int>(mine.size() * sizeof(T));
  std::vector<int> counts(static_cast<std::size_t>(ranks)), at(static_cast<std::size_t>(ranks));
  MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int r = 0; r < ranks; ++r) {
    at[static_cast<std::size_t>(r)] = total;
    total += counts[static_cast<std::size_t>(r)];
  }
  std::vector<T> out(static_cast<std::size_t>(total) / sizeof(T));
  MPI_Allgatherv(mine.data(), bytes, MPI_BYTE, out.data(), counts.data(), at.data(), MPI_BYTE, comm);
  return out;
}

// A pair in the events' exchange: an overlapping pair (sensor 0) or a sensor pair (sensor 1), its
// bodies by ids and, where one is a chain, the segments by their places in it.
struct Claim {
  std::uint64_t a = 0;
  std::uint64_t b = 0;
  std::uint32_t part_a = 0;
  std::uint32_t part_b = 0;
  std::uint64_t sensor = 0;
  friend auto operator<=>(const Claim&, const Claim&) = default;
};

}  // namespace

struct DistributedWorld::State {
  // A body this rank owns: its record, and its reach boxes at the last update and at this one.
  struct Own {
    BodyRecord record;
    std::optional<Aabb> previous;
    Aabb reach{};
  };

  MPI_Comm comm = MPI_COMM_NULL;
  int rank = 0;
  int ranks = 1;
  DistributedOptions options;
  RegionWorld region;
  Slabs previous_slabs;
  std::unordered_map<std::uint64_t, Own> owned;
  std::map<std::uint64_t, Own> statics;  // every rank's, replicated
  std::set<std::uint64_t> level;         // chains, added alike on every rank
  std::vector<Wire> new_statics;         // added here since the last update
  std::vector<std::uint64_t> removed_statics;
  std::unordered_map<std::uint64_t, std::optional<Aabb>> ghost_reach;  // each ghost's at the last update
  bool has_predicate = false;
  std::vector<Claim> reported;  // the pairs this rank reported at the last update, sorted
  std::vector<IdPair> began, ended;
  std::vector<IdSensorPair> sensor_began, sensor_ended;
  DistributedStats stats;
  int frame = 0;

  State(MPI_Comm c, const DistributedOptions& o, int ranks_, int rank_)
      : comm(c),
        rank(rank_),
        ranks(ranks_),
        options(o),
        region(o.world, Slabs(o.bounds.empty() ? default_bounds(ranks_) : o.bounds), rank_),
        previous_slabs(region.slabs()) {}

  void share_statics();
  void require_unused(std::uint64_t id) const {
    if (owned.count(id) != 0 || statics.count(id) != 0 || level.count(id) != 0) {
      throw std::invalid_argument("body id " + std::to_string(id) + " is in use on this rank");
    }
  }
  // Whether this rank answers queries for the body: one it owns, or on rank 0 the level.
  bool answers_for(std::uint64_t id) const {
    return owned.count(id) != 0 || (rank == 0 && (statics.count(id) != 0 || level.count(id) != 0));
  }
  std::pair<std::vector<BodyRecord>, std::vector<BodyRecord>> deal();
  std::optional<Aabb> reach_before(std::uint64_t id, ShapeId shape) const;
  Aabb reach_of(const BodyRecord& r) const {
    return reach_box(r.shape, r.continuous ? std::optional(r.start) : std::nullopt, options.world);
  }
  std::vector<std::pair<Claim, int>> current() const;
  void settle_events(const std::vector<std::pair<Claim, int>>& now);
  void rebalance();
};

DistributedWorld::DistributedWorld(MPI_Comm comm, const DistributedOptions& options) {
  MPI_Comm own = MPI_COMM_NULL;
  MPI_Comm_dup(comm, &own);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(own, &rank);
  MPI_Comm_size(own, &ranks);
  const bool same = same_everywhere(own, fingerprint(options));
  const bool fits = options.bounds.empty() || static_cast<int>(options.bounds.size()) == ranks - 1;
  int fit_everywhere = fits ? 1 : 0, all_fit = 0;
  MPI_Allreduce(&fit_everywhere, &all_fit, 1, MPI_INT, MPI_MIN, own);
  if (!same || all_fit == 0) {
    MPI_Comm_free(&own);
    throw std::invalid_argument(!same ? "DistributedWorld options differ between ranks"
                                      : "DistributedWorld needs ranks - 1 = " + std::to_string(ranks - 1) +
                                            " slab bounds (or none)");
  }
  state_ = std::make_unique<State>(own, options, ranks, rank);
}

DistributedWorld::~DistributedWorld() {
  if (state_) MPI_Comm_free(&state_->comm);
}

void DistributedWorld::add(std::uint64_t id, const Shape& shape, const BodyDef& def, bool continuous) {
  State& s = *state_;
  s.require_unused(id);
  validate(shape);
  if (continuous && def.is_static) throw std::invalid_argument("a static body cannot be continuous");
  const BodyRecord r{.id = id,
                     .shape = shape,
                     .start = pose_of(shape),
                     .filter = def.filter,
                     .is_static = def.is_static,
                     .sensor = def.sensor,
                     .continuous = continuous};
  if (def.is_static) {
    s.new_statics.push_back(wire_of(r, std::nullopt, true));
  } else {
    s.owned.emplace(id, State::Own{r, std::nullopt});
  }
}

void DistributedWorld::add_chain(std::uint64_t id, std::span<const Vec2> points, bool loop, const ChainDef& def) {
  State& s = *state_;
  s.require_unused(id);
  s.region.add_chain(id, points, loop, def);
  s.level.insert(id);
}

void DistributedWorld::move_to(std::uint64_t id, const Vec2& position, double angle) {
  const auto it = state_->owned.find(id);
  if (it == state_->owned.end()) throw std::out_of_range("body " + std::to_string(id) + " is not this rank's");
  validate_point(position, "move_to position");
  detail::require_finite(angle, "move_to angle");
  detail::place(it->second.record.shape, position, angle);
}

void DistributedWorld::remove(std::uint64_t id) {
  State& s = *state_;
  if (s.owned.erase(id) != 0) return;
  if (s.statics.count(id) != 0) {
    s.removed_statics.push_back(id);
    return;
  }
  throw std::out_of_range("body " + std::to_string(id) + " is not this rank's");
}

bool DistributedWorld::owns(std::uint64_t id) const { return state_->owned.count(id) != 0; }

std::vector<std::uint64_t> DistributedWorld::owned() const {
  std::vector<std::uint64_t> out;
  for (const auto& [id, own] : state_->owned) out.push_back(id);
  std::sort(out.begin(), out.end());
  return out;
}

const Shape& DistributedWorld::shape(std::uint64_t id) const {
  const auto it = state_->owned.find(id);
  if (it == state_->owned.end()) throw std::out_of_range("body " + std::to_string(id) + " is not this rank's");
  return it->second.record.shape;
}

void DistributedWorld::set_pair_predicate(std::function<bool(std::uint64_t, std::uint64_t)> predicate) {
  state_->has_predicate = static_cast<bool>(predicate);
  state_->region.set_pair_predicate(std::move(predicate));
}

// Statics added or removed on any rank, on every rank.
void DistributedWorld::State::share_statics() {
  for (const Wire& w : gathered(comm, new_statics)) statics.emplace(w.id, Own{record_of(w), std::nullopt});
  for (const std::uint64_t id : gathered(comm, removed_statics)) statics.erase(id);
  new_statics.clear();
  removed_statics.clear();
}

// Each moving body this rank owns to its owner (itself, or the rank it migrates to) and as a ghost
// to every other slab its reach box meets; what the others send here. Returns the owned records
// (statics included) and the ghosts this rank holds for the update.
std::pair<std::vector<BodyRecord>, std::vector<BodyRecord>> DistributedWorld::State::deal() {
  std::vector<std::vector<Wire>> out(static_cast<std::size_t>(ranks));
  const Slabs& slabs = region.slabs();
  stats.migrated = 0;
  ghost_reach.clear();
  std::vector<BodyRecord> mine, ghosts;
  std::uint64_t twice = ~std::uint64_t{0};  // the least id that came to this rank twice
  for (auto it = owned.begin(); it != owned.end();) {
    const BodyRecord& r = it->second.record;
    const Aabb& reach = it->second.reach = reach_of(r);
    const auto [first, last] = slabs.regions_of(reach);
    for (int k = first; k <= last; ++k) {
      if (k != rank) out[static_cast<std::size_t>(k)].push_back(wire_of(r, it->second.previous, k == first));
    }
    if (first == rank) {
      ++it;
      continue;
    }
    // Handed on; still a ghost here where its reach box meets this slab.
    if (first < rank && rank <= last) {
      ghosts.push_back(r);
      ghost_reach[r.id] = it->second.previous;
    }
    ++stats.migrated;
    it = owned.erase(it);
  }
  for (const auto& from : exchange(comm, out, stats.bytes_sent)) {
    for (const Wire& w : from) {
      if ((w.flags & kOwned) != 0) {
        const BodyRecord r = record_of(w);
        if (!owned.emplace(w.id, Own{r, previous_of(w), reach_of(r)}).second) twice = std::min(twice, w.id);
      } else {
        ghosts.push_back(record_of(w));
        ghost_reach[w.id] = previous_of(w);
      }
    }
  }
  // Every rank throws alike, so that none is left waiting in the next exchange.
  MPI_Allreduce(MPI_IN_PLACE, &twice, 1, MPI_UINT64_T, MPI_MIN, comm);
  if (twice != ~std::uint64_t{0}) {
    throw std::logic_error("body id " + std::to_string(twice) + " was added on two ranks: ids must be unique");
  }
  for (const auto& [id, own] : owned) mine.push_back(own.record);
  for (const auto& [id, own] : statics) mine.push_back(own.record);
  return {mine, ghosts};
}

// A shape's reach box at the last update: a chain's segment's never changes.
std::optional<Aabb> DistributedWorld::State::reach_before(std::uint64_t id, ShapeId shape) const {
  if (const std::optional<Aabb> level = region.level_reach(shape)) return level;
  if (const auto it = owned.find(id); it != owned.end()) return it->second.previous;
  if (const auto it = statics.find(id); it != statics.end()) return it->second.previous;
  const auto it = ghost_reach.find(id);
  return it == ghost_reach.end() ? std::nullopt : it->second;
}

// This update's reported pairs as claims, sorted, each with the rank whose slab held its owner
// point at the last update (this rank where a body had no reach box then).
std::vector<std::pair<Claim, int>> DistributedWorld::State::current() const {
  std::vector<std::pair<Claim, int>> now;
  const auto add = [&](std::uint64_t a, ShapeId sa, std::uint64_t b, ShapeId sb, std::uint64_t sensor) {
    const std::optional<Aabb> ra = reach_before(a, sa), rb = reach_before(b, sb);
    const int before = ra && rb ? previous_slabs.region_of(owner_point(*ra, *rb).x()) : rank;
    now.emplace_back(Claim{a, b, region.part_of(sa), region.part_of(sb), sensor}, before);
  };
  for (const ShapePair& p : region.report().overlapping) add(p.user_a, p.shape_a, p.user_b, p.shape_b, 0);
  for (const SensorPair& p : region.report().sensing)
    add(p.user_sensor, p.sensor_shape, p.user_visitor, p.visitor_shape, 1);
  std::sort(now.begin(), now.end());
  return now;
}

namespace {

// Claims into overlapping pairs and sensor pairs, in their order.
void split(const std::vector<Claim>& claims, std::vector<IdPair>& pairs, std::vector<IdSensorPair>& sensors) {
  pairs.clear();
  sensors.clear();
  for (const Claim& c : claims) {
    if (c.sensor != 0) {
      sensors.push_back({c.a, c.b});
    } else {
      pairs.push_back({c.a, c.b});
    }
  }
}

}  // namespace

// began: reported now and not at the last update by any rank; ended: reported here at the last
// update and by no rank now. A pair new here whose bodies both had reach boxes then asks the rank
// whose slab held its owner point then; that rank answers whether it reported it, and keeps it from
// ending.
void DistributedWorld::State::settle_events(const std::vector<std::pair<Claim, int>>& pairs) {
  std::vector<std::vector<Claim>> asks(static_cast<std::size_t>(ranks));
  std::vector<Claim> fresh, now;
  for (const auto& [c, before] : pairs) {
    now.push_back(c);
    if (std::binary_search(reported.begin(), reported.end(), c)) continue;
    if (before == rank) {
      fresh.push_back(c);
    } else {
      asks[static_cast<std::size_t>(before)].push_back(c);
    }
  }
  const auto asked = exchange(comm, asks, stats.bytes_sent);
  std::set<Claim> going_on;
  std::vector<std::vector<std::uint8_t>> answers(static_cast<std::size_t>(ranks));
  for (std::size_t r = 0; r < asked.size(); ++r) {
    for (const Claim& c : asked[r]) {
      const bool was = std::binary_search(reported.begin(), reported.end(), c);
      answers[r].push_back(was ? 1 : 0);
      if (was) going_on.insert(c);
    }
  }
  const auto answered = exchange(comm, answers, stats.bytes_sent);
  for (std::size_t r = 0; r < answered.size(); ++r) {
    for (std::size_t k = 0; k < answered[r].size(); ++k) {
      if (answered[r][k] == 0) fresh.push_back(asks[r][k]);
    }
  }
  std::sort(fresh.begin(), fresh.end());
  std::vector<Claim> gone;
  for (const Claim& c : reported) {
    if (!std::binary_search(now.begin(), now.end(), c) && going_on.count(c) == 0) gone.push_back(c);
  }
  split(fresh, began, sensor_began);
  split(gone, ended, sensor_ended);
  reported = std::move(now);
}

// Bounds at the quantiles of the owned bodies' reach boxes' left ends, so that each slab owns about
// as many.
void DistributedWorld::State::rebalance() {
  std::vector<double> lefts;
  for (const auto& [id, own] : owned) lefts.push_back(own.reach.min.x());
  std::vector<double> all = gathered(comm, lefts);
  if (all.size() >= static_cast<std::size_t>(ranks)) region.set_slabs(Slabs::balanced(std::move(all), ranks));
}

void DistributedWorld::update() {
  State& s = *state_;
  const auto start = std::chrono::steady_clock::now();
  if (!same_everywhere(s.comm, s.has_predicate ? 1 : 0)) {
    throw std::logic_error("a pair predicate is set on some ranks and not on others");
  }
  s.stats.bytes_sent = 0;
  s.share_statics();
  const auto [mine, ghosts] = s.deal();
  s.region.sync(mine, ghosts);
  s.region.update();
  s.settle_events(s.current());
  // Each body's reach box of this update, for the next one's events; a continuous body's next step
  // starts where it is.
  for (auto& [id, own] : s.owned) {
    own.previous = own.reach;
    if (own.record.continuous) own.record.start = pose_of(own.record.shape);
  }
  for (auto& [id, own] : s.statics) {
    if (!own.previous) own.previous = s.reach_of(own.record);
  }
  s.previous_slabs = s.region.slabs();
  ++s.frame;
  if (s.options.rebalance_every > 0 && s.frame % s.options.rebalance_every == 0) s.rebalance();
  s.stats.owned = s.owned.size();
  s.stats.ghosts = ghosts.size();
  s.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

const RegionReport& DistributedWorld::report() const { return state_->region.report(); }
const std::vector<IdPair>& DistributedWorld::began() const { return state_->began; }
const std::vector<IdPair>& DistributedWorld::ended() const { return state_->ended; }
const std::vector<IdSensorPair>& DistributedWorld::sensor_began() const { return state_->sensor_began; }
const std::vector<IdSensorPair>& DistributedWorld::sensor_ended() const { return state_->sensor_ended; }
const World& DistributedWorld::world() const { return state_->region.world(); }
int DistributedWorld::rank() const { return state_->rank; }
int DistributedWorld::ranks() const { return state_->ranks; }
const Slabs& DistributedWorld::slabs() const { return state_->region.slabs(); }
const DistributedStats& DistributedWorld::stats() const { return state_->stats; }

namespace {

// A query's bodies from every rank, each answered by one (State::answers_for), sorted.
template <class State>
std::vector<std::uint64_t> everyone_found(const State& s, const std::vector<BodyId>& found) {
  const World& world = s.region.world();
  std::vector<std::uint64_t> mine;
  for (const BodyId b : found) {
    if (s.answers_for(world.user_id(b))) mine.push_back(world.user_id(b));
  }
  std::vector<std::uint64_t> all = gathered(s.comm, mine);
  std::sort(all.begin(), all.end());
  return all;
}

// A hit: how far along (a distance or a fraction) and the body.
struct Hit {
  double at = 0.0;
  std::uint64_t id = 0;
  bool operator<(const Hit& o) const { return std::pair(at, id) < std::pair(o.at, o.id); }
};

// The first of every rank's first hits (the lowest id on a tie).
std::optional<std::pair<std::uint64_t, double>> first_of_all(MPI_Comm comm, const std::optional<Hit>& mine) {
  std::vector<Hit> one;
  if (mine) one.push_back(*mine);
  const std::vector<Hit> all = gathered(comm, one);
  if (all.empty()) return std::nullopt;
  const Hit best = *std::min_element(all.begin(), all.end());
  return std::pair(best.id, best.at);
}

}  // namespace

std::vector<std::uint64_t> DistributedWorld::overlapping(const Shape& shape) {
  return everyone_found(*state_, state_->region.world().overlapping(shape));
}

std::vector<std::uint64_t> DistributedWorld::overlapping(const Aabb& box) {
  return everyone_found(*state_, state_->region.world().overlapping(box));
}

std::optional<std::pair<std::uint64_t, double>> DistributedWorld::ray_cast(const Vec2& origin, const Vec2& direction,
                                                                           double max_distance) {
  const State& s = *state_;
  std::optional<Hit> mine;
  s.region.world().ray_cast(origin, direction, max_distance, [&](const RayHit& h) {
    const Hit hit{h.distance, s.region.world().user_id(h.body)};
    if (s.answers_for(hit.id) && (!mine || hit < *mine)) mine = hit;
    return -1.0;  // every hit: a nearer one may be a ghost's
  });
  return first_of_all(s.comm, mine);
}

std::optional<std::pair<std::uint64_t, double>> DistributedWorld::cast(const Shape& shape, const Vec2& translation) {
  const State& s = *state_;
  std::optional<Hit> mine;
  s.region.world().cast(shape, translation, [&](const BodyCastHit& h) {
    const Hit hit{h.fraction, s.region.world().user_id(h.body)};
    if (s.answers_for(hit.id) && (!mine || hit < *mine)) mine = hit;
    return -1.0;
  });
  return first_of_all(s.comm, mine);
}

std::vector<IdSensorPair> DistributedWorld::sensing_everywhere() {
  std::vector<IdSensorPair> mine;
  for (const SensorPair& p : report().sensing) mine.push_back({p.user_sensor, p.user_visitor});
  std::vector<IdSensorPair> all = gathered(state_->comm, mine);
  std::sort(all.begin(), all.end());
  return all;
}

FrameStats DistributedWorld::totals() {
  const RegionReport& r = report();
  std::array<std::uint64_t, 5> mine{r.overlapping.size(), r.proximity.size(), r.contacts.size(), r.impacts.size(),
                                    r.sensing.size()};
  std::array<std::uint64_t, 5> sum{};
  MPI_Allreduce(mine.data(), sum.data(), 5, MPI_UINT64_T, MPI_SUM, state_->comm);
  FrameStats out;
  out.overlapping = sum[0];
  out.proximity = sum[1];
  out.contacts = sum[2];
  out.impacts = sum[3];
  out.sensing = sum[4];
  return out;
}

}  // namespace collide2d
