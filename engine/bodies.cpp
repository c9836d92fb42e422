// The World's bodies: their storage and ids, poses, kinds and filters, and their place in the broad
// phase of their kind (the static tree, or the sweep and prune with the moving bodies' tree).
#include "engine/world_state.h"
#include "shapes/internal.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>

namespace collide2d {
namespace detail {
namespace {

Shape posed(Shape shape, const Vec2& center, double angle) {
  std::visit(
      [&](auto& s) {
        s.center = center;
        if constexpr (!std::is_same_v<std::decay_t<decltype(s)>, Circle>) s.angle = angle;
      },
      shape);
  return shape;
}

}  // namespace

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
      speculative_margin_(options.contacts ? options.speculative_margin : 0.0) {
  require_margin(options.proximity_margin, "proximity margin");
  require_margin(options.speculative_margin, "speculative margin");
  pool_ = std::make_unique<ThreadPool>(options.threads > 0 ? options.threads
                                                           : std::max(1u, std::thread::hardware_concurrency()));
}

bool WorldState::contains(BodyId id) const {
  return id.index < bodies_.size() && bodies_[id.index].alive && bodies_[id.index].generation == id.generation;
}

const WorldState::Body& WorldState::body(BodyId id) const {
  if (contains(id)) return bodies_[id.index];
  const std::string name = "body " + std::to_string(id.index) + " (generation " + std::to_string(id.generation) + ")";
  const bool stale = id.index < bodies_.size() && id.generation != 0 && id.generation < bodies_[id.index].generation;
  if (!stale) throw std::out_of_range("unknown " + name);
  throw std::out_of_range("stale " + name + ": that body was removed; its slot is at generation " +
                          std::to_string(bodies_[id.index].generation));
}

WorldState::Body& WorldState::body(BodyId id) { return const_cast<Body&>(std::as_const(*this).body(id)); }

void WorldState::set_filter(BodyId id, const Filter& filter) {
  require_not_querying("set_filter");
  body(id).filter = filter;
}

void WorldState::set_pair_predicate(std::function<bool(BodyId, BodyId)> predicate) {
  require_not_querying("set_pair_predicate");
  pair_predicate_ = std::move(predicate);
}

bool WorldState::passes(std::uint32_t a, std::uint32_t b) const {
  return should_pair(bodies_[a].filter, bodies_[b].filter) && (!pair_predicate_ || pair_predicate_(id_of(a), id_of(b)));
}

std::vector<BodyId> WorldState::bodies() const {
  std::vector<BodyId> out;
  for (std::uint32_t index = 0; index < bodies_.size(); ++index) {
    if (bodies_[index].alive) out.push_back(id_of(index));
  }
  return out;
}

Aabb WorldState::broad_box(const Aabb& box) const {
  return grown(box, 0.5 * std::max(proximity_margin_, speculative_margin_));
}

Aabb WorldState::broad_box(const Body& b) const { return broad_box(b.continuous ? swept(b.start, b.shape) : b.box); }

// Into the broad phase of its kind: the static tree, or the sweep and prune and the moving tree.
void WorldState::enter(std::uint32_t index) {
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

void WorldState::leave(std::uint32_t index) {
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

void WorldState::unloose(std::uint32_t index) {
  const auto at = static_cast<std::size_t>(bodies_[index].loose);
  loose_[at] = loose_.back();
  bodies_[loose_[at]].loose = static_cast<std::int32_t>(at);
  loose_.pop_back();
  bodies_[index].loose = -1;
}

// Its broad-phase box, after a new pose or margin.
void WorldState::place(std::uint32_t index) {
  Body& b = bodies_[index];
  if (b.is_static) {
    static_tree_.move(b.leaf, broad_box(b));
    statics_changed_ = true;
  } else if (broad_.move(b.proxy, broad_box(b)) && b.loose < 0) {
    b.loose = static_cast<std::int32_t>(loose_.size());
    loose_.push_back(index);
  }
}

BodyId WorldState::add(const Shape& shape, const BodyDef& def) {
  require_not_querying("add");
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
  b.angle = angle_of(shape);
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

void WorldState::move_to(BodyId id, const Vec2& position, double angle) {
  require_not_querying("move_to");
  pose(body(id), position, angle, "move_to");
  place(id.index);
}

void WorldState::set_pose(BodyId id, const Vec2& position, double angle) {
  require_not_querying("set_pose");
  Body& b = body(id);
  pose(b, position, angle, "set_pose");
  if (b.continuous) b.start = b.shape;  // a teleport: the step starts here
  place(id.index);
}

void WorldState::move_by(BodyId id, const Vec2& shift, double turn) {
  require_not_querying("move_by");
  Body& b = body(id);
  require_finite(shift.x(), "move_by shift x");
  require_finite(shift.y(), "move_by shift y");
  require_finite(turn, "move_by turn");
  pose(b, center_of(b.shape) + shift, b.angle + turn, "move_by");
  place(id.index);
}

// The body at a pose, checked first so that a refusal, named after the call, leaves it as it was.
void WorldState::pose(Body& b, const Vec2& position, double angle, const char* call) {
  // The names are built on a refusal only: poses are set every frame, and a frame allocates nothing.
  if (!(std::abs(position.x()) <= kMaxMagnitude && std::abs(position.y()) <= kMaxMagnitude))
    validate_point(position, (std::string(call) + " position").c_str());
  if (!std::isfinite(angle)) require_finite(angle, (std::string(call) + " angle").c_str());
  b.shape = posed(b.shape, position, angle);
  b.angle = angle;
  b.orientation = Orientation::of(angle_of(b.shape));
  b.box = aabb(b.shape, b.orientation);
}

void WorldState::set_static(BodyId id, bool is_static) {
  require_not_querying("set_static");
  Body& b = body(id);
  if (b.is_static == is_static) return;
  if (b.continuous) set_continuous(id, false);
  leave(id.index);
  b.is_static = is_static;
  enter(id.index);
}

void WorldState::remove(BodyId id) {
  require_not_querying("remove");
  Body& b = body(id);
  if (b.continuous) set_continuous(id, false);
  leave(id.index);
  b.alive = false;
  b.generation = b.generation == UINT32_MAX ? 1 : b.generation + 1;  // 0 names no body
  free_.push_back(id.index);
  --live_;
}

void WorldState::set_proximity_margin(double margin) {
  require_not_querying("set_proximity_margin");
  require_margin(margin, "proximity margin");
  proximity_margin_ = margin;
  for (const BodyId id : bodies()) place(id.index);
}

}  // namespace detail

bool should_pair(const Filter& a, const Filter& b) {
  if (a.group == b.group && a.group != 0) return a.group > 0;
  return (a.mask & b.category) != 0 && (a.category & b.mask) != 0;
}

}  // namespace collide2d
