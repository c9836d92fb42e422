#include "engine/world.h"

#include "narrowphase/ray_cast.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
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
}

bool World::contains(BodyId id) const {
  return broad_.contains(id.index) && bodies_[id.index].generation == id.generation;
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

void World::set_filter(BodyId id, const Filter& filter) { body(id).filter = filter; }

void World::set_pair_predicate(std::function<bool(BodyId, BodyId)> predicate) { pair_predicate_ = std::move(predicate); }

bool World::passes(const ProxyPair& p) const {
  return should_pair(bodies_[p.a].filter, bodies_[p.b].filter) && (!pair_predicate_ || pair_predicate_(id_of(p.a), id_of(p.b)));
}

std::vector<BodyId> World::bodies() const {
  std::vector<BodyId> out;
  for (ProxyId index = 0; index < bodies_.size(); ++index) {
    if (broad_.contains(index)) out.push_back(id_of(index));
  }
  return out;
}

Aabb World::broad_box(const Aabb& box) const {
  return grown(box, 0.5 * std::max(proximity_margin_, speculative_margin_));
}

BodyId World::add(const Shape& shape, std::uint64_t user_id, const Filter& filter) {
  validate(shape);
  const Aabb box = aabb(shape);
  const ProxyId index = broad_.insert(broad_box(box));
  if (index >= bodies_.size()) bodies_.resize(static_cast<std::size_t>(index) + 1);
  Body& b = bodies_[index];
  b.shape = shape;  // a reused slot keeps the generation remove() gave it
  if (contacts_on_) b.orientation = Orientation::of(angle_of(shape));
  b.box = box;
  b.user_id = user_id;
  b.filter = filter;
  return id_of(index);
}

void World::set_pose(BodyId id, const Vec2& center, double angle) {
  Body& b = body(id);
  require_finite(center.x(), "pose x");
  require_finite(center.y(), "pose y");
  require_finite(angle, "pose angle");
  const Shape moved = posed(b.shape, center, angle);
  validate(moved);  // the range of the centre
  const Aabb box = aabb(moved);
  broad_.move(id.index, broad_box(b.continuous ? swept(b.start, moved) : box));
  b.shape = moved;
  if (contacts_on_) b.orientation = Orientation::of(angle_of(moved));  // only contacts use it
  b.box = box;
}

void World::move_by(BodyId id, const Vec2& shift, double turn) {
  const Shape& s = body(id).shape;
  set_pose(id, center_of(s) + shift, angle_of(s) + turn);
}

void World::set_continuous(BodyId id, bool continuous) {
  Body& b = body(id);
  if (b.continuous == continuous) return;
  if (continuous) {
    continuous_.push_back(id.index);
  } else {
    continuous_.erase(std::find(continuous_.begin(), continuous_.end(), id.index));
  }
  b.continuous = continuous;
  b.start = b.shape;
  broad_.move(id.index, broad_box(b.box));
}

void World::remove(BodyId id) {
  Body& b = body(id);
  if (b.continuous) set_continuous(id, false);
  broad_.remove(id.index);
  b.generation = b.generation == UINT32_MAX ? 1 : b.generation + 1;  // 0 names no body
}

void World::set_proximity_margin(double margin) {
  require_margin(margin, "proximity margin");
  proximity_margin_ = margin;
  for (const BodyId id : bodies()) broad_.move(id.index, broad_box(bodies_[id.index].box));
}

void World::update() {
  const auto start = std::chrono::steady_clock::now();
  broad_.update();
  stats_ = {};
  stats_.broad_seconds = seconds_since(start);
  const auto narrow_start = std::chrono::steady_clock::now();
  std::vector<BodyPair> now;
  proximity_.clear();
  contacts_.clear();
  impacts_.clear();
  const ContactOptions manifold{.margin = speculative_margin_};
  for (const ProxyPair& p : broad_.pairs()) {
    if (!passes(p)) {
      ++stats_.filtered;
      continue;
    }
    const Body& x = bodies_[p.a];
    const Body& y = bodies_[p.b];
    if (x.continuous || y.continuous) impact(p);
    if (intersects(x.box, y.box) && overlaps(x.shape, y.shape)) {
      now.push_back(pair_of(p));
      if (contacts_on_) contacts_.push_back({id_of(p.a), id_of(p.b), contact(x.shape, x.orientation, y.shape, y.orientation, manifold)});
      continue;
    }
    if (proximity_margin_ > 0.0) {
      const DistanceResult d = distance(x.shape, y.shape);
      if (!d.overlapping && d.distance <= proximity_margin_) proximity_.push_back({id_of(p.a), id_of(p.b), d});
    }
    if (speculative_margin_ > 0.0 && intersects(grown(x.box, 0.5 * speculative_margin_), grown(y.box, 0.5 * speculative_margin_))) {
      const Contact c = contact(x.shape, x.orientation, y.shape, y.orientation, manifold);
      if (c.separation <= speculative_margin_) contacts_.push_back({id_of(p.a), id_of(p.b), c});
    }
  }
  began_.clear();
  ended_.clear();
  std::set_difference(now.begin(), now.end(), overlapping_.begin(), overlapping_.end(), std::back_inserter(began_));
  std::set_difference(overlapping_.begin(), overlapping_.end(), now.begin(), now.end(), std::back_inserter(ended_));
  overlapping_ = std::move(now);
  for (const ProxyId index : continuous_) {  // the next step begins here
    Body& b = bodies_[index];
    b.start = b.shape;
    broad_.move(index, broad_box(b.box));
  }
  stats_.narrow_seconds = seconds_since(narrow_start);
  stats_.candidates = broad_.pairs().size();
  stats_.overlapping = overlapping_.size();
  stats_.proximity = proximity_.size();
  stats_.contacts = contacts_.size();
  stats_.impacts = impacts_.size();
}

// A pair with a continuous body, over the step: each continuous body from its start pose, any other
// at rest where it is now. Pairs that start the step overlapping are the overlap test's.
void World::impact(const ProxyPair& p) {
  const Body& x = bodies_[p.a];
  const Body& y = bodies_[p.b];
  const auto from = [](const Body& b) { return b.continuous ? b.start : b.shape; };
  const auto motion = [](const Body& b) { return b.continuous ? step_of(b.start, b.shape) : Motion{}; };
  const TimeOfImpact r = time_of_impact(from(x), motion(x), from(y), motion(y));
  if (r.status == ToiStatus::hit || r.status == ToiStatus::stalled) {
    impacts_.push_back({id_of(p.a), id_of(p.b), r.t, r.normal, r.point});
  }
}

template <class Test>
std::vector<BodyId> World::select(const Aabb& box, const QueryFilter& filter, Test test) const {
  std::vector<BodyId> out;
  for (ProxyId index = 0; index < bodies_.size(); ++index) {
    const Body& b = bodies_[index];
    if (broad_.contains(index) && lets_through(filter, b.filter) && intersects(b.box, box) && test(b.shape)) {
      out.push_back(id_of(index));
    }
  }
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

std::optional<RayHit> World::ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                                      const QueryFilter& filter) const {
  validate_point(origin, "ray origin");
  require_finite(direction.x(), "ray direction x");
  require_finite(direction.y(), "ray direction y");
  if (std::isnan(max_distance) || max_distance < 0.0) throw std::invalid_argument("ray length must not be negative");
  const double length = direction.norm();
  if (!(length > 0.0)) throw std::invalid_argument("ray direction must not be zero");
  const Vec2 unit = direction / length;
  std::optional<RayHit> best;
  for (ProxyId index = 0; index < bodies_.size(); ++index) {
    if (!broad_.contains(index) || !lets_through(filter, bodies_[index].filter)) continue;
    const double reach = best ? best->distance : max_distance;
    const auto hit = collide2d::ray_cast(bodies_[index].shape, origin, unit, reach);
    if (hit && (!best || hit->distance < best->distance)) best = RayHit{id_of(index), hit->distance, hit->point, hit->normal};
  }
  return best;
}

}  // namespace collide2d
