// Sensors: a sensor shape reports the solid shapes of other bodies that overlap it, in lists of its
// own, and is otherwise not solid. It never appears in the solid pairs, proximity, contacts, impacts
// or queries, and sensors do not sense each other (Box2D v3's rules); filters apply to sensor pairs
// too.
#include "engine/world_state.h"

#include "broadphase/internal.h"

#include <algorithm>

namespace collide2d::detail {
namespace {

// A visit's overlap gathers its shapes' overlaps: the area and the area-weighted sum of centroids,
// divided once all are in (place_centroid).
void add_overlap(SensorVisit& v, const OverlapArea& o) {
  v.area += o.area;
  v.centroid += o.area * o.centroid;
}

void place_centroid(SensorVisit& v, const Shape& sensor) {
  v.centroid = v.area > 0.0 ? Vec2(v.centroid / v.area) : center_of(sensor);
}

}  // namespace

void WorldState::sense(std::uint32_t a, std::uint32_t b, bool touching, ChunkResults& out) const {
  if (!touching) return;
  const std::uint32_t sensor = entries_[a].sensor ? a : b, visitor = sensor == a ? b : a;
  const PairIds ids = ids_of(sensor, visitor);
  out.sensing.push_back({ids.a, ids.b, ids.shape_a, ids.shape_b, ids.user_a, ids.user_b, ids.shape_user_a,
                         ids.shape_user_b, false, pair_overlap(sensor, visitor)});
}

// The first `chunks` chunks' sensor pairs joined in chunk order and sorted, and what entered and
// left.
void WorldState::update_sensing(std::size_t chunks) {
  sensed_.clear();
  for (std::size_t k = 0; k < chunks; ++k)
    sensed_.insert(sensed_.end(), chunks_[k].sensing.begin(), chunks_[k].sensing.end());
  std::sort(sensed_.begin(), sensed_.end());
  replace_pairs(sensing_, sensed_, sensor_began_, sensor_ended_);
  // By visiting bodies: the shape pairs are sorted by bodies, then the sensor shape, so that each
  // visit's pairs are together and the visits come in their own order.
  frame_visits_.clear();
  for (const SensorPair& p : sensing_) {
    const SensorVisit visit{p.sensor, p.visitor, p.sensor_shape, p.user_sensor, p.user_visitor, p.shape_user_sensor};
    if (frame_visits_.empty() || frame_visits_.back() != visit) frame_visits_.push_back(visit);
    add_overlap(frame_visits_.back(), p.overlap);
  }
  if (overlap_areas_) {
    for (SensorVisit& v : frame_visits_) place_centroid(v, entry(v.sensor_shape).shape);
  }
  replace_pairs(body_sensing_, frame_visits_, body_sensor_began_, body_sensor_ended_);
}

}  // namespace collide2d::detail
