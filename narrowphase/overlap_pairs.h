// Private: the batched overlap tests (overlap_batch.h) over pairs given by reference rather than as
// lists of copies: pair k is pairs.pair(pairs.context, k). The World passes its bodies by index
// this way, so that a batch entry is two indices and no shape is copied; the public functions are
// this over their lists.
#pragma once

#include "shapes/shapes.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace collide2d::detail {

template <class A, class B>
struct PairRef {
  const A& a;
  const Orientation& a_orientation;  // a circle's is not read
  const B& b;
  const Orientation& b_orientation;
};

template <class A, class B>
struct PairSource {
  const void* context;
  PairRef<A, B> (*pair)(const void* context, std::size_t k);
};

// overlapping[k] for the pairs k < overlapping.size(), A before B in kernel order (rectangle,
// circle, ellipse); every kind but two ellipses.
template <class A, class B>
void overlap_pairs(const PairSource<A, B>& pairs, std::span<std::uint8_t> overlapping);

}  // namespace collide2d::detail
