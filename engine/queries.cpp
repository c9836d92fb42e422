// Queries on the current poses: each validates its input, looks up the boxes it meets in the moving
// bodies' tree and the static tree, then tests the exact shapes, and returns body ids in increasing
// order. The sweep-and-prune strips are not used for them: a strip's endpoints answer "which boxes
// overlap along the sweep axis" well, but neither a ray nor a box far smaller than a strip, and a
// tree answers both in O(log n + hits).
#include "engine/world_state.h"

#include <collide2d/ray_cast.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace collide2d::detail {
namespace {

bool lets_through(const QueryFilter& q, const Filter& f) {
  return (f.category & q.mask) != 0 && (f.mask & q.category) != 0;
}

}  // namespace

// The solid bodies the filter lets through whose tight box meets `box` and that pass `test`, by index.
template <class Test>
std::vector<BodyId> WorldState::select(const Aabb& box, const QueryFilter& filter, Test test) const {
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

std::vector<BodyId> WorldState::overlapping(const Shape& shape, const QueryFilter& filter) const {
  validate(shape);
  return select(aabb(shape), filter, [&shape](const Shape& s) { return overlaps(shape, s); });
}

std::vector<BodyId> WorldState::overlapping(const Aabb& box, const QueryFilter& filter) const {
  validate(box);
  return select(box, filter, [&box](const Shape& s) { return overlaps(s, box); });
}

std::vector<BodyId> WorldState::within(const Vec2& point, double d, const QueryFilter& filter) const {
  validate_point(point, "point");
  require_margin(d, "distance");
  if (d > 0.0) return overlapping(Shape(Circle{point, d}), filter);
  return select({point, point}, filter, [&point](const Shape& s) { return collide2d::contains(s, point); });
}

std::vector<BodyId> WorldState::within(const Shape& shape, double d, const QueryFilter& filter) const {
  validate(shape);
  require_margin(d, "distance");
  return select(grown(aabb(shape), d), filter, [&](const Shape& s) { return distance(shape, s).distance <= d; });
}

std::optional<BodyCastHit> WorldState::cast(const Shape& shape, const Vec2& translation,
                                            const QueryFilter& filter) const {
  validate(shape);
  require_finite(translation.x(), "cast translation x");
  require_finite(translation.y(), "cast translation y");
  const Shape end = at_time(shape, {translation, 0.0}, 1.0);
  validate(end);  // the range of the centre
  std::optional<BodyCastHit> best;
  for (const BodyId id : select(swept(shape, end), filter, [](const Shape&) { return true; })) {
    const auto hit = shape_cast(shape, translation, bodies_[id.index].shape);
    if (hit && (!best || hit->fraction < best->fraction))
      best = BodyCastHit{id, hit->fraction, hit->point, hit->normal};
  }
  return best;
}

// on_hit(hit) for each solid body the filter lets through that the ray hits within the reach, which
// starts at max_distance and becomes what on_hit returns.
template <class OnHit>
void WorldState::rays(const Vec2& origin, const Vec2& direction, double max_distance, const QueryFilter& filter,
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

std::optional<RayHit> WorldState::ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                                           const QueryFilter& filter) const {
  std::optional<RayHit> best;
  rays(origin, direction, max_distance, filter, [&best](const RayHit& hit, double) {
    if (!best || hit.distance < best->distance ||
        (hit.distance == best->distance && hit.body.index < best->body.index)) {
      best = hit;
    }
    return best->distance;
  });
  return best;
}

std::vector<RayHit> WorldState::ray_cast_all(const Vec2& origin, const Vec2& direction, double max_distance,
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

}  // namespace collide2d::detail
