// Private: the area queries on shapes already checked (solid, valid), for the batches, which check
// every shape before they answer any pair.
#pragma once

#include <collide2d/area.h>

namespace collide2d::detail::areas {

OverlapArea overlap_of(const Shape& a, const Shape& b);
double iou_of(const Shape& a, const Shape& b);

}  // namespace collide2d::detail::areas
