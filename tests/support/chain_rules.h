// Test helper: the chain rules (chain.h) as a World applies them to a pair of its shapes, for the
// all-pairs checks of the World test, the soak run and the World fuzzer.
#pragma once

#include <collide2d/chain.h>
#include <collide2d/world.h>

namespace collide2d::reference {

// Whether a pair that overlaps passes a chain's rules: where one shape is a chain's segment, its
// contact with the other has points.
inline bool admitted_by_chain(const World& world, ShapeId x, ShapeId y) {
  if (const auto chain = world.chain_segment(x)) return !contact(*chain, world.shape(y)).empty();
  if (const auto chain = world.chain_segment(y)) return !contact(*chain, world.shape(x)).empty();
  return true;
}

}  // namespace collide2d::reference
