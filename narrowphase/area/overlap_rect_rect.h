// Private: the area of two rectangles' overlap in double, for IoU, which needs neither the centroid
// nor the crossings.
#pragma once

#include <collide2d/shapes.h>

#include "narrowphase/batch/batch_chunk.h"

#include <cstddef>

namespace collide2d::detail::areas {

// The area of A ∩ B to a few eps of the larger rectangle's area; 0 or below where they are apart or
// touch. The callers take a small result again in double-double.
double rect_rect_area(const Rect& a, const Rect& b);

// The same for the chunk's first `count` pairs, its fields those of RectRectLanes
// (narrowphase/shared/lanes.h), into out[0 ... count - 1]: in vectors, each lane's operations
// those of the one-off kernel.
void rect_rect_areas(Chunk<8>& chunk, std::size_t count, double* out);

}  // namespace collide2d::detail::areas
