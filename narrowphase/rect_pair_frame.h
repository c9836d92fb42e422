// Private: rectangle B seen from rectangle A's frame.
#pragma once

#include "shapes/rotation.h"
#include "shapes/shapes.h"

namespace collide2d::detail {

struct RectPairFrame {
  Rotation<double> a_rot;   // A's orientation in the world
  Rotation<double> b_rel;   // B's orientation in A's frame
  Vec2 b_center;            // B's centre in A's frame

  RectPairFrame(const Rect& a, const Rect& b)
      : a_rot(Rotation<double>::of(a.angle)),
        b_rel(Rotation<double>::of(b.angle).relative_to(a_rot)),
        b_center(a_rot.apply_inverse(Vec2(b.center - a.center))) {}
};

}  // namespace collide2d::detail
