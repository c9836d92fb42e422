// The pairs of a World as a check independent of its own aabb() sees them: shared by the World test
// and the soak run.
#pragma once

#include "engine/world.h"
#include "mp_reference.h"

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

}  // namespace collide2d::reference
