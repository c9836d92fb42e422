// The pairs of a World as a check independent of its own aabb() sees them: shared by the World test
// and the soak run.
#pragma once

#include <collide2d/world.h>
#include "chain_rules.h"
#include "mp_reference.h"

#include <algorithm>
#include <vector>

namespace collide2d::reference {

// Every shape of the World with its body, by body index (a body's shapes in the order added).
inline std::vector<BodyShape> all_shapes(const World& world) {
  std::vector<BodyShape> out;
  for (const BodyId body : world.bodies()) {
    for (const ShapeId shape : world.shapes(body)) out.push_back({body, shape});
  }
  return out;
}

// The pair of two shapes of different bodies, x's body the lower index.
inline ShapePair pair_of(const BodyShape& x, const BodyShape& y) { return {x.body, y.body, x.shape, y.shape}; }

// The pairs of shapes of different bodies whose exact boxes (50 digits, rounded outward;
// bounding_box), grown by `grow` on every side, meet: every overlapping pair, and with grow = margin
// / 2 every pair within the margin, is among them. Sorted.
inline std::vector<ShapePair> exact_box_pairs(const World& world, double grow) {
  const std::vector<BodyShape> all = all_shapes(world);
  std::vector<Aabb> boxes;
  boxes.reserve(all.size());
  for (const BodyShape& s : all) {
    const Aabb b = bounding_box(world.shape(s.shape));
    boxes.push_back({b.min.array() - grow, b.max.array() + grow});
  }
  std::vector<ShapePair> pairs;
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      if (all[i].body != all[j].body && intersects(boxes[i], boxes[j])) pairs.push_back(pair_of(all[i], all[j]));
    }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// What a World should report, from every pair of shapes tested directly with the narrow phase it
// uses, under its rules: no pair of one body's shapes, none of two static bodies, none the filters
// refuse; a pair with one sensor goes to sensing (sensors sense no sensor); solid pairs overlap (a
// chain's segment's where its rules give a contact), or lie within `margin` (near). Sorted.
struct AllPairs {
  std::vector<ShapePair> overlapping;
  std::vector<SensorPair> sensing;
  std::vector<ShapePair> near;
};

inline AllPairs all_pairs(const World& world, double margin) {
  const std::vector<BodyShape> all = all_shapes(world);
  AllPairs out;
  for (std::size_t i = 0; i < all.size(); ++i) {
    for (std::size_t j = i + 1; j < all.size(); ++j) {
      const BodyShape& x = all[i];
      const BodyShape& y = all[j];
      if (x.body == y.body || (world.is_static(x.body) && world.is_static(y.body)) ||
          !should_pair(world.filter(x.shape), world.filter(y.shape)))
        continue;
      const Shape& a = world.shape(x.shape);
      const Shape& b = world.shape(y.shape);
      const bool sx = world.is_sensor(x.shape), sy = world.is_sensor(y.shape);
      if (sx || sy) {
        if (sx != sy && collide2d::overlaps(a, b)) {
          out.sensing.push_back(sx ? SensorPair{x.body, y.body, x.shape, y.shape}
                                   : SensorPair{y.body, x.body, y.shape, x.shape});
        }
      } else if (collide2d::overlaps(a, b) && admitted_by_chain(world, x.shape, y.shape)) {
        out.overlapping.push_back(pair_of(x, y));
      } else if (margin > 0 && collide2d::distance(a, b).distance <= margin) {
        out.near.push_back(pair_of(x, y));
      }
    }
  }
  std::sort(out.overlapping.begin(), out.overlapping.end());
  std::sort(out.sensing.begin(), out.sensing.end());
  std::sort(out.near.begin(), out.near.end());
  return out;
}

}  // namespace collide2d::reference
