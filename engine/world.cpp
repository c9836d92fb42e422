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

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

World::World(const WorldOptions& options) : broad_(options.fat_margin), proximity_margin_(options.proximity_margin) {
  require_margin(options.proximity_margin, "proximity margin");
}

World::Body& World::body(BodyId id) {
  if (!contains(id)) throw std::out_of_range("unknown body " + std::to_string(id));
  return bodies_[id];
}

const World::Body& World::body(BodyId id) const {
  if (!contains(id)) throw std::out_of_range("unknown body " + std::to_string(id));
  return bodies_[id];
}

const Shape& World::shape(BodyId id) const { return body(id).shape; }
std::uint64_t World::user_id(BodyId id) const { return body(id).user_id; }

std::vector<BodyId> World::bodies() const {
  std::vector<BodyId> out;
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    if (contains(id)) out.push_back(id);
  }
  return out;
}

Aabb World::broad_box(const Shape& shape) const { return grown(aabb(shape), 0.5 * proximity_margin_); }

BodyId World::add(const Shape& shape, std::uint64_t user_id) {
  validate(shape);
  const BodyId id = broad_.insert(broad_box(shape));
  if (id >= bodies_.size()) bodies_.resize(static_cast<std::size_t>(id) + 1);
  bodies_[id] = {shape, user_id};
  return id;
}

void World::set_pose(BodyId id, const Vec2& center, double angle) {
  Body& b = body(id);
  require_finite(center.x(), "pose x");
  require_finite(center.y(), "pose y");
  require_finite(angle, "pose angle");
  const Shape moved = posed(b.shape, center, angle);
  validate(moved);  // the range of the centre
  broad_.move(id, broad_box(moved));
  b.shape = moved;
}

void World::move_by(BodyId id, const Vec2& shift, double turn) {
  const Shape& s = body(id).shape;
  set_pose(id, center_of(s) + shift, angle_of(s) + turn);
}

void World::remove(BodyId id) {
  body(id);
  broad_.remove(id);
}

void World::set_proximity_margin(double margin) {
  require_margin(margin, "proximity margin");
  proximity_margin_ = margin;
  for (const BodyId id : bodies()) broad_.move(id, broad_box(bodies_[id].shape));
}

void World::update() {
  const auto start = std::chrono::steady_clock::now();
  broad_.update();
  stats_ = {};
  stats_.broad_seconds = seconds_since(start);
  const auto narrow_start = std::chrono::steady_clock::now();
  std::vector<BodyPair> now;
  proximity_.clear();
  for (const ProxyPair& p : broad_.pairs()) {
    const Shape& a = bodies_[p.a].shape;
    const Shape& b = bodies_[p.b].shape;
    if (overlaps(a, b)) {
      now.push_back(p);
    } else if (proximity_margin_ > 0.0) {
      const DistanceResult d = distance(a, b);
      if (!d.overlapping && d.distance <= proximity_margin_) proximity_.push_back({p.a, p.b, d});
    }
  }
  began_.clear();
  ended_.clear();
  std::set_difference(now.begin(), now.end(), overlapping_.begin(), overlapping_.end(), std::back_inserter(began_));
  std::set_difference(overlapping_.begin(), overlapping_.end(), now.begin(), now.end(), std::back_inserter(ended_));
  overlapping_ = std::move(now);
  stats_.narrow_seconds = seconds_since(narrow_start);
  stats_.candidates = broad_.pairs().size();
  stats_.overlapping = overlapping_.size();
  stats_.proximity = proximity_.size();
}

template <class Test>
std::vector<BodyId> World::select(const Aabb& box, Test test) const {
  std::vector<BodyId> out;
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    if (contains(id) && intersects(aabb(bodies_[id].shape), box) && test(bodies_[id].shape)) out.push_back(id);
  }
  return out;
}

std::vector<BodyId> World::overlapping(const Shape& shape) const {
  validate(shape);
  return select(aabb(shape), [&shape](const Shape& s) { return overlaps(shape, s); });
}

std::vector<BodyId> World::overlapping(const Aabb& box) const {
  for (int k = 0; k < 2; ++k) {
    require_finite(box.min[k], "box min");
    require_finite(box.max[k], "box max");
    if (box.min[k] > box.max[k]) throw std::invalid_argument("box min must not exceed box max");
  }
  return select(box, [](const Shape&) { return true; });
}

std::vector<BodyId> World::within(const Vec2& point, double d) const {
  validate_point(point, "point");
  require_margin(d, "distance");
  if (d > 0.0) return overlapping(Shape(Circle{point, d}));
  return select({point, point}, [&point](const Shape& s) { return collide2d::contains(s, point); });
}

std::vector<BodyId> World::within(const Shape& shape, double d) const {
  validate(shape);
  require_margin(d, "distance");
  return select(grown(aabb(shape), d), [&](const Shape& s) { return distance(shape, s).distance <= d; });
}

std::optional<RayHit> World::ray_cast(const Vec2& origin, const Vec2& direction, double max_distance) const {
  validate_point(origin, "ray origin");
  require_finite(direction.x(), "ray direction x");
  require_finite(direction.y(), "ray direction y");
  if (std::isnan(max_distance) || max_distance < 0.0) throw std::invalid_argument("ray length must not be negative");
  const double length = direction.norm();
  if (!(length > 0.0)) throw std::invalid_argument("ray direction must not be zero");
  const Vec2 unit = direction / length;
  std::optional<RayHit> best;
  for (BodyId id = 0; id < bodies_.size(); ++id) {
    if (!contains(id)) continue;
    const double reach = best ? best->distance : max_distance;
    const auto hit = collide2d::ray_cast(bodies_[id].shape, origin, unit, reach);
    if (hit && (!best || hit->distance < best->distance)) best = RayHit{id, hit->distance, hit->point, hit->normal};
  }
  return best;
}

}  // namespace collide2d
