// The mover's cast of one pair (mover_cast.cpp), for World::cast_mover() and cast_mover().
#pragma once

#include <collide2d/shapes.h>

namespace collide2d::detail {

// What the mover's floor lies below the smaller of its initial separation and the skin: 1e-12 of
// the larger of its reach and its centre's magnitude, above the rounding of its pose.
double mover_floor_hair(const Shape& mover);

// The first fraction of `translation`, at most `reach`, at which the mover's separation from the
// target falls to its floor (cast_mover() in mover.h), with each shape's kept orientation; `reach`
// where it does not. Nothing is validated.
double mover_cast(const Shape& mover, const Orientation& mover_orientation, const Vec2& translation,
                  const Shape& target, const Orientation& target_orientation, double skin, double reach);

}  // namespace collide2d::detail
