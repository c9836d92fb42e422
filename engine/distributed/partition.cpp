// A World split by slabs along x: the regions' Worlds kept in step with their bodies' records, and
// the pairs each region reports by the owner-point rule (partition.h, docs/distributed.md).
#include <collide2d/partition.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace collide2d {

Slabs::Slabs(std::vector<double> bounds) : bounds_(std::move(bounds)) {
  for (std::size_t k = 0; k < bounds_.size(); ++k) {
    if (!std::isfinite(bounds_[k]) || (k > 0 && !(bounds_[k - 1] < bounds_[k]))) {
      throw std::invalid_argument("slab bound " + std::to_string(k) + " must be finite and above the one before it");
    }
  }
}

Slabs Slabs::balanced(std::vector<double> xs, int count) {
  if (xs.empty()) throw std::invalid_argument("balanced slabs need at least one x");
  std::sort(xs.begin(), xs.end());
  std::vector<double> bounds;
  for (int k = 1; k < count; ++k) {
    const double x = xs[xs.size() * static_cast<std::size_t>(k) / static_cast<std::size_t>(count)];
    bounds.push_back(bounds.empty() || bounds.back() < x ? x : std::nextafter(bounds.back(), INFINITY));
  }
  return Slabs(std::move(bounds));
}

int Slabs::region_of(double x) const {
  return static_cast<int>(std::upper_bound(bounds_.begin(), bounds_.end(), x) - bounds_.begin());
}

std::pair<int, int> Slabs::regions_of(const Aabb& box) const {
  return {region_of(box.min.x()), region_of(box.max.x())};
}

namespace {

// A pair record turned round: A's and B's handles, ids and values swapped.
template <class Record>
void turn_ids(Record& r) {
  std::swap(r.a, r.b);
  std::swap(r.shape_a, r.shape_b);
  std::swap(r.user_a, r.user_b);
  std::swap(r.shape_user_a, r.shape_user_b);
}
void turn(ShapePair& r) { turn_ids(r); }
void turn(Proximity& r) {
  turn_ids(r);
  r.result = r.result.swapped();
}
void turn(BodyContact& r) {
  turn_ids(r);
  r.contact = r.contact.swapped();
  std::swap(r.overlap.chord[0], r.overlap.chord[1]);
}
void turn(Impact& r) {
  turn_ids(r);
  r.normal = -r.normal;
}

// The records `keep` takes, each with its ids in increasing order, sorted by them.
template <class Record, class Keep>
void ordered(const std::vector<Record>& from, Keep keep, std::vector<Record>& out) {
  out.clear();
  for (Record r : from) {
    if (!keep(r.shape_a, r.shape_b)) continue;
    if (r.user_b < r.user_a) turn(r);
    out.push_back(r);
  }
  std::sort(out.begin(), out.end(), [](const Record& p, const Record& q) {
    return std::pair(p.user_a, p.user_b) < std::pair(q.user_a, q.user_b);
  });
}

template <class Keep>
void report_of(const World& world, Keep keep, RegionReport& out) {
  ordered(world.overlapping(), keep, out.overlapping);
  ordered(world.proximity(), keep, out.proximity);
  ordered(world.contacts(), keep, out.contacts);
  ordered(world.impacts(), keep, out.impacts);
  out.sensing.clear();
  for (const SensorPair& s : world.sensing()) {
    if (keep(s.sensor_shape, s.visitor_shape)) out.sensing.push_back(s);
  }
  std::sort(out.sensing.begin(), out.sensing.end(), [](const SensorPair& p, const SensorPair& q) {
    return std::pair(p.user_sensor, p.user_visitor) < std::pair(q.user_sensor, q.user_visitor);
  });
}

}  // namespace

RegionWorld::RegionWorld(const WorldOptions& options, Slabs slabs, int region)
    : world_(options), slabs_(std::move(slabs)), region_(region) {
  if (region < 0 || region >= slabs_.count()) {
    throw std::invalid_argument("region " + std::to_string(region) + " is not one of the " +
                                std::to_string(slabs_.count()) + " slabs");
  }
}

std::optional<BodyId> RegionWorld::find(std::uint64_t id) const {
  const auto it = bodies_.find(id);
  if (it == bodies_.end()) return std::nullopt;
  return it->second.body;
}

void RegionWorld::place(const BodyRecord& r, bool ghost) {
  auto it = bodies_.find(r.id);
  if (it == bodies_.end()) {
    const BodyId body = world_.add(
        r.shape, {.user_id = r.id, .filter = r.filter, .is_static = r.is_static, .sensor = r.sensor, .ghost = ghost});
    it = bodies_.emplace(r.id, Held{body, world_.shapes(body).front(), 0}).first;
  }
  Held& held = it->second;
  held.frame = frame_;
  const BodyId body = held.body;
  if (world_.is_static(body) != r.is_static) world_.set_static(body, r.is_static);
  if (world_.is_ghost(body) != ghost) world_.set_ghost(body, ghost);
  if (world_.filter(body) != r.filter) world_.set_filter(body, r.filter);
  if (world_.is_sensor(held.shape) != r.sensor) world_.set_sensor(held.shape, r.sensor);
  if (world_.is_continuous(body) != r.continuous) world_.set_continuous(body, r.continuous);
  // A continuous body's step starts where the record says, as in the World that has held it all
  // along; then it moves on to where it is.
  if (r.continuous) world_.set_pose(body, r.start.position, r.start.angle);
  const Pose now = pose_of(r.shape);
  world_.move_to(body, now.position, now.angle);
}

void RegionWorld::sync(std::span<const BodyRecord> owned, std::span<const BodyRecord> ghosts) {
  ++frame_;
  for (const BodyRecord& r : owned) place(r, false);
  for (const BodyRecord& r : ghosts) place(r, true);
  std::erase_if(bodies_, [this](const auto& entry) {
    if (entry.second.frame == frame_) return false;
    world_.remove(entry.second.body);
    return true;
  });
}

BodyId RegionWorld::add_chain(std::uint64_t id, std::span<const Vec2> points, bool loop, const ChainDef& def) {
  ChainDef d = def;
  d.user_id = id;
  const BodyId body = world_.add_chain(points, loop, d);
  level_.push_back(body);
  std::uint32_t place = 0;
  for (const ShapeId s : world_.shapes(body)) part_[s.index] = place++;
  return body;
}

std::uint32_t RegionWorld::part_of(ShapeId shape) const {
  const auto it = part_.find(shape.index);
  return it == part_.end() ? 0 : it->second;
}

std::optional<Aabb> RegionWorld::level_reach(ShapeId shape) const {
  if (part_.count(shape.index) == 0) return std::nullopt;
  return world_.reach_box(shape);
}

void RegionWorld::set_pair_predicate(std::function<bool(std::uint64_t, std::uint64_t)> predicate) {
  if (!predicate) return world_.set_pair_predicate({});
  world_.set_pair_predicate([this, predicate = std::move(predicate)](BodyId a, BodyId b) {
    const std::uint64_t x = world_.user_id(a), y = world_.user_id(b);
    return predicate(std::min(x, y), std::max(x, y));
  });
}

void RegionWorld::update() {
  // Each shape's reach box for this update (a continuous one's changes with it).
  const auto keep = [this](ShapeId s) {
    if (reach_.size() <= s.index) reach_.resize(s.index + 1);
    reach_[s.index] = world_.reach_box(s);
  };
  for (const auto& [id, held] : bodies_) keep(held.shape);
  for (const BodyId level : level_) {
    for (const ShapeId s : world_.shapes(level)) keep(s);
  }
  world_.update();
  report_of(
      world_,
      [this](ShapeId a, ShapeId b) {
        return slabs_.region_of(owner_point(reach_[a.index], reach_[b.index]).x()) == region_;
      },
      report_);
}

RegionReport whole_report(const World& world) {
  RegionReport out;
  report_of(
      world, [](ShapeId, ShapeId) { return true; }, out);
  return out;
}

}  // namespace collide2d
