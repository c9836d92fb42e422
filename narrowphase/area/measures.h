// Private: the area queries on shapes already checked (solid, valid), for the batches, which check
// every shape before they answer any pair.
#pragma once

#include <collide2d/area.h>

namespace collide2d::detail::areas {

OverlapArea overlap_of(const Shape& a, const Shape& b);
double iou_of(const Shape& a, const Shape& b);

// The IoU of two rectangles in rank order (shapes/kinds.h's precedes()), given the area
// rect_rect_area() finds for them (narrowphase/area/overlap_rect_rect.h): a sliver is taken again in
// double-double.
double rect_iou(const Rect& a, const Rect& b, double area);

}  // namespace collide2d::detail::areas
