// World::state_hash(): a digest of the bodies and of the last update's results, defined word by word
// in docs/world.md (the state hash), so that two machines that hold the same World compute the same
// value, whatever their compiler, library or thread count.
#include <collide2d/world.h>

#include "engine/world_state.h"
#include "shapes/internal.h"

#include <cstdint>
#include <vector>

namespace collide2d {
namespace {

class Digest {
 public:
  // h = (h ^ w) * P, then h ^= h >> 32: each step is a bijection of h, so that changing any one
  // word changes the digest.
  void word(std::uint64_t w) {
    h_ = (h_ ^ w) * 0x100000001b3u;
    h_ ^= h_ >> 32;
  }
  void real(double x) { word(detail::bit_copy<std::uint64_t>(x)); }
  void point(const Vec2& p) {
    real(p.x());
    real(p.y());
  }
  template <class Id>
  void id(const Id& handle) {
    word(std::uint64_t{handle.generation} << 32 | handle.index);
  }
  void ids(const PairIds& p) {
    id(p.a);
    id(p.b);
    id(p.shape_a);
    id(p.shape_b);
  }
  // A list: its length, then each record, so that no record can pass for another list's.
  template <class T, class Each>
  void list(const std::vector<T>& records, Each each) {
    word(records.size());
    for (const T& r : records) each(r);
  }
  std::uint64_t value() const { return h_; }

 private:
  std::uint64_t h_ = 0xcbf29ce484222325u;
};

void overlap(Digest& d, const OverlapArea& o) {
  d.real(o.area);
  d.point(o.centroid);
  d.word(static_cast<std::uint64_t>(o.crossings));
  d.point(o.chord[0]);
  d.point(o.chord[1]);
}

void contact(Digest& d, const BodyContact& c, bool areas) {
  d.ids(c);
  d.word(c.touching);
  d.real(c.contact.separation);
  d.point(c.contact.normal);
  d.point(c.contact.point_a);
  d.point(c.contact.point_b);
  d.word(static_cast<std::uint64_t>(c.contact.manifold_size));
  for (const ContactPoint& p : c.contact.points()) {
    d.point(p.point_a);
    d.point(p.point_b);
    d.real(p.separation);
    d.word(p.id);
  }
  if (areas) overlap(d, c.overlap);
}

}  // namespace

std::uint64_t World::state_hash() const {
  Digest d;
  d.list(bodies(), [&](const BodyId& b) {
    d.id(b);
    d.word(user_id(b));
    const Pose p = pose(b);
    d.point(p.position);
    d.real(p.angle);
  });
  d.list(overlapping(), [&](const ShapePair& p) { d.ids(p); });
  d.list(proximity(), [&](const Proximity& p) {
    d.ids(p);
    d.real(p.result.distance);
    d.point(p.result.point_a);
    d.point(p.result.point_b);
  });
  const bool areas = state_->overlap_areas();
  d.list(contacts(), [&](const BodyContact& c) { contact(d, c, areas); });
  d.list(impacts(), [&](const Impact& i) {
    d.ids(i);
    d.real(i.t);
    d.point(i.normal);
    d.point(i.point);
  });
  d.list(sensing(), [&](const SensorPair& p) {
    d.id(p.sensor);
    d.id(p.visitor);
    d.id(p.sensor_shape);
    d.id(p.visitor_shape);
    if (areas) overlap(d, p.overlap);
  });
  return d.value();
}

}  // namespace collide2d
