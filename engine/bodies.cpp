// The World's bodies: their storage and ids, poses, kinds and filters, and their place in the broad
// phase of their kind (the static tree, or the sweep and prune with the moving bodies' tree).
#include "engine/world_state.h"
#include "shapes/internal.h"
#include "shapes/kinds.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>

namespace collide2d {
namespace detail {
void require_finite(double value, const char* what) {
  if (!std::isfinite(value))
    throw std::invalid_argument(std::string(what) + " must be finite (got " + detail::shortest(value) + ')');
}

void require_margin(double value, const char* what) {
  require_finite(value, what);
  if (value < 0.0) throw std::invalid_argument(std::string(what) + " must not be negative");
}

Aabb grown(const Aabb& box, double by) { return {box.min.array() - by, box.max.array() + by}; }

WorldState::WorldState(const WorldOptions& options)
    : broad_(options.fat_margin),
      proximity_margin_(options.proximity_margin),
      contacts_on_(options.contacts),
      speculative_margin_(options.contacts ? options.speculative_margin : 0.0),
      contact_tolerance_(options.contact_tolerance),
      overlap_areas_(options.overlap_areas) {
  require_margin(options.proximity_margin, "proximity margin");
  require_margin(options.speculative_margin, "speculative margin");
  require_margin(options.contact_tolerance, "contact tolerance");
  pool_ = std::make_unique<ThreadPool>(options.threads > 0 ? options.threads
                                                           : std::max(1u, std::thread::hardware_concurrency()));
  scratch_.resize(pool_->threads());
}

bool WorldState::contains(BodyId id) const {
  return id.index < bodies_.size() && bodies_[id.index].alive && bodies_[id.index].generation == id.generation;
}

bool WorldState::contains(ShapeId id) const {
  return id.index < entries_.size() && entries_[id.index].alive && entries_[id.index].generation == id.generation;
}

namespace {

// A free slot of `slots` (a std::vector or Pages), the last one freed, or a new one at the end.
template <class Slots>
std::uint32_t take_slot(Slots& slots, std::vector<std::uint32_t>& free) {
  if (free.empty()) {
    slots.emplace_back();
    return static_cast<std::uint32_t>(slots.size() - 1);
  }
  const std::uint32_t index = free.back();
  free.pop_back();
  return index;
}

// The error for a handle that names nothing: unknown, or stale (its slot has moved on since).
[[noreturn]] void refuse(const char* what, std::uint32_t index, std::uint32_t generation, bool in_range,
                         std::uint32_t slot_generation) {
  const std::string name =
      std::string(what) + ' ' + std::to_string(index) + " (generation " + std::to_string(generation) + ")";
  if (!(in_range && generation != 0 && generation < slot_generation)) throw std::out_of_range("unknown " + name);
  throw std::out_of_range("stale " + name + ": that " + what + " was removed; its slot is at generation " +
                          std::to_string(slot_generation));
}

}  // namespace

const WorldState::Body& WorldState::body(BodyId id) const {
  if (contains(id)) return bodies_[id.index];
  const bool in_range = id.index < bodies_.size();
  refuse("body", id.index, id.generation, in_range, in_range ? bodies_[id.index].generation : 0);
}

WorldState::Body& WorldState::body(BodyId id) { return const_cast<Body&>(std::as_const(*this).body(id)); }

const WorldState::ShapeEntry& WorldState::entry(ShapeId id) const {
  if (contains(id)) return entries_[id.index];
  const bool in_range = id.index < entries_.size();
  refuse("shape", id.index, id.generation, in_range, in_range ? entries_[id.index].generation : 0);
}

WorldState::ShapeEntry& WorldState::entry(ShapeId id) {
  return const_cast<ShapeEntry&>(std::as_const(*this).entry(id));
}

void WorldState::set_filter(BodyId id, const Filter& filter) {
  require_not_querying("set_filter");
  Body& b = body(id);
  b.filter = filter;
  each_entry(b, [&](std::uint32_t k) { entries_[k].filter = filter; });
}

void WorldState::set_filter(ShapeId id, const Filter& filter) {
  require_not_querying("set_filter");
  entry(id).filter = filter;
}

void WorldState::set_sensor(ShapeId id, bool sensor) {
  require_not_querying("set_sensor");
  entry(id).sensor = sensor;
}

void WorldState::set_pair_predicate(std::function<bool(BodyId, BodyId)> predicate) {
  require_not_querying("set_pair_predicate");
  pair_predicate_ = std::move(predicate);
}

bool WorldState::passes(std::uint32_t a, std::uint32_t b) const {
  const ShapeEntry& x = entries_[a];
  const ShapeEntry& y = entries_[b];
  return should_pair(x.filter, y.filter) && (!pair_predicate_ || pair_predicate_(x.body, y.body));
}

std::vector<BodyId> WorldState::bodies() const {
  std::vector<BodyId> out;
  for (std::uint32_t index = 0; index < bodies_.size(); ++index) {
    if (bodies_[index].alive) out.push_back(body_id(index));
  }
  return out;
}

std::vector<ShapeId> WorldState::shapes(BodyId id) const {
  std::vector<ShapeId> out;
  each_entry(body(id), [&](std::uint32_t k) { out.push_back(shape_id(k)); });
  return out;
}

Aabb WorldState::broad_box(const Aabb& box) const {
  return grown(box, 0.5 * std::max(proximity_margin_, speculative_margin_));
}

Aabb WorldState::broad_box(const ShapeEntry& p) const {
  return broad_box(p.continuous ? swept(start_of(p), p.shape) : p.box);
}

Aabb WorldState::broad_box(ShapeId id) const {
  const ShapeEntry& p = entry(id);
  return p.is_static ? broad_box(p) : broad_.fat_box(p.proxy);
}

// Into the broad phase of its body's kind: the static tree, or the sweep and prune and the moving tree.
void WorldState::enter(std::uint32_t index) {
  ShapeEntry& p = entries_[index];
  if (p.is_static) {
    p.leaf = static_tree_.insert(broad_box(p), index);
    statics_changed_ = true;
    return;
  }
  p.proxy = broad_.insert(broad_box(p));
  if (p.proxy >= part_of_.size()) resize_room(part_of_, std::size_t{p.proxy} + 1, kNone);
  part_of_[p.proxy] = index;
  if (moving_tree_on_.load(std::memory_order_relaxed)) {
    if (p.proxy >= moving_leaves_.size()) moving_leaves_.resize(static_cast<std::size_t>(p.proxy) + 1, -1);
    moving_leaves_[p.proxy] = moving_tree_.insert(broad_.fat_box(p.proxy), index);
  }
  p.stale_at = -1;
  p.queried = kNowhere;
}

void WorldState::leave(std::uint32_t index) {
  ShapeEntry& p = entries_[index];
  if (p.is_static) {
    static_tree_.remove(p.leaf);
    statics_changed_ = true;
    return;
  }
  broad_.remove(p.proxy);
  part_of_[p.proxy] = kNone;
  if (moving_tree_on_.load(std::memory_order_relaxed)) moving_tree_.remove(moving_leaves_[p.proxy]);
  if (p.stale_at >= 0) drop_stale(index);
  release_statics(p);
}

void WorldState::drop_stale(std::uint32_t index) {
  const auto at = static_cast<std::size_t>(entries_[index].stale_at);
  stale_leaves_[at] = stale_leaves_.back();
  entries_[stale_leaves_[at]].stale_at = static_cast<std::int32_t>(at);
  stale_leaves_.pop_back();
  entries_[index].stale_at = -1;
}

// Its broad-phase box, after a new pose or margin. A moving shape's tree leaf goes stale only once
// the tree is built: the first query builds it from the fat boxes as they are.
void WorldState::refresh_box(std::uint32_t index) {
  ShapeEntry& p = entries_[index];
  if (p.is_static) {
    static_tree_.move(p.leaf, broad_box(p));
    statics_changed_ = true;
  } else if (broad_.move(p.proxy, broad_box(p)) && p.stale_at < 0 && moving_tree_on_.load(std::memory_order_relaxed)) {
    p.stale_at = static_cast<std::int32_t>(stale_leaves_.size());
    stale_leaves_.push_back(index);
  }
}

// A shape where its body's pose puts it: its world angle is the body's plus its own, and its
// orientation that angle's (the kernels' contract), not the two rotations composed.
void WorldState::place_entry(std::uint32_t index, const Pose& at, const Orientation& turn) {
  ShapeEntry& p = entries_[index];
  if (p.at_origin) {
    place(p.shape, at.position, at.angle);
  } else {
    p.shape = placed(locals_[p.local], at, turn);
  }
  p.orientation = Orientation::of(angle_of(p.shape));
  p.box = aabb(p.shape, p.orientation);
}

// The shape placed anew in its body's frame, posed where the body is; a continuous body's step for it
// starts there.
void WorldState::set_local(std::uint32_t index, const Shape& local) {
  ShapeEntry& p = entries_[index];
  const Body& b = bodies_[p.body.index];
  p.shape = local;  // its sizes: place_entry() moves a shape at the origin as it is
  p.at_origin = at_origin(local);
  if (p.at_origin) {
    release_local(p);
  } else {
    if (p.local == kNone) p.local = take_slot(locals_, free_locals_);
    locals_[p.local] = local;
  }
  place_entry(index, b.pose(), Orientation::of(b.angle));
  if (p.continuous) continuous_[p.step].start = pose_of(p.shape);
}

// A new shape of body `body`, last in its list, posed and in the broad phase; def.shape is valid.
std::uint32_t WorldState::new_entry(std::uint32_t body, const ShapeDef& def) {
  const std::uint32_t index = take_slot(entries_, free_entries_);
  Body& b = bodies_[body];
  ShapeEntry& p = entries_[index];  // a reused slot keeps the generation free_entry() gave it
  p.body = body_id(body);
  p.body_user_id = b.user_id;
  p.next = kNone;
  p.user_id = def.user_id.value_or(b.user_id);
  p.filter = def.filter.value_or(b.filter);
  p.sensor = def.sensor.value_or(b.sensor);
  p.is_static = b.is_static;
  p.continuous = b.continuous;
  p.ghost = b.ghost;
  p.chain = false;
  p.alive = true;
  if (b.continuous) join_steps(index);
  set_local(index, def.shape);
  (b.first == kNone ? b.first : entries_[b.last].next) = index;
  b.last = index;
  ++b.count;
  enter(index);
  return index;
}

void WorldState::release_slot(std::uint32_t& slot, std::vector<std::uint32_t>& free) {
  if (slot == kNone) return;
  free.push_back(slot);
  slot = kNone;
}

void WorldState::release_local(ShapeEntry& p) { release_slot(p.local, free_locals_); }

std::vector<std::uint32_t>& WorldState::static_list(ShapeEntry& p) {
  if (p.statics == kNone) p.statics = take_slot(static_lists_, free_static_lists_);
  std::vector<std::uint32_t>& list = static_lists_[p.statics];
  list.clear();
  return list;
}

void WorldState::release_statics(ShapeEntry& p) { release_slot(p.statics, free_static_lists_); }

void WorldState::free_entry(std::uint32_t index) {
  ShapeEntry& p = entries_[index];
  if (p.continuous) leave_steps(index);
  release_local(p);
  leave(index);
  p.alive = false;
  p.generation = p.generation == UINT32_MAX ? 1 : p.generation + 1;  // 0 names no shape
  free_entries_.push_back(index);
}

namespace {

// A chain changes only whole: its segments' ghosts name their neighbours.
void require_not_chain(bool chain, ShapeId id, const char* call) {
  if (chain) {
    throw std::invalid_argument(std::string(call) + ": shape " + std::to_string(id.index) +
                                " is a chain's segment; a chain changes only whole (remove its body)");
  }
}

// A segment is level geometry (shapes/kinds.h): its body must be static (BodyDef::is_static).
void require_static_for(const Shape& shape, bool is_static, const char* call) {
  if (!is_static && is_level_geometry(shape)) {
    throw std::invalid_argument(std::string(call) + ": a " + shape_name(shape) +
                                " is level geometry, and its body must be static");
  }
}

}  // namespace

BodyId WorldState::add(const Pose& pose, std::span<const ShapeDef> shapes, const BodyDef& def) {
  require_not_querying("add");
  validate_point(pose.position, "add position");
  require_finite(pose.angle, "add angle");
  if (shapes.empty()) throw std::invalid_argument("add needs at least one shape for the body");
  for (const ShapeDef& s : shapes) validate(s.shape);
  for (const ShapeDef& s : shapes) require_static_for(s.shape, def.is_static, "add");
  const std::uint32_t index = take_slot(bodies_, free_bodies_);
  Body& b = bodies_[index];  // a reused slot keeps the generation remove() gave it
  b.position = pose.position;
  b.angle = pose.angle;
  b.user_id = def.user_id;
  b.filter = def.filter;
  b.is_static = def.is_static;
  b.sensor = def.sensor;
  b.continuous = false;
  b.ghost = def.ghost;
  b.alive = true;
  b.first = kNone;
  b.last = kNone;
  b.count = 0;
  for (const ShapeDef& s : shapes) new_entry(index, s);
  ++live_;
  return body_id(index);
}

BodyId WorldState::add_chain(std::span<const Vec2> points, bool loop, const ChainDef& def) {
  require_not_querying("add_chain");
  const std::vector<ChainSegment> chain = chain_segments(points, loop);
  std::vector<ShapeDef> defs;
  defs.reserve(chain.size());
  for (const ChainSegment& s : chain) defs.push_back({.shape = s.segment});
  const BodyId id = add({}, defs, {.user_id = def.user_id, .filter = def.filter, .is_static = true});
  ghosts_.resize(entries_.size());
  auto next = chain.begin();
  each_entry(bodies_[id.index], [&](std::uint32_t k) {
    entries_[k].chain = true;
    ghosts_[k] = {next->ghost1, next->ghost2};
    ++next;
  });
  return id;
}

std::optional<ChainSegment> WorldState::chain_segment(ShapeId id) const {
  if (!entry(id).chain) return std::nullopt;
  return chain_of(id.index);
}

ShapeId WorldState::add_shape(BodyId id, const ShapeDef& def) {
  require_not_querying("add_shape");
  const Body& b = body(id);
  validate(def.shape);
  require_static_for(def.shape, b.is_static, "add_shape");
  return shape_id(new_entry(id.index, def));
}

void WorldState::remove_shape(ShapeId id) {
  require_not_querying("remove_shape");
  require_not_chain(entry(id).chain, id, "remove_shape");
  Body& b = bodies_[entry(id).body.index];
  if (b.count == 1) {
    throw std::invalid_argument("remove_shape: shape " + std::to_string(id.index) +
                                " is its body's last; remove the body instead");
  }
  std::uint32_t* link = &b.first;
  std::uint32_t before = kNone;
  while (*link != id.index) {
    before = *link;
    link = &entries_[*link].next;
  }
  *link = entries_[id.index].next;
  if (b.last == id.index) b.last = before;
  --b.count;
  free_entry(id.index);
}

void WorldState::set_local_shape(ShapeId id, const Shape& local) {
  require_not_querying("set_local_shape");
  const ShapeEntry& p = entry(id);
  require_not_chain(p.chain, id, "set_local_shape");
  validate(local);
  require_static_for(local, p.is_static, "set_local_shape");
  set_local(id.index, local);
  refresh_box(id.index);
}

void WorldState::move_to(BodyId id, const Vec2& position, double angle) {
  require_not_querying("move_to");
  place_body(body(id), position, angle, "move_to", false);
}

void WorldState::set_pose(BodyId id, const Vec2& position, double angle) {
  require_not_querying("set_pose");
  place_body(body(id), position, angle, "set_pose", true);
}

void WorldState::move_by(BodyId id, const Vec2& shift, double turn) {
  require_not_querying("move_by");
  Body& b = body(id);
  require_finite(shift.x(), "move_by shift x");
  require_finite(shift.y(), "move_by shift y");
  require_finite(turn, "move_by turn");
  place_body(b, b.position + shift, b.angle + turn, "move_by", false);
}

// The body and its shapes at a pose, checked first so that a refusal, named after the call, leaves
// it as it was. A teleport starts a continuous body's step there.
void WorldState::place_body(Body& b, const Vec2& position, double angle, const char* call, bool teleport) {
  // The names are built on a refusal only: poses are set every frame, and a frame allocates nothing.
  if (!(std::abs(position.x()) <= kMaxMagnitude && std::abs(position.y()) <= kMaxMagnitude))
    validate_point(position, (std::string(call) + " position").c_str());
  if (!std::isfinite(angle)) require_finite(angle, (std::string(call) + " angle").c_str());
  if (b.moved[1].after != updates_) b.moved = {b.moved[1], {updates_, b.pose()}};
  b.position = position;
  b.angle = angle;
  // A body of one shape at its origin needs no turn of its own (the shape's orientation is computed
  // anyway).
  const bool alone = b.count == 1 && entries_[b.first].at_origin;
  const Orientation turn = alone ? Orientation{} : Orientation::of(angle);
  const Pose pose = b.pose();
  for (std::uint32_t k = b.first; k != kNone; k = entries_[k].next) {
    ShapeEntry& p = entries_[k];
    place_entry(k, pose, turn);
    if (teleport && p.continuous) continuous_[p.step].start = pose_of(p.shape);
    refresh_box(k);
  }
}

// The body's pose at the update before the last, and at the last (before any move since), from
// its runs of moves; a point carried from the one to the other.
Vec2 WorldState::displacement(BodyId id, const Vec2& point) const {
  const Body& b = body(id);
  validate_point(point, "displacement point");
  const auto it = std::find_if(b.moved.begin(), b.moved.end(),
                               [this](const Body::Moved& m) { return updates_ > 0 && m.after == updates_ - 1; });
  if (it == b.moved.end()) return Vec2::Zero();  // it did not move between the last two updates
  const Pose& before = it->from;
  const Pose after = b.moved[1].after == updates_ ? b.moved[1].from : b.pose();
  if (after.angle == before.angle) return after.position - before.position;
  using Turn = detail::Rotation<double>;
  const Vec2 local = Turn::of(before.angle).apply_inverse(Vec2(point - before.position));
  return Vec2(after.position + Turn::of(after.angle).apply(local) - point);
}

void WorldState::set_static(BodyId id, bool is_static) {
  require_not_querying("set_static");
  Body& b = body(id);
  if (b.is_static == is_static) return;
  each_entry(b, [&](std::uint32_t k) { require_static_for(entries_[k].shape, is_static, "set_static"); });
  if (b.continuous) set_continuous(id, false);
  each_entry(b, [&](std::uint32_t k) {
    leave(k);
    entries_[k].is_static = is_static;
    enter(k);
  });
  b.is_static = is_static;
}

void WorldState::set_ghost(BodyId id, bool ghost) {
  require_not_querying("set_ghost");
  Body& b = body(id);
  b.ghost = ghost;
  each_entry(b, [&](std::uint32_t k) { entries_[k].ghost = ghost; });
}

void WorldState::remove(BodyId id) {
  require_not_querying("remove");
  Body& b = body(id);
  if (b.continuous) set_continuous(id, false);
  each_entry(b, [&](std::uint32_t k) { free_entry(k); });
  b.alive = false;
  b.generation = b.generation == UINT32_MAX ? 1 : b.generation + 1;  // 0 names no body
  free_bodies_.push_back(id.index);
  --live_;
}

void WorldState::set_proximity_margin(double margin) {
  require_not_querying("set_proximity_margin");
  require_margin(margin, "proximity margin");
  proximity_margin_ = margin;
  for (std::uint32_t k = 0; k < entries_.size(); ++k) {
    if (entries_[k].alive) refresh_box(k);
  }
}

}  // namespace detail

// A shape at the origin with no angle of its own takes the pose as it is: a body of one shape is
// then posed to the bit as that shape alone (adding a zero offset or angle could flip a zero's sign).
Pose pose_of(const Shape& shape) { return {center_of(shape), angle_of(shape)}; }

Shape placed(const Shape& local, const Pose& pose, const Orientation& turn) {
  if (detail::at_origin(local)) return detail::placed_at(local, pose.position, pose.angle);
  const Vec2 offset = center_of(local);
  const Vec2 center =
      pose.position + Vec2(turn.c * offset.x() - turn.s * offset.y(), turn.s * offset.x() + turn.c * offset.y());
  return detail::placed_at(local, center, pose.angle + angle_of(local));
}

bool should_pair(const Filter& a, const Filter& b) {
  if (a.group == b.group && a.group != 0) return a.group > 0;
  return (a.mask & b.category) != 0 && (a.category & b.mask) != 0;
}

Vec2 normal_from(const BodyContact& c, BodyId body) {
  if (body == c.a) return c.contact.normal;
  if (body == c.b) return -c.contact.normal;
  throw std::invalid_argument("normal_from: body " + std::to_string(body.index) + " (generation " +
                              std::to_string(body.generation) + ") is neither body of the contact");
}

}  // namespace collide2d
