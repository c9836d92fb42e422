// Private: a point in a box's own frame, and the box point nearest to it.
#pragma once

#include <collide2d/shapes.h>

namespace collide2d::detail {

inline Vec2 clamp_to_box(const Vec2& p, const Vec2& half) { return p.cwiseMax(-half).cwiseMin(half); }

}  // namespace collide2d::detail
