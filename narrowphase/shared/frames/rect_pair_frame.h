// Private: rectangle B seen from rectangle A's frame.
#pragma once

#include <collide2d/shapes.h>
#include "narrowphase/shared/lanes.h"
#include "shapes/internal.h"

namespace collide2d::detail {

struct RectPairFrame {
  Rotation<double> a_rot;  // A's orientation in the world
  Rotation<double> b_rel;  // B's orientation in A's frame
  Vec2 b_center;           // B's centre in A's frame

  RectPairFrame(const Rect& a, const Rect& b)
      : RectPairFrame(a, Rotation<double>::of(a.angle), b, Rotation<double>::of(b.angle)) {}
  // With each rectangle's orientation given (the cosine and sine of its angle).
  RectPairFrame(const Rect& a, const Rotation<double>& ra, const Rect& b, const Rotation<double>& rb)
      : a_rot(ra), b_rel(rb.relative_to(ra)), b_center(ra.apply_inverse(Vec2(b.center - a.center))) {}
};

// The overlap test's inputs (overlap_rect_rect-inl.h) for one pair.
inline RectRectLanes<double> rect_rect_lanes(const Rect& a, const Orientation& ao, const Rect& b,
                                             const Orientation& bo) {
  const RectPairFrame f(a, Rotation<double>::of(ao), b, Rotation<double>::of(bo));
  return {f.b_center.x(),     f.b_center.y(),     f.b_rel.c,          f.b_rel.s,
          a.half_extents.x(), a.half_extents.y(), b.half_extents.x(), b.half_extents.y()};
}

}  // namespace collide2d::detail
