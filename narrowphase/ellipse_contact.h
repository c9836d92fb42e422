// Private: the overlap decision for two ellipses with what it found on the way, shared by the
// overlap test and the distance queries.
#pragma once

#include "narrowphase/overlap_rect_ellipse.h"  // FilterVerdict
#include "shapes/shapes.h"

namespace collide2d::detail {

struct EllipseContact {
  bool overlap = false;
  Vec2 direction = Vec2::UnitX();  // separated: a direction n (A towards B) with s(n) > 0
  Vec2 witness = Vec2::Zero();     // overlap: a world point in both shapes (to rounding)
  int iterations = 0;              // GJK support evaluations, both precisions
};

// With `double_verdict`, stops after the double pass and stores its verdict there (`uncertain` when
// it could not decide; the returned contact is then only a guess).
EllipseContact ellipse_contact(const Ellipse& a, const Ellipse& b, FilterVerdict* double_verdict = nullptr);

}  // namespace collide2d::detail
