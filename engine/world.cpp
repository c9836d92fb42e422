#include <collide2d/world.h>

#include "engine/thread_pool.h"
#include "narrowphase/kernel_order.h"
#include "narrowphase/batch/overlap_pairs.h"
#include <collide2d/ray_cast.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

namespace collide2d {
namespace {

void require_finite(double value, const char* what) {
  if (!std::isfinite(value)) {
    std::ostringstream msg;
    msg << what << " must be finite (got " << value << ')';
    throw std::invalid_argument(msg.str());
  }
}

void require_margin(double value, const char* what) {
  require_finite(value, what);
  if (value < 0.0) throw std::invalid_argument(std::string(what) + " must not be negative");
}

Shape posed(Shape shape, const Vec2& center, double angle) {
  std::visit(
      [&](auto& s) {
        s.center = center;
        if constexpr (!std::is_same_v<std::decay_t<decltype(s)>, Circle>) s.angle = angle;
      },
      shape);
  return shape;
}

Aabb grown(const Aabb& box, double by) { return {box.min.array() - by, box.max.array() + by}; }

Aabb merged(const Aabb& p, const Aabb& q) { return {p.min.cwiseMin(q.min), p.max.cwiseMax(q.max)}; }

// Every pose of a step from `start` to `end` (its centre on the segment, any angle) lies in the
// segment grown by the shape's reach; the two end boxes are kept in it against rounding.
Aabb swept(const Shape& start, const Shape& end) {
  const Vec2 c0 = center_of(start), c1 = center_of(end);
  const double r = reach_of(end);
  return merged(merged({c0.cwiseMin(c1).array() - r, c0.cwiseMax(c1).array() + r}, aabb(start)), aabb(end));
}

Motion step_of(const Shape& start, const Shape& end) {
  return {center_of(end) - center_of(start), angle_of(end) - angle_of(start)};
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool lets_through(const QueryFilter& q, const Filter& f) { return (f.category & q.mask) != 0 && (f.mask & q.category) != 0; }

}  // namespace

bool should_pair(const Filter& a, const Filter& b) {
  if (a.group == b.group && a.group != 0) return a.group > 0;
  return (a.mask & b.category) != 0 && (a.category & b.mask) != 0;
}

World::World(const WorldOptions& options)
    : broad_(options.fat_margin),
      proximity_margin_(options.proximity_margin),
      contacts_on_(options.contacts),
      speculative_margin_(options.contacts ? options.speculative_margin : 0.0) {
  require_margin(options.proximity_margin, "proximity margin");
  require_margin(options.speculative_margin, "speculative margin");
  pool_ = std::make_unique<detail::ThreadPool>(options.threads > 0 ? options.threads
                                                                   : std::max(1u, std::thread::hardware_concurrency()));
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

bool World::contains(BodyId id) const {
  return id.index < bodies_.size() && bodies_[id.index].alive && bodies_[id.index].generation == id.generation;
}

const World::Body& World::body(BodyId id) const {
  if (contains(id)) return bodies_[id.index];
  const std::string name = "body " + std::to_string(id.index) + " (generation " + std::to_string(id.generation) + ")";
  const bool stale = id.index < bodies_.size() && id.generation != 0 && id.generation < bodies_[id.index].generation;
  if (!stale) throw std::out_of_range("unknown " + name);
  throw std::out_of_range("stale " + name + ": that body was removed; its slot is at generation " +
                          std::to_string(bodies_[id.index].generation));
}

World::Body& World::body(BodyId id) { return const_cast<Body&>(std::as_const(*this).body(id)); }

const Shape& World::shape(BodyId id) const { return body(id).shape; }
std::uint64_t World::user_id(BodyId id) const { return body(id).user_id; }
const Filter& World::filter(BodyId id) const { return body(id).filter; }
bool World::is_static(BodyId id) const { return body(id).is_static; }
bool World::is_sensor(BodyId id) const { return body(id).sensor; }

void World::set_filter(BodyId id, const Filter& filter) { body(id).filter = filter; }

void World::set_pair_predicate(std::function<bool(BodyId, BodyId)> predicate) { pair_predicate_ = std::move(predicate); }

bool World::passes(std::uint32_t a, std::uint32_t b) const {
  return should_pair(bodies_[a].filter, bodies_[b].filter) && (!pair_predicate_ || pair_predicate_(id_of(a), id_of(b)));
}

std::vector<BodyId> World::bodies() const {
  std::vector<BodyId> out;
  for (std::uint32_t index = 0; index < bodies_.size(); ++index) {
    if (bodies_[index].alive) out.push_back(id_of(index));
  }
  return out;
}

Aabb World::broad_box(const Aabb& box) const {
  return grown(box, 0.5 * std::max(proximity_margin_, speculative_margin_));
}

Aabb World::broad_box(const Body& b) const { return broad_box(b.continuous ? swept(b.start, b.shape) : b.box); }

// Into the broad phase of its kind: the static tree, or the sweep and prune and the moving tree.
void World::enter(std::uint32_t index) {
  Body& b = bodies_[index];
  if (b.is_static) {
    b.leaf = static_tree_.insert(broad_box(b), index);
    statics_changed_ = true;
    return;
  }
  b.proxy = broad_.insert(broad_box(b));
  if (b.proxy >= body_of_.size()) body_of_.resize(static_cast<std::size_t>(b.proxy) + 1, kNoBody);
  body_of_[b.proxy] = index;
  b.leaf = moving_tree_.insert(broad_.fat_box(b.proxy), index);
  b.loose = -1;
  b.queried = kNowhere;
}

void World::leave(std::uint32_t index) {
  Body& b = bodies_[index];
  if (b.is_static) {
    static_tree_.remove(b.leaf);
    statics_changed_ = true;
    return;
  }
  broad_.remove(b.proxy);
  body_of_[b.proxy] = kNoBody;
  moving_tree_.remove(b.leaf);
  if (b.loose >= 0) unloose(index);
  b.statics.clear();
}

void World::unloose(std::uint32_t index) {
  const auto at = static_cast<std::size_t>(bodies_[index].loose);
  loose_[at] = loose_.back();
  bodies_[loose_[at]].loose = static_cast<std::int32_t>(at);
  loose_.pop_back();
  bodies_[index].loose = -1;
}

// Its broad-phase box, after a new pose or margin.
void World::place(std::uint32_t index) {
  Body& b = bodies_[index];
  if (b.is_static) {
    static_tree_.move(b.leaf, broad_box(b));
    statics_changed_ = true;
  } else if (broad_.move(b.proxy, broad_box(b)) && b.loose < 0) {
    b.loose = static_cast<std::int32_t>(loose_.size());
    loose_.push_back(index);
  }
}

namespace {

// A tree with a quarter or more of its leaves inserted since its last rebuild.
bool fresh(const AabbTree& tree) { return tree.size() >= 64 && 4 * tree.inserted_since_rebuild() >= tree.size(); }

}  // namespace

// The moving bodies' tree catches up: each loose body's leaf takes its fat box (its ancestors
// refitted), and the tree is rebuilt when a quarter of it is new since its last rebuild or its inner
// perimeters have grown 1.5 times since. It runs alongside the narrow phase, which does not use it.
void World::refresh_moving_tree() {
  tree_boxes_.clear();
  for (const std::uint32_t index : loose_) {
    Body& b = bodies_[index];
    tree_boxes_.emplace_back(b.leaf, broad_.fat_box(b.proxy));
    b.loose = -1;
  }
  moving_tree_.set_boxes(tree_boxes_);
  const bool moved = !loose_.empty();
  loose_.clear();
  const bool worn = moved && moving_tree_.size() >= 64 && moving_tree_.inner_perimeter() > 1.5 * moving_perimeter_;
  if (fresh(moving_tree_) || worn) {
    moving_tree_.rebuild();
    moving_perimeter_ = moving_tree_.inner_perimeter();
  }
}

BodyId World::add(const Shape& shape, const BodyDef& def) {
  validate(shape);
  std::uint32_t index;
  if (free_.empty()) {
    index = static_cast<std::uint32_t>(bodies_.size());
    bodies_.emplace_back();
  } else {
    index = free_.back();
    free_.pop_back();
  }
  Body& b = bodies_[index];  // a reused slot keeps the generation remove() gave it
  b.shape = shape;
  b.orientation = Orientation::of(angle_of(shape));
  b.box = aabb(shape, b.orientation);
  b.user_id = def.user_id;
  b.filter = def.filter;
  b.is_static = def.is_static;
  b.sensor = def.sensor;
  b.continuous = false;
  b.alive = true;
  enter(index);
  ++live_;
  return id_of(index);
}

void World::set_pose(BodyId id, const Vec2& center, double angle) {
  Body& b = body(id);
  require_finite(center.x(), "pose x");
  require_finite(center.y(), "pose y");
  require_finite(angle, "pose angle");
  const Shape moved = posed(b.shape, center, angle);
  validate(moved);  // the range of the centre
  b.shape = moved;
  b.orientation = Orientation::of(angle_of(moved));
  b.box = aabb(moved, b.orientation);
  place(id.index);
}

void World::move_by(BodyId id, const Vec2& shift, double turn) {
  const Shape& s = body(id).shape;
  set_pose(id, center_of(s) + shift, angle_of(s) + turn);
}

void World::set_static(BodyId id, bool is_static) {
  Body& b = body(id);
  if (b.is_static == is_static) return;
  if (b.continuous) set_continuous(id, false);
  leave(id.index);
  b.is_static = is_static;
  enter(id.index);
}

void World::set_continuous(BodyId id, bool continuous) {
  Body& b = body(id);
  if (b.continuous == continuous) return;
  if (b.is_static) {
    throw std::invalid_argument("body " + std::to_string(id.index) + " is static: only moving bodies can be continuous");
  }
  if (continuous) {
    continuous_.push_back(id.index);
  } else {
    continuous_.erase(std::find(continuous_.begin(), continuous_.end(), id.index));
  }
  b.continuous = continuous;
  b.start = b.shape;
  place(id.index);
}

void World::remove(BodyId id) {
  Body& b = body(id);
  if (b.continuous) set_continuous(id, false);
  leave(id.index);
  b.alive = false;
  b.generation = b.generation == UINT32_MAX ? 1 : b.generation + 1;  // 0 names no body
  free_.push_back(id.index);
  --live_;
}

void World::set_proximity_margin(double margin) {
  require_margin(margin, "proximity margin");
  proximity_margin_ = margin;
  for (const BodyId id : bodies()) place(id.index);
}

// The pairs of moving bodies from the sweep and prune, and each moving body's pairs with the static
// bodies it keeps, looked up again where its fat box or the statics changed.
void World::find_candidates() {
  // A few thousand moving bodies sort and sweep in less time than waking the pool takes.
  constexpr std::size_t kParallelBodies = 4096;
  broad_.update([this](std::size_t count, const std::function<void(std::size_t)>& task) {
    if (broad_.size() < kParallelBodies) {
      for (std::size_t k = 0; k < count; ++k) task(k);
    } else {
      pool_->run(count, task);
    }
  });
  if (fresh(static_tree_)) static_tree_.rebuild();
  candidates_.clear();
  const auto ordered = [](std::uint32_t a, std::uint32_t b) { return a < b ? std::pair(a, b) : std::pair(b, a); };
  for (const ProxyPair& p : broad_.pairs()) candidates_.push_back(ordered(body_of_[p.a], body_of_[p.b]));
  const bool statics = static_tree_.size() > 0 || statics_changed_;  // else every body's list is empty
  for (ProxyId proxy = 0; statics && proxy < body_of_.size(); ++proxy) {
    const std::uint32_t index = body_of_[proxy];
    if (index == kNoBody) continue;
    Body& b = bodies_[index];
    const Aabb& fat = broad_.fat_box(proxy);
    if (statics_changed_ || !encloses(b.queried, fat)) {
      // Looked up around the fat box, half its larger side further, so that the next few frames'
      // fat boxes stay within it and need no look-up (that halved the broad phase of bench_world's
      // level): the statics kept are a superset, and the test below keeps those the fat box meets.
      b.queried = grown(fat, 0.5 * (fat.max - fat.min).maxCoeff());
      b.statics.clear();
      static_tree_.query(b.queried, [&](std::uint32_t s) {
        if (intersects(broad_box(bodies_[s]), b.queried)) b.statics.push_back(s);
      });
      ++stats_.requeried;
    }
    for (const std::uint32_t s : b.statics) {
      if (intersects(broad_box(bodies_[s]), fat)) candidates_.push_back(ordered(index, s));
    }
  }
  statics_changed_ = false;
}

void World::Found::clear() {
  overlapping.clear();
  sensing.clear();
  proximity.clear();
  contacts.clear();
  impacts.clear();
  filtered = 0;
  verdicts.clear();
  std::apply([](auto&... batch) { (batch.clear(), ...); }, batches);
}

template <class A, class B>
void World::Batch<A, B>::add(std::uint32_t place, std::uint32_t a_body, std::uint32_t b_body) {
  if (places.capacity() < kPairsPerChunk) {
    places.reserve(kPairsPerChunk);
    a.reserve(kPairsPerChunk);
    b.reserve(kPairsPerChunk);
    verdicts.reserve(kPairsPerChunk);
  }
  places.push_back(place);
  a.push_back(a_body);
  b.push_back(b_body);
}

template <class A, class B>
void World::Batch<A, B>::run(const std::vector<Body>& bodies, std::vector<Verdict>& chunk_verdicts) {
  verdicts.resize(places.size());
  detail::overlap_pairs<A, B>(
      [&](std::size_t k) {
        const Body& x = bodies[a[k]];
        const Body& y = bodies[b[k]];
        return detail::PairRef<A, B>{std::get<A>(x.shape), x.orientation, std::get<B>(y.shape), y.orientation};
      },
      verdicts);
  for (std::size_t j = 0; j < places.size(); ++j) chunk_verdicts[places[j]] = verdicts[j] != 0 ? Verdict::touching : Verdict::apart;
}

template <class A, class B>
void World::Batch<A, B>::clear() {
  places.clear();
  a.clear();
  b.clear();
}

void World::update() {
  const auto start = std::chrono::steady_clock::now();
  stats_ = {};
  find_candidates();
  stats_.broad_seconds = seconds_since(start);
  const auto narrow_start = std::chrono::steady_clock::now();
  narrow_phase();
  for (const std::uint32_t index : continuous_) {  // the next step begins here
    bodies_[index].start = bodies_[index].shape;
    place(index);
  }
  stats_.narrow_seconds = seconds_since(narrow_start);
  stats_.candidates = candidates_.size();
  stats_.overlapping = overlapping_.size();
  stats_.proximity = proximity_.size();
  stats_.contacts = contacts_.size();
  stats_.impacts = impacts_.size();
  stats_.sensing = sensing_.size();
}

// The candidate pairs in chunks, in order, on the pool with the moving tree's refresh beside them;
// then each result list joined in chunk order and sorted by pair, which makes it the same for any
// thread count.
void World::narrow_phase() {
  const std::size_t chunks = std::max<std::size_t>(1, (candidates_.size() + kPairsPerChunk - 1) / kPairsPerChunk);
  if (chunks_.size() < chunks) chunks_.resize(chunks);
  const auto task = [this](std::size_t task) {
    if (task == 0) {  // the longest task, so first
      refresh_moving_tree();
      return;
    }
    const std::size_t k = task - 1;
    narrow_chunk(k * kPairsPerChunk, std::min(candidates_.size(), (k + 1) * kPairsPerChunk), chunks_[k]);
  };
  if (chunks < 4) {  // a thousand pairs take tens of microseconds: less than waking the pool
    for (std::size_t k = 0; k <= chunks; ++k) task(k);
  } else {
    pool_->run(chunks + 1, task);
  }
  now_.clear();
  sensed_.clear();
  proximity_.clear();
  contacts_.clear();
  impacts_.clear();
  for (std::size_t k = 0; k < chunks; ++k) {
    const Found& f = chunks_[k];
    now_.insert(now_.end(), f.overlapping.begin(), f.overlapping.end());
    sensed_.insert(sensed_.end(), f.sensing.begin(), f.sensing.end());
    proximity_.insert(proximity_.end(), f.proximity.begin(), f.proximity.end());
    contacts_.insert(contacts_.end(), f.contacts.begin(), f.contacts.end());
    impacts_.insert(impacts_.end(), f.impacts.begin(), f.impacts.end());
    stats_.filtered += f.filtered;
  }
  const auto by_pair = [](const auto& p, const auto& q) { return std::tie(p.a, p.b) < std::tie(q.a, q.b); };
  std::sort(now_.begin(), now_.end());
  std::sort(sensed_.begin(), sensed_.end());
  std::sort(proximity_.begin(), proximity_.end(), by_pair);
  std::sort(contacts_.begin(), contacts_.end(), by_pair);
  std::sort(impacts_.begin(), impacts_.end(), by_pair);
  replace_pairs(overlapping_, now_, began_, ended_);
  replace_pairs(sensing_, sensed_, sensor_began_, sensor_ended_);
}

// The candidate pairs [begin, end): first every overlap test, the chunk's pairs in batches by kind
// (the same verdicts as one by one, 2 to 8 pairs at a time), then each pair's results in order.
void World::narrow_chunk(std::size_t begin, std::size_t end, Found& out) const {
  out.clear();
  for (std::size_t i = begin; i < end; ++i) out.verdicts.push_back(overlap_verdict(candidates_[i].first, candidates_[i].second, out));
  std::apply([&](auto&... batch) { (batch.run(bodies_, out.verdicts), ...); }, out.batches);
  for (std::size_t i = begin; i < end; ++i) {
    const Verdict v = out.verdicts[i - begin];
    if (v != Verdict::skipped) narrow(candidates_[i].first, candidates_[i].second, v == Verdict::touching, out);
  }
}

// A pair dropped by the filters or made of two sensors is skipped; a pair whose boxes meet joins the
// batch of its kind, in kernel order.
World::Verdict World::overlap_verdict(std::uint32_t a, std::uint32_t b, Found& out) const {
  if (!passes(a, b)) {
    ++out.filtered;
    return Verdict::skipped;
  }
  const Body& x = bodies_[a];
  const Body& y = bodies_[b];
  if (x.sensor && y.sensor) return Verdict::skipped;
  if (!intersects(x.box, y.box)) return Verdict::apart;
  const auto place = static_cast<std::uint32_t>(out.verdicts.size());
  return std::visit(
      [&](const auto& xs, const auto& ys) {
        using X = std::decay_t<decltype(xs)>;
        using Y = std::decay_t<decltype(ys)>;
        if constexpr (detail::rank<X>() <= detail::rank<Y>()) {
          std::get<Batch<X, Y>>(out.batches).add(place, a, b);
          return Verdict::batched;
        } else {
          std::get<Batch<Y, X>>(out.batches).add(place, b, a);
          return Verdict::batched;
        }
      },
      x.shape, y.shape);
}

// One candidate pair that passed the filters, given its overlap verdict: a sensor's overlap, or the
// solid pair's overlap, proximity, contact and time of impact, as far as they were asked for.
void World::narrow(std::uint32_t a, std::uint32_t b, bool touching, Found& out) const {
  const Body& x = bodies_[a];
  const Body& y = bodies_[b];
  if (x.sensor || y.sensor) {
    if (touching) out.sensing.push_back(x.sensor ? SensorPair{id_of(a), id_of(b)} : SensorPair{id_of(b), id_of(a)});
    return;
  }
  const ContactOptions manifold{.margin = speculative_margin_};
  if (x.continuous || y.continuous) impact(a, b, out);
  if (touching) {
    out.overlapping.push_back({id_of(a), id_of(b)});
    if (contacts_on_) out.contacts.push_back({id_of(a), id_of(b), contact(x.shape, x.orientation, y.shape, y.orientation, manifold)});
    return;
  }
  if (proximity_margin_ > 0.0) {
    const DistanceResult d = distance(x.shape, y.shape);
    if (!d.overlapping && d.distance <= proximity_margin_) out.proximity.push_back({id_of(a), id_of(b), d});
  }
  if (speculative_margin_ > 0.0 && intersects(grown(x.box, 0.5 * speculative_margin_), grown(y.box, 0.5 * speculative_margin_))) {
    const Contact c = contact(x.shape, x.orientation, y.shape, y.orientation, manifold);
    if (c.separation <= speculative_margin_) out.contacts.push_back({id_of(a), id_of(b), c});
  }
}

// A pair with a continuous body, over the step: each continuous body from its start pose, any other
// at rest where it is now. Pairs that start the step overlapping are the overlap test's.
void World::impact(std::uint32_t a, std::uint32_t b, Found& out) const {
  const Body& x = bodies_[a];
  const Body& y = bodies_[b];
  const auto from = [](const Body& body) { return body.continuous ? body.start : body.shape; };
  const auto motion = [](const Body& body) { return body.continuous ? step_of(body.start, body.shape) : Motion{}; };
  const TimeOfImpact r = time_of_impact(from(x), motion(x), from(y), motion(y));
  if (r.status == ToiStatus::hit || r.status == ToiStatus::stalled) {
    out.impacts.push_back({id_of(a), id_of(b), r.t, r.normal, r.point});
  }
}

// The solid bodies the filter lets through whose tight box meets `box` and that pass `test`, by index.
template <class Test>
std::vector<BodyId> World::select(const Aabb& box, const QueryFilter& filter, Test test) const {
  std::vector<std::uint32_t> found;
  const auto visit = [&](std::uint32_t index) {
    const Body& b = bodies_[index];
    if (!b.sensor && lets_through(filter, b.filter) && intersects(b.box, box) && test(b.shape)) found.push_back(index);
  };
  moving_tree_.query(box, [&](std::uint32_t index) {
    if (bodies_[index].loose < 0) visit(index);  // a loose body's leaf is out of date: see below
  });
  for (const std::uint32_t index : loose_) visit(index);
  static_tree_.query(box, visit);
  std::sort(found.begin(), found.end());
  std::vector<BodyId> out;
  out.reserve(found.size());
  for (const std::uint32_t index : found) out.push_back(id_of(index));
  return out;
}

std::vector<BodyId> World::overlapping(const Shape& shape, const QueryFilter& filter) const {
  validate(shape);
  return select(aabb(shape), filter, [&shape](const Shape& s) { return overlaps(shape, s); });
}

std::vector<BodyId> World::overlapping(const Aabb& box, const QueryFilter& filter) const {
  validate(box);
  return select(box, filter, [&box](const Shape& s) { return overlaps(s, box); });
}

std::vector<BodyId> World::within(const Vec2& point, double d, const QueryFilter& filter) const {
  validate_point(point, "point");
  require_margin(d, "distance");
  if (d > 0.0) return overlapping(Shape(Circle{point, d}), filter);
  return select({point, point}, filter, [&point](const Shape& s) { return collide2d::contains(s, point); });
}

std::vector<BodyId> World::within(const Shape& shape, double d, const QueryFilter& filter) const {
  validate(shape);
  require_margin(d, "distance");
  return select(grown(aabb(shape), d), filter, [&](const Shape& s) { return distance(shape, s).distance <= d; });
}

std::optional<BodyCastHit> World::cast(const Shape& shape, const Vec2& translation, const QueryFilter& filter) const {
  validate(shape);
  require_finite(translation.x(), "cast translation x");
  require_finite(translation.y(), "cast translation y");
  const Shape end = at_time(shape, {translation, 0.0}, 1.0);
  validate(end);  // the range of the centre
  std::optional<BodyCastHit> best;
  for (const BodyId id : select(swept(shape, end), filter, [](const Shape&) { return true; })) {
    const auto hit = shape_cast(shape, translation, bodies_[id.index].shape);
    if (hit && (!best || hit->fraction < best->fraction)) best = BodyCastHit{id, hit->fraction, hit->point, hit->normal};
  }
  return best;
}

// on_hit(hit) for each solid body the filter lets through that the ray hits within the reach, which
// starts at max_distance and becomes what on_hit returns.
template <class OnHit>
void World::rays(const Vec2& origin, const Vec2& direction, double max_distance, const QueryFilter& filter,
                 OnHit on_hit) const {
  validate_point(origin, "ray origin");
  require_finite(direction.x(), "ray direction x");
  require_finite(direction.y(), "ray direction y");
  if (std::isnan(max_distance) || max_distance < 0.0) throw std::invalid_argument("ray length must not be negative");
  const double length = direction.norm();
  if (!(length > 0.0)) throw std::invalid_argument("ray direction must not be zero");
  const Vec2 unit = direction / length;
  const auto visit = [&](std::uint32_t index, double reach) {
    const Body& b = bodies_[index];
    if (b.sensor || !lets_through(filter, b.filter)) return reach;
    const auto hit = collide2d::ray_cast(b.shape, origin, unit, reach);
    return hit ? on_hit(RayHit{id_of(index), hit->distance, hit->point, hit->normal}, reach) : reach;
  };
  double reach = max_distance;
  moving_tree_.ray_cast(origin, unit, reach, [&](std::uint32_t index, double r) {
    return reach = bodies_[index].loose < 0 ? visit(index, r) : r;  // a loose body's leaf is out of date
  });
  for (const std::uint32_t index : loose_) reach = visit(index, reach);
  static_tree_.ray_cast(origin, unit, reach, visit);
}

std::optional<RayHit> World::ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                                      const QueryFilter& filter) const {
  std::optional<RayHit> best;
  rays(origin, direction, max_distance, filter, [&best](const RayHit& hit, double) {
    if (!best || hit.distance < best->distance || (hit.distance == best->distance && hit.body.index < best->body.index)) {
      best = hit;
    }
    return best->distance;
  });
  return best;
}

std::vector<RayHit> World::ray_cast_all(const Vec2& origin, const Vec2& direction, double max_distance,
                                        const QueryFilter& filter) const {
  std::vector<RayHit> hits;
  rays(origin, direction, max_distance, filter, [&hits](const RayHit& hit, double reach) {
    hits.push_back(hit);
    return reach;
  });
  std::sort(hits.begin(), hits.end(), [](const RayHit& p, const RayHit& q) {
    return std::tie(p.distance, p.body.index) < std::tie(q.distance, q.body.index);
  });
  return hits;
}

}  // namespace collide2d
