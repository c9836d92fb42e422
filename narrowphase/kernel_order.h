// Private: the order in which kernels take their shapes: by rank across kinds (a rectangle first,
// an ellipse last), and by key within one.
//
// The key is a total order on shapes of one kind. Same-kind pairs are put in this order before the
// kernel runs (query.cpp, and the batch in overlap_batch.cpp), so that swapping A and B swaps the
// result exactly, bit for bit, whatever frame the kernel uses.
#pragma once

#include <collide2d/shapes.h>

#include <array>
#include <type_traits>

namespace collide2d::detail {

template <class T>
constexpr int rank() {
  if constexpr (std::is_same_v<T, Rect>) return 0;
  if constexpr (std::is_same_v<T, Circle>) return 1;
  return 2;
}

inline std::array<double, 3> key(const Circle& c) { return {c.center.x(), c.center.y(), c.radius}; }
inline std::array<double, 5> key(const Ellipse& e) { return {e.center.x(), e.center.y(), e.a, e.b, e.angle}; }
inline std::array<double, 5> key(const Rect& r) {
  return {r.center.x(), r.center.y(), r.half_extents.x(), r.half_extents.y(), r.angle};
}

}  // namespace collide2d::detail
