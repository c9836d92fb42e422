// Continuous bodies (bullets): a continuous body's step, from its pose at the last update to its
// pose now, counts. Its broad-phase box covers the whole path, and update() reports, for each of its
// candidate pairs that starts the step apart, the first time of impact within the step; a body not
// flagged is taken at its current pose. Bodies not flagged cost one flag test per pair.
#include "engine/world_state.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace collide2d::detail {
namespace {

Aabb merged(const Aabb& p, const Aabb& q) { return {p.min.cwiseMin(q.min), p.max.cwiseMax(q.max)}; }

Motion step_of(const Shape& start, const Shape& end) {
  return {center_of(end) - center_of(start), angle_of(end) - angle_of(start)};
}

}  // namespace

// Every pose of a step from `start` to `end` (its centre on the segment, any angle) lies in the
// segment grown by the shape's reach; the two end boxes are kept in it against rounding.
Aabb swept(const Shape& start, const Shape& end) {
  const Vec2 c0 = center_of(start), c1 = center_of(end);
  const double r = reach_of(end);
  return merged(merged({c0.cwiseMin(c1).array() - r, c0.cwiseMax(c1).array() + r}, aabb(start)), aabb(end));
}

void WorldState::set_continuous(BodyId id, bool continuous) {
  require_not_querying("set_continuous");
  Body& b = body(id);
  if (b.continuous == continuous) return;
  if (b.is_static) {
    throw std::invalid_argument("body " + std::to_string(id.index) +
                                " is static: only moving bodies can be continuous");
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

// A pair with a continuous body, over the step: each continuous body from its start pose, any other
// at rest where it is now. Pairs that start the step overlapping are the overlap test's.
void WorldState::impact(std::uint32_t a, std::uint32_t b, Found& out) const {
  const Body& x = bodies_[a];
  const Body& y = bodies_[b];
  const auto from = [](const Body& body) { return body.continuous ? body.start : body.shape; };
  const auto motion = [](const Body& body) { return body.continuous ? step_of(body.start, body.shape) : Motion{}; };
  const TimeOfImpact r = time_of_impact(from(x), motion(x), from(y), motion(y));
  if (r.status == ToiStatus::hit || r.status == ToiStatus::stalled) {
    out.impacts.push_back({id_of(a), id_of(b), x.user_id, y.user_id, r.t, r.normal, r.point});
  }
}

// The next step of every continuous body begins at its pose now.
void WorldState::begin_steps() {
  for (const std::uint32_t index : continuous_) {
    bodies_[index].start = bodies_[index].shape;
    place(index);
  }
}

}  // namespace collide2d::detail
