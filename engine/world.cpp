// The public World: each call goes to its state (engine/world_state.h).
#include <collide2d/world.h>

#include "engine/world_state.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <tuple>
#include <vector>

namespace collide2d {

World::World(const WorldOptions& options) : state_(std::make_unique<detail::WorldState>(options)) {}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

BodyId World::add(const Shape& shape, const BodyDef& def) {
  validate(shape);  // so that a refusal names the shape's own fields
  const ShapeDef only{.shape = detail::placed_at(shape, Vec2::Zero(), 0.0)};
  return state_->add({center_of(shape), angle_of(shape)}, std::span(&only, 1), def);
}
BodyId World::add(const Pose& pose, std::span<const ShapeDef> shapes, const BodyDef& def) {
  return state_->add(pose, shapes, def);
}
BodyId World::add_chain(std::span<const Vec2> points, bool loop, const ChainDef& def) {
  return state_->add_chain(points, loop, def);
}
ShapeId World::add_shape(BodyId body, const ShapeDef& shape) { return state_->add_shape(body, shape); }
void World::remove_shape(ShapeId id) { state_->remove_shape(id); }
void World::set_pose(BodyId id, const Vec2& position, double angle) { state_->set_pose(id, position, angle); }
void World::move_to(BodyId id, const Vec2& position, double angle) { state_->move_to(id, position, angle); }
void World::move_by(BodyId id, const Vec2& shift, double turn) { state_->move_by(id, shift, turn); }
void World::set_static(BodyId id, bool is_static) { state_->set_static(id, is_static); }
void World::set_filter(BodyId id, const Filter& filter) { state_->set_filter(id, filter); }
void World::set_filter(ShapeId id, const Filter& filter) { state_->set_filter(id, filter); }
void World::set_sensor(ShapeId id, bool sensor) { state_->set_sensor(id, sensor); }
void World::set_local_shape(ShapeId id, const Shape& local) { state_->set_local_shape(id, local); }
void World::set_pair_predicate(std::function<bool(BodyId, BodyId)> predicate) {
  state_->set_pair_predicate(std::move(predicate));
}
void World::remove(BodyId id) { state_->remove(id); }
void World::set_proximity_margin(double margin) { state_->set_proximity_margin(margin); }
void World::set_continuous(BodyId id, bool continuous) { state_->set_continuous(id, continuous); }
void World::set_ghost(BodyId id, bool ghost) { state_->set_ghost(id, ghost); }
void World::update() { state_->update(); }

bool World::contains(BodyId id) const { return state_->contains(id); }
bool World::contains(ShapeId id) const { return state_->contains(id); }
std::size_t World::size() const { return state_->size(); }
unsigned World::threads() const { return state_->threads(); }
const detail::WorldState& detail::state_of(const World& world) { return *world.state_; }

Pose World::pose(BodyId id) const { return state_->pose(id); }
Vec2 World::displacement(BodyId id, const Vec2& point) const { return state_->displacement(id, point); }
const Shape& World::shape(BodyId id) const { return state_->shape(id); }
std::uint64_t World::user_id(BodyId id) const { return state_->user_id(id); }
const Filter& World::filter(BodyId id) const { return state_->filter(id); }
bool World::is_static(BodyId id) const { return state_->is_static(id); }
bool World::is_sensor(BodyId id) const { return state_->is_sensor(id); }
bool World::is_continuous(BodyId id) const { return state_->is_continuous(id); }
bool World::is_ghost(BodyId id) const { return state_->is_ghost(id); }
std::vector<ShapeId> World::shapes(BodyId id) const { return state_->shapes(id); }
const Shape& World::shape(ShapeId id) const { return state_->shape(id); }
Shape World::local_shape(ShapeId id) const { return state_->local_shape(id); }
BodyId World::body(ShapeId id) const { return state_->body_of(id); }
std::optional<ChainSegment> World::chain_segment(ShapeId id) const { return state_->chain_segment(id); }
std::uint64_t World::user_id(ShapeId id) const { return state_->user_id(id); }
const Filter& World::filter(ShapeId id) const { return state_->filter(id); }
bool World::is_sensor(ShapeId id) const { return state_->is_sensor(id); }
std::vector<BodyId> World::bodies() const { return state_->bodies(); }

const std::vector<ShapePair>& World::overlapping() const { return state_->overlapping_; }
const std::vector<ShapePair>& World::began() const { return state_->began_; }
const std::vector<ShapePair>& World::ended() const { return state_->ended_; }
const std::vector<BodyPair>& World::body_overlapping() const { return state_->body_overlapping_; }
const std::vector<BodyPair>& World::body_began() const { return state_->body_began_; }
const std::vector<BodyPair>& World::body_ended() const { return state_->body_ended_; }
const std::vector<Proximity>& World::proximity() const { return state_->proximity_; }
const std::vector<BodyContact>& World::contacts() const { return state_->contacts_; }
const std::vector<Impact>& World::impacts() const { return state_->impacts_; }
const std::vector<SensorPair>& World::sensing() const { return state_->sensing_; }
const std::vector<SensorPair>& World::sensor_began() const { return state_->sensor_began_; }
const std::vector<SensorPair>& World::sensor_ended() const { return state_->sensor_ended_; }
const std::vector<SensorVisit>& World::body_sensing() const { return state_->body_sensing_; }
const std::vector<SensorVisit>& World::body_sensor_began() const { return state_->body_sensor_began_; }
const std::vector<SensorVisit>& World::body_sensor_ended() const { return state_->body_sensor_ended_; }
std::span<const std::uint32_t> World::contacts_of(BodyId id) const { return state_->contacts_of(id); }
const FrameStats& World::last_frame() const { return state_->stats_; }
std::vector<ShapePair> World::candidates() const { return state_->candidates(); }
Aabb World::broad_box(ShapeId id) const { return state_->broad_box(id); }
Aabb World::reach_box(ShapeId id) const { return state_->reach_box(id); }

Vec2 owner_point(const Aabb& a, const Aabb& b) { return a.min.cwiseMax(b.min); }

// As WorldState::broad_box() of a shape's entry, to the bit.
Aabb reach_box(const Shape& shape, const std::optional<Pose>& start, const WorldOptions& options) {
  const Aabb box = start ? detail::swept(*start, shape) : aabb(shape, Orientation::of(angle_of(shape)));
  return detail::grown(box, 0.5 * std::max(options.proximity_margin, options.speculative_margin));
}

namespace {

// The bodies of the shapes a callback query finds, each once, by index.
template <class Query>
std::vector<BodyId> collect(Query query) {
  std::vector<BodyId> found;
  query([&found](const BodyShape& s) {
    found.push_back(s.body);
    return true;
  });
  std::sort(found.begin(), found.end(), [](BodyId p, BodyId q) { return p.index < q.index; });
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

// A hit's place in the order of hits: by `t`, then body index, then shape index.
template <class Hit>
auto rank_of(const Hit& hit, double t) {
  return std::tuple(t, hit.body.index, hit.shape.index);
}

// Whether `hit` at `t` comes before the best so far.
template <class Hit>
bool before(const std::optional<Hit>& best, const Hit& hit, double t, double best_t) {
  return !best || rank_of(hit, t) < rank_of(*best, best_t);
}

// The reach that keeps only hits as near as `t`: the callback's 0 would stop the walk before a
// lower index hit at 0 too is seen, so 0 clips to the least positive double instead.
double clip_to(double t) { return std::max(t, std::numeric_limits<double>::denorm_min()); }

}  // namespace

void World::overlapping(const Shape& shape, FunctionRef<bool(const BodyShape&)> visit,
                        const QueryFilter& filter) const {
  state_->overlapping(shape, visit, filter);
}
std::vector<BodyId> World::overlapping(const Shape& shape, const QueryFilter& filter) const {
  return collect([&](FunctionRef<bool(const BodyShape&)> visit) { overlapping(shape, visit, filter); });
}
void World::overlapping(const Aabb& box, FunctionRef<bool(const BodyShape&)> visit, const QueryFilter& filter) const {
  state_->overlapping(box, visit, filter);
}
std::vector<BodyId> World::overlapping(const Aabb& box, const QueryFilter& filter) const {
  return collect([&](FunctionRef<bool(const BodyShape&)> visit) { overlapping(box, visit, filter); });
}
void World::within(const Vec2& point, double distance, FunctionRef<bool(const BodyShape&)> visit,
                   const QueryFilter& filter) const {
  state_->within(point, distance, visit, filter);
}
std::vector<BodyId> World::within(const Vec2& point, double distance, const QueryFilter& filter) const {
  return collect([&](FunctionRef<bool(const BodyShape&)> visit) { within(point, distance, visit, filter); });
}
void World::within(const Shape& shape, double distance, FunctionRef<bool(const BodyShape&)> visit,
                   const QueryFilter& filter) const {
  state_->within(shape, distance, visit, filter);
}
std::vector<BodyId> World::within(const Shape& shape, double distance, const QueryFilter& filter) const {
  return collect([&](FunctionRef<bool(const BodyShape&)> visit) { within(shape, distance, visit, filter); });
}

void World::ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                     FunctionRef<double(const RayHit&)> visit, const QueryFilter& filter,
                     const RayOptions& options) const {
  state_->ray_cast(origin, direction, max_distance, visit, filter, options);
}
std::optional<RayHit> World::ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                                      const QueryFilter& filter, const RayOptions& options) const {
  std::optional<RayHit> best;
  const auto keep = [&best](const RayHit& hit) {
    if (before(best, hit, hit.distance, best ? best->distance : 0.0)) best = hit;
    return clip_to(best->distance);
  };
  ray_cast(origin, direction, max_distance, keep, filter, options);
  return best;
}
std::vector<RayHit> World::ray_cast_all(const Vec2& origin, const Vec2& direction, double max_distance,
                                        const QueryFilter& filter, const RayOptions& options) const {
  std::vector<RayHit> hits;
  const auto keep = [&hits](const RayHit& hit) {
    hits.push_back(hit);
    return -1.0;
  };
  ray_cast(origin, direction, max_distance, keep, filter, options);
  std::sort(hits.begin(), hits.end(),
            [](const RayHit& p, const RayHit& q) { return rank_of(p, p.distance) < rank_of(q, q.distance); });
  return hits;
}

void World::cast(const Shape& shape, const Vec2& translation, FunctionRef<double(const BodyCastHit&)> visit,
                 const QueryFilter& filter, const CastOptions& options) const {
  state_->cast(shape, translation, visit, filter, options);
}
std::optional<BodyCastHit> World::cast(const Shape& shape, const Vec2& translation, const QueryFilter& filter,
                                       const CastOptions& options) const {
  std::optional<BodyCastHit> best;
  const auto keep = [&best](const BodyCastHit& hit) {
    if (before(best, hit, hit.fraction, best ? best->fraction : 0.0)) best = hit;
    return clip_to(best->fraction);
  };
  cast(shape, translation, keep, filter, options);
  return best;
}

double World::cast_mover(const Shape& mover, const Vec2& translation, const MoverQuery& query) const {
  return state_->cast_mover(mover, translation, query);
}
void World::collide_mover(const Shape& mover, FunctionRef<bool(const MoverPlane&)> visit,
                          const MoverQuery& query) const {
  state_->collide_mover(mover, visit, query);
}
std::vector<MoverPlane> World::collide_mover(const Shape& mover, const MoverQuery& query) const {
  std::vector<MoverPlane> planes;
  collide_mover(
      mover,
      [&planes](const MoverPlane& p) {
        planes.push_back(p);
        return true;
      },
      query);
  std::sort(planes.begin(), planes.end(), [](const MoverPlane& p, const MoverPlane& q) {
    return std::pair(p.body.index, p.shape.index) < std::pair(q.body.index, q.shape.index);
  });
  return planes;
}

}  // namespace collide2d
