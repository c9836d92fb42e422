// Private: boxes kept in float, rounded outward, so that each holds the double box it was made from:
// the trees' nodes, and the World's look-up boxes.
#pragma once

#include <collide2d/shapes.h>

#include "shapes/bits.h"

#include <cstdint>
#include <limits>

namespace collide2d::detail {

// The next float up (or down) from a finite f; std::nextafter, but inline: boxes are stored at every
// update, and a library call each would be a noticeable part of a frame.
inline float float_step(float f, bool up) {
  if (f == 0.0f) return up ? std::numeric_limits<float>::denorm_min() : -std::numeric_limits<float>::denorm_min();
  const auto bits = bit_copy<std::uint32_t>(f);
  return bit_copy<float>((f > 0.0f) == up ? bits + 1 : bits - 1);
}

// A float at or below x (at or above, for up), one more step out, so that a box rounded so holds
// the double box however its users round; past float's range, the largest float or infinity.
inline float outward(double x, bool up) {
  constexpr float kMax = std::numeric_limits<float>::max();
  constexpr float kInf = std::numeric_limits<float>::infinity();
  if (x > kMax) return up ? kInf : kMax;
  if (x < -kMax) return up ? -kMax : -kInf;
  float f = static_cast<float>(x);
  if (up ? f < x : f > x) f = float_step(f, up);
  return float_step(f, up);
}

struct FloatBox {
  float lo[2];
  float hi[2];
};

inline FloatBox outward(const Aabb& box) {
  return {{outward(box.min.x(), false), outward(box.min.y(), false)},
          {outward(box.max.x(), true), outward(box.max.y(), true)}};
}

inline Aabb as_aabb(const FloatBox& box) { return {Vec2(box.lo[0], box.lo[1]), Vec2(box.hi[0], box.hi[1])}; }

}  // namespace collide2d::detail
