// Private: pairs as lanes. The lane-generic kernels (the *-inl.h files) are written with the names
// Highway gives its operations; the overloads below give the same names to double values and bool
// masks (one pair, a lane of width one), found by ordinary lookup, while Highway's own are found on
// its vector types by argument-dependent lookup. One template then serves the one-off kernel and
// the batch (overlap_batch.cpp), with the same IEEE operations in the same order. The inputs of
// each kernel, one field per lane, are plain structs here, shared by both.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace collide2d::detail {

struct Scalar {};
inline double Set(Scalar, double x) { return x; }
inline double Abs(double x) { return std::abs(x); }
inline double Max(double x, double y) { return std::max(x, y); }
inline double Min(double x, double y) { return std::min(x, y); }
inline double Sqrt(double x) { return std::sqrt(x); }
inline double Neg(double x) { return -x; }
inline bool And(bool x, bool y) { return x && y; }
inline bool Or(bool x, bool y) { return x || y; }
inline bool AndNot(bool not_x, bool y) { return !not_x && y; }
inline bool AllTrue(Scalar, bool m) { return m; }
inline bool Not(bool m) { return !m; }

// Per lane: certainly separated, certainly overlapping, or neither (uncertain: the exact fallback).
template <class M>
struct LaneVerdicts {
  M separated;
  M overlap;
};

// A rectangle–ellipse pair in the rectangle's frame (RectEllipseFrame's fields).
template <class V>
struct RectEllipseLanes {
  V x0, x1;  // ellipse centre
  V e0, e1;  // rectangle half extents
  V c, s;    // ellipse a-axis direction
  V a, b;    // ellipse semi-axes

  static constexpr std::size_t kFields = 8;
  std::array<V, kFields> fields() const { return {x0, x1, e0, e1, c, s, a, b}; }  // in declaration order
};

// A rectangle pair: B seen from A's frame (RectPairFrame), and both rectangles' half extents.
template <class V>
struct RectRectLanes {
  V tx, ty;  // B's centre
  V c, s;    // B's orientation
  V ax, ay;  // A's half extents
  V bx, by;  // B's half extents

  static constexpr std::size_t kFields = 8;
  std::array<V, kFields> fields() const { return {tx, ty, c, s, ax, ay, bx, by}; }  // in declaration order
};

}  // namespace collide2d::detail
