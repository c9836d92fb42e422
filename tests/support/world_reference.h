// The pairs of a World as a check independent of its own aabb() sees them: shared by the World test
// and the soak run.
#pragma once

#include <collide2d/world.h>
#include "mp_reference.h"

#include <algorithm>
#include <vector>

namespace collide2d::reference {

// The pairs of bodies whose exact boxes (50 digits, rounded outward; bounding_box), grown by `grow`
// on every side, meet: every overlapping pair, and with grow = margin / 2 every pair within the
// margin, is among them. Sorted.
inline std::vector<BodyPair> exact_box_pairs(const World& world, double grow) {
  const std::vector<BodyId> ids = world.bodies();
  std::vector<Aabb> boxes;
  boxes.reserve(ids.size());
  for (const BodyId id : ids) {
    const Aabb b = bounding_box(world.shape(id));
    boxes.push_back({b.min.array() - grow, b.max.array() + grow});
  }
  std::vector<BodyPair> pairs;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    for (std::size_t j = i + 1; j < ids.size(); ++j) {
      if (intersects(boxes[i], boxes[j])) pairs.push_back({ids[i], ids[j]});
    }
  }
  return pairs;
}

// What a World should report, from every pair tested directly with the narrow phase it uses, under
// its rules: no pair of two static bodies, none the filters refuse; a pair with one sensor goes to
// sensing (sensors sense no sensor); solid pairs overlap, or lie within `margin` (near). Sorted.
struct AllPairs {
  std::vector<BodyPair> overlapping;
  std::vector<SensorPair> sensing;
  std::vector<BodyPair> near;
};

inline AllPairs all_pairs(const World& world, double margin) {
  const std::vector<BodyId> ids = world.bodies();
  AllPairs out;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    for (std::size_t j = i + 1; j < ids.size(); ++j) {
      const BodyId x = ids[i], y = ids[j];
      if ((world.is_static(x) && world.is_static(y)) || !should_pair(world.filter(x), world.filter(y))) continue;
      const Shape& a = world.shape(x);
      const Shape& b = world.shape(y);
      if (world.is_sensor(x) || world.is_sensor(y)) {
        if (world.is_sensor(x) != world.is_sensor(y) && collide2d::overlaps(a, b)) {
          out.sensing.push_back(world.is_sensor(x) ? SensorPair{x, y} : SensorPair{y, x});
        }
      } else if (collide2d::overlaps(a, b)) {
        out.overlapping.push_back({x, y});
      } else if (margin > 0 && collide2d::distance(a, b).distance <= margin) {
        out.near.push_back({x, y});
      }
    }
  }
  std::sort(out.sensing.begin(), out.sensing.end());
  return out;
}

}  // namespace collide2d::reference
