// The public World: each call goes to its state (engine/world_state.h).
#include <collide2d/world.h>

#include "engine/world_state.h"

namespace collide2d {

World::World(const WorldOptions& options) : state_(std::make_unique<detail::WorldState>(options)) {}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

BodyId World::add(const Shape& shape, const BodyDef& def) { return state_->add(shape, def); }
void World::set_pose(BodyId id, const Vec2& position, double angle) { state_->set_pose(id, position, angle); }
void World::move_to(BodyId id, const Vec2& position, double angle) { state_->move_to(id, position, angle); }
void World::move_by(BodyId id, const Vec2& shift, double turn) { state_->move_by(id, shift, turn); }
void World::set_static(BodyId id, bool is_static) { state_->set_static(id, is_static); }
void World::set_filter(BodyId id, const Filter& filter) { state_->set_filter(id, filter); }
void World::set_pair_predicate(std::function<bool(BodyId, BodyId)> predicate) {
  state_->set_pair_predicate(std::move(predicate));
}
void World::remove(BodyId id) { state_->remove(id); }
void World::set_proximity_margin(double margin) { state_->set_proximity_margin(margin); }
void World::set_continuous(BodyId id, bool continuous) { state_->set_continuous(id, continuous); }
void World::update() { state_->update(); }

bool World::contains(BodyId id) const { return state_->contains(id); }
std::size_t World::size() const { return state_->size(); }
Pose World::pose(BodyId id) const { return state_->pose(id); }
const Shape& World::shape(BodyId id) const { return state_->shape(id); }
std::uint64_t World::user_id(BodyId id) const { return state_->user_id(id); }
const Filter& World::filter(BodyId id) const { return state_->filter(id); }
bool World::is_static(BodyId id) const { return state_->is_static(id); }
bool World::is_sensor(BodyId id) const { return state_->is_sensor(id); }
bool World::is_continuous(BodyId id) const { return state_->is_continuous(id); }
std::vector<BodyId> World::bodies() const { return state_->bodies(); }

const std::vector<BodyPair>& World::overlapping() const { return state_->overlapping_; }
const std::vector<BodyPair>& World::began() const { return state_->began_; }
const std::vector<BodyPair>& World::ended() const { return state_->ended_; }
const std::vector<Proximity>& World::proximity() const { return state_->proximity_; }
const std::vector<BodyContact>& World::contacts() const { return state_->contacts_; }
const std::vector<Impact>& World::impacts() const { return state_->impacts_; }
const std::vector<SensorPair>& World::sensing() const { return state_->sensing_; }
const std::vector<SensorPair>& World::sensor_began() const { return state_->sensor_began_; }
const std::vector<SensorPair>& World::sensor_ended() const { return state_->sensor_ended_; }
const FrameStats& World::last_frame() const { return state_->stats_; }

std::vector<BodyId> World::overlapping(const Shape& shape, const QueryFilter& filter) const {
  return state_->overlapping(shape, filter);
}
std::vector<BodyId> World::overlapping(const Aabb& box, const QueryFilter& filter) const {
  return state_->overlapping(box, filter);
}
std::vector<BodyId> World::within(const Vec2& point, double distance, const QueryFilter& filter) const {
  return state_->within(point, distance, filter);
}
std::vector<BodyId> World::within(const Shape& shape, double distance, const QueryFilter& filter) const {
  return state_->within(shape, distance, filter);
}
std::optional<RayHit> World::ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                                      const QueryFilter& filter) const {
  return state_->ray_cast(origin, direction, max_distance, filter);
}
std::vector<RayHit> World::ray_cast_all(const Vec2& origin, const Vec2& direction, double max_distance,
                                        const QueryFilter& filter) const {
  return state_->ray_cast_all(origin, direction, max_distance, filter);
}
std::optional<BodyCastHit> World::cast(const Shape& shape, const Vec2& translation, const QueryFilter& filter) const {
  return state_->cast(shape, translation, filter);
}

}  // namespace collide2d
