// A rival for rotated-box IoU in plain double, written from the method detectron2 publishes for
// pairwise_iou_rotated (and mmcv for box_iou_rotated): both boxes moved so that the midpoint of
// their centres is the origin; their corners; the points where the 16 pairs of edges cross and the
// corners of each box inside the other, each test with a fixed epsilon; the convex hull of those
// points by Graham's scan ("An efficient algorithm for determining the convex hull of a finite
// planar set", 1972); its area by a fan; IoU = overlap / (area a + area b - overlap). The benchmarks
// race it and the accuracy tests measure it on the hard families.
#pragma once

#include <collide2d/shapes.h>

namespace collide2d::baselines {

double rotated_box_iou(const Rect& a, const Rect& b);

}  // namespace collide2d::baselines
