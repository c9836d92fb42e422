// Queries on the current poses: each validates its input, looks up the boxes it meets in the moving
// bodies' tree and the static tree, then tests the exact shapes, and calls back with what it finds
// in the trees' order (world.cpp collects and sorts for the other forms). The sweep-and-prune strips are not used for
// them: a strip's endpoints answer "which boxes overlap along the sweep axis" well, but neither a ray nor a box far
// smaller than a strip, and a tree answers both in O(log n + hits).
#include "engine/world_state.h"

#include <collide2d/kernels.h>
#include <collide2d/ray_cast.h>

#include <atomic>
#include <cmath>
#include <stdexcept>
#include <string>

namespace collide2d::detail {
namespace {

bool lets_through(const QueryFilter& q, const Filter& f) {
  return (f.category & q.mask) != 0 && (f.mask & q.category) != 0;
}

// Counts a callback query for as long as it runs, so that the World refuses changes meanwhile.
class Querying {
 public:
  explicit Querying(std::atomic<int>& count) : count_(count) { count_.fetch_add(1, std::memory_order_relaxed); }
  ~Querying() { count_.fetch_sub(1, std::memory_order_relaxed); }
  Querying(const Querying&) = delete;
  Querying& operator=(const Querying&) = delete;

 private:
  std::atomic<int>& count_;
};

// What a callback's answer does to the reach (Box2D v3's b2CastResultFcn): 0 stops the walk (a
// negative reach, for the trees), a value within (0, reach) shortens it, anything else leaves it.
double next_reach(double answer, double reach) {
  if (answer == 0.0) return -1.0;
  return answer > 0.0 && answer < reach ? answer : reach;
}

}  // namespace

void WorldState::require_not_querying(const char* call) const {
  if (querying_.load(std::memory_order_relaxed) > 0) {
    throw std::logic_error(std::string(call) +
                           " called from inside a query's callback: the World cannot change while a query walks it");
  }
}

// The moving shapes' tree, built by the first query from their fat boxes (a stale leaf's is then
// its new box, and the walks below test it from stale_leaves_ all the same), top-down.
void WorldState::need_moving_tree() const {
  if (moving_tree_on_.load(std::memory_order_acquire)) return;
  const std::lock_guard lock(moving_tree_mutex_);
  if (moving_tree_on_.load(std::memory_order_relaxed)) return;
  moving_leaves_.assign(part_of_.size(), -1);
  for (ProxyId proxy = 0; proxy < part_of_.size(); ++proxy) {
    if (part_of_[proxy] != kNone) moving_leaves_[proxy] = moving_tree_.insert(broad_.fat_box(proxy), part_of_[proxy]);
  }
  moving_tree_.rebuild();
  moving_perimeter_ = moving_tree_.inner_perimeter();
  moving_tree_on_.store(true, std::memory_order_release);
}

// visit(found) for the solid shapes the filter lets through whose tight box meets `box` and that
// pass `test`, in the trees' order, until visit returns false.
template <class Test>
void WorldState::each(const Aabb& box, const QueryFilter& filter, Test test, FunctionRef<bool(const BodyShape&)> visit,
                      const Nearby* near) const {
  const Querying guard(querying_);
  bool go = true;
  const auto consider = [&](std::uint32_t index) {
    const ShapeEntry& p = entries_[index];
    if (!p.sensor && lets_through(filter, p.filter) && intersects(p.box, box) && test(p.shape))
      go = visit({p.body, shape_id(index)});
    return go;
  };
  if (near && encloses(near->box, box)) {
    for (std::size_t k = 0; go && k < near->shapes.size(); ++k) consider(near->shapes[k]);
    return;
  }
  need_moving_tree();
  // A shape whose tree leaf is stale is tested from stale_leaves_ instead (see below).
  moving_tree_.query(box, [&](std::uint32_t index) { return entries_[index].stale_at >= 0 || consider(index); });
  for (std::size_t k = 0; go && k < stale_leaves_.size(); ++k) consider(stale_leaves_[k]);
  if (go) static_tree_.query(box, consider);
}

void WorldState::overlapping(const Shape& shape, FunctionRef<bool(const BodyShape&)> visit,
                             const QueryFilter& filter) const {
  validate(shape);
  each(
      aabb(shape), filter, [&shape](const Shape& s) { return overlaps(shape, s); }, visit);
}

void WorldState::overlapping(const Aabb& box, FunctionRef<bool(const BodyShape&)> visit,
                             const QueryFilter& filter) const {
  validate(box);
  each(
      box, filter, [&box](const Shape& s) { return overlaps(s, box); }, visit);
}

void WorldState::within(const Vec2& point, double d, FunctionRef<bool(const BodyShape&)> visit,
                        const QueryFilter& filter) const {
  validate_point(point, "point");
  require_margin(d, "distance");
  if (d > 0.0) return overlapping(Shape(Circle{point, d}), visit, filter);
  each(
      {point, point}, filter, [&point](const Shape& s) { return collide2d::contains(s, point); }, visit);
}

void WorldState::within(const Shape& shape, double d, FunctionRef<bool(const BodyShape&)> visit,
                        const QueryFilter& filter) const {
  validate(shape);
  require_margin(d, "distance");
  each(
      grown(aabb(shape), d), filter, [&](const Shape& s) { return distance(shape, s).distance <= d; }, visit);
}

void WorldState::cast(const Shape& shape, const Vec2& translation, FunctionRef<double(const BodyCastHit&)> visit,
                      const QueryFilter& filter, const CastOptions& options) const {
  validate(shape);
  require_finite(translation.x(), "cast translation x");
  require_finite(translation.y(), "cast translation y");
  const Shape end = at_time(shape, {translation, 0.0}, 1.0);
  validate(end);  // the range of the centre
  double reach = 1.0;
  const auto meet = [&](const BodyShape& found) {
    const Shape& target = entries_[found.shape.index].shape;
    if (options.skip_initial_overlap && overlaps(shape, target)) return true;
    if (entries_[found.shape.index].chain && !in_front(chain_of(found.shape.index), shape)) return true;  // one-sided
    const auto hit = shape_cast(shape, translation, target);
    if (hit && hit->fraction <= reach)
      reach = next_reach(visit({found.body, found.shape, hit->fraction, hit->point, hit->normal}), reach);
    return reach >= 0.0;
  };
  each(
      swept(pose_of(shape), end), filter, [](const Shape&) { return true; }, meet);
}

// A mover query's checks: the shape, the skin, the mover's own body (a stale handle is refused).
void WorldState::validate_mover(const Shape& mover, const MoverQuery& query) const {
  validate(mover);
  require_margin(query.skin, "mover skin");
  if (query.self) body(*query.self);
}

double WorldState::cast_mover(const Shape& mover, const Vec2& translation, const MoverQuery& query) const {
  validate_mover(mover, query);
  require_finite(translation.x(), "mover translation x");
  require_finite(translation.y(), "mover translation y");
  validate(at_time(mover, {translation, 0.0}, 1.0));  // the range of the centre
  return cast_mover(mover, Orientation::of(angle_of(mover)), translation, query);
}

void WorldState::gather(const Aabb& box, const QueryFilter& filter, Nearby& out) const {
  out.box = box;
  out.shapes.clear();
  each(
      box, filter, [](const Shape&) { return true; },
      [&](const BodyShape& found) {
        out.shapes.push_back(found.shape.index);
        return true;
      });
}

double WorldState::cast_mover(const Shape& mover, const Orientation& turn, const Vec2& translation,
                              const MoverQuery& query, const Nearby* near) const {
  double reach = 1.0;
  const auto meet = [&](const BodyShape& found) {
    const ShapeEntry& p = entries_[found.shape.index];
    if (found.body == query.self || (p.chain && !in_front(chain_of(found.shape.index), mover))) return true;
    reach = mover_cast(mover, turn, translation, p.shape, p.orientation, query.skin, reach);
    return reach > 0.0;
  };
  // A shape stops the mover only within the skin of its path.
  const Shape end = at_time(mover, {translation, 0.0}, 1.0);
  each(
      grown(swept(pose_of(mover), end), query.skin), query.filter, [](const Shape&) { return true; }, meet, near);
  return reach;
}

void WorldState::collide_mover(const Shape& mover, FunctionRef<bool(const MoverPlane&)> visit,
                               const MoverQuery& query) const {
  validate_mover(mover, query);
  collide_mover(mover, Orientation::of(angle_of(mover)), visit, query);
}

void WorldState::collide_mover(const Shape& mover, const Orientation& turn, FunctionRef<bool(const MoverPlane&)> visit,
                               const MoverQuery& query, const Nearby* near) const {
  const ContactOptions within_skin{.max_separation = query.skin};
  const auto meet = [&](const BodyShape& found) {
    if (found.body == query.self) return true;
    const std::uint32_t index = found.shape.index;
    const ShapeEntry& p = entries_[index];
    const Contact c = p.chain ? contact(chain_of(index), p.orientation, mover, turn, within_skin)
                              : contact(p.shape, p.orientation, mover, turn, within_skin);
    if (c.empty() || c.separation > query.skin) return true;
    return visit({found.body, found.shape, p.body_user_id, c.point_a, c.normal, c.separation});
  };
  each(
      grown(aabb(mover, turn), query.skin), query.filter, [](const Shape&) { return true; }, meet, near);
}

Contact WorldState::contact_with(ShapeId id, const Shape& other, const Orientation& turn) const {
  const ShapeEntry& p = entry(id);
  return contact(p.shape, p.orientation, other, turn);
}

void WorldState::ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                          FunctionRef<double(const RayHit&)> visit, const QueryFilter& filter,
                          const RayOptions& options) const {
  validate_point(origin, "ray origin");
  require_finite(direction.x(), "ray direction x");
  require_finite(direction.y(), "ray direction y");
  if (std::isnan(max_distance) || max_distance < 0.0) throw std::invalid_argument("ray length must not be negative");
  const double length = direction.norm();
  if (!(length > 0.0)) throw std::invalid_argument("ray direction must not be zero");
  const Vec2 unit = direction / length;
  const Querying guard(querying_);
  // The reach after shape `index`; the kernel's zero normal marks a shape that contains the origin.
  const auto visit_shape = [&](std::uint32_t index, double reach) {
    const ShapeEntry& p = entries_[index];
    if (p.sensor || !lets_through(filter, p.filter)) return reach;
    const auto hit = p.chain ? collide2d::ray_cast(chain_of(index), origin, unit, reach)
                             : collide2d::ray_cast(p.shape, origin, unit, reach);
    if (!hit || (!options.from_inside && hit->normal == Vec2::Zero())) return reach;
    return next_reach(visit(RayHit{p.body, shape_id(index), hit->distance, hit->point, hit->normal}), reach);
  };
  double reach = max_distance;
  need_moving_tree();
  moving_tree_.ray_cast(origin, unit, reach, [&](std::uint32_t index, double r) {
    return reach =
               entries_[index].stale_at < 0 ? visit_shape(index, r) : r;  // a stale leaf is tested from stale_leaves_
  });
  for (std::size_t k = 0; reach >= 0.0 && k < stale_leaves_.size(); ++k) reach = visit_shape(stale_leaves_[k], reach);
  if (reach >= 0.0) static_tree_.ray_cast(origin, unit, reach, visit_shape);
}

}  // namespace collide2d::detail
