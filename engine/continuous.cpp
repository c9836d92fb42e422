// Continuous bodies (bullets): a continuous body's step, from its pose at the last update to its
// pose now, counts. Each of its shapes' broad-phase boxes covers the shape's whole path, and update()
// reports, for each pair of bodies with a candidate pair of shapes that starts the step apart, the
// first time of impact within the step over their shapes' pairs; a body not flagged is taken at its
// current pose. Bodies not flagged cost one flag test per pair.
#include "engine/world_state.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace collide2d::detail {
namespace {

Aabb merged(const Aabb& p, const Aabb& q) { return {p.min.cwiseMin(q.min), p.max.cwiseMax(q.max)}; }

Motion step_of(const Pose& start, const Shape& end) {
  return {center_of(end) - start.position, angle_of(end) - start.angle};
}

}  // namespace

// Every pose of a step from `start` to `end` (its centre on the segment, any angle) lies in the
// segment grown by the shape's reach; the two end boxes are kept in it against rounding.
Aabb swept(const Pose& start, const Shape& end) {
  const Vec2 c0 = start.position, c1 = center_of(end);
  const double r = reach_of(end);
  return merged(merged({c0.cwiseMin(c1).array() - r, c0.cwiseMax(c1).array() + r},
                       aabb(placed_at(end, start.position, start.angle))),
                aabb(end));
}

void WorldState::set_continuous(BodyId id, bool continuous) {
  require_not_querying("set_continuous");
  Body& b = body(id);
  if (b.continuous == continuous) return;
  if (b.is_static) {
    throw std::invalid_argument("body " + std::to_string(id.index) +
                                " is static: only moving bodies can be continuous");
  }
  b.continuous = continuous;
  each_entry(b, [&](std::uint32_t k) {
    ShapeEntry& p = entries_[k];
    if (continuous) {
      join_steps(k);
    } else {
      leave_steps(k);
    }
    p.continuous = continuous;
    refresh_box(k);
  });
}

// A pair with a continuous body, over the step: each continuous body from its start pose, any other
// at rest where it is now. Pairs that start the step overlapping are the overlap test's.
void WorldState::impact(std::uint32_t a, std::uint32_t b, ChunkResults& out) const {
  const ShapeEntry& x = entries_[a];
  const ShapeEntry& y = entries_[b];
  const auto from = [&](const ShapeEntry& p) {
    return p.continuous ? placed_at(p.shape, start_of(p).position, start_of(p).angle) : p.shape;
  };
  const auto motion = [&](const ShapeEntry& p) { return p.continuous ? step_of(start_of(p), p.shape) : Motion{}; };
  // A chain's segment stops only what comes at it from the front (chain.h's one-sided rule, at the
  // step's start).
  if (x.chain && !in_front(chain_of(a), from(y))) return;
  if (y.chain && !in_front(chain_of(b), from(x))) return;
  const TimeOfImpact r = time_of_impact(from(x), motion(x), from(y), motion(y));
  if (r.status == ToiStatus::hit || r.status == ToiStatus::stalled) {
    Impact& i = out.impacts.emplace_back(Impact{ids_of(a, b)});
    i.t = r.t;
    i.normal = r.normal;
    i.point = r.point;
  }
}

// One impact per pair of bodies, the earliest of their shapes' (the first pair of shapes on a tie);
// impacts_ is sorted by bodies, then shapes.
void WorldState::keep_earliest_impacts() {
  std::size_t kept = 0;
  for (std::size_t k = 0; k < impacts_.size(); ++k) {
    const Impact& i = impacts_[k];
    if (kept > 0 && impacts_[kept - 1].a == i.a && impacts_[kept - 1].b == i.b) {
      if (i.t < impacts_[kept - 1].t) impacts_[kept - 1] = i;
    } else {
      impacts_[kept++] = i;
    }
  }
  impacts_.resize(kept);
}

// The next step of every continuous body begins at its pose now.
void WorldState::begin_steps() {
  for (Step& s : continuous_) {
    s.start = pose_of(entries_[s.entry].shape);
    refresh_box(s.entry);
  }
}

void WorldState::join_steps(std::uint32_t index) {
  ShapeEntry& p = entries_[index];
  p.step = static_cast<std::uint32_t>(continuous_.size());
  continuous_.push_back({index, pose_of(p.shape)});
}

// The later steps move up one place, in order: begin_steps() refreshes the boxes in the order the
// shapes became continuous.
void WorldState::leave_steps(std::uint32_t index) {
  const std::uint32_t at = entries_[index].step;
  continuous_.erase(continuous_.begin() + at);
  for (std::uint32_t k = at; k < continuous_.size(); ++k) entries_[continuous_[k].entry].step = k;
  entries_[index].step = kNone;
}

}  // namespace collide2d::detail
