// Private: the order in which kernels take their shapes: by rank across kinds (a rectangle, a
// polygon, a capsule, a segment, a circle, an ellipse), and by key within one.
//
// The key is a total order on shapes of one kind (precedes()). Same-kind pairs are put in this order
// before the kernel runs (query.cpp, and the batch in overlap_batch.cpp), so that swapping A and B
// swaps the result exactly, bit for bit, whatever frame the kernel uses.
#pragma once

#include <collide2d/shapes.h>

#include <array>
#include <type_traits>

namespace collide2d::detail {

template <class T>
constexpr int rank() {
  if constexpr (std::is_same_v<T, Rect>) return 0;
  if constexpr (std::is_same_v<T, ConvexPolygon>) return 1;
  if constexpr (std::is_same_v<T, Capsule>) return 2;
  if constexpr (std::is_same_v<T, Segment>) return 3;
  if constexpr (std::is_same_v<T, Circle>) return 4;
  return 5;
}

template <class T>
constexpr bool one_of_first_kinds = std::is_same_v<T, Rect> || std::is_same_v<T, Circle> || std::is_same_v<T, Ellipse>;
// The kinds the kernels settle on convex cores (narrowphase/shared/cores/convex_core.h).
template <class T>
constexpr bool on_cores = std::is_same_v<T, ConvexPolygon> || std::is_same_v<T, Capsule> || std::is_same_v<T, Segment>;

// A polygon or a capsule (not a segment: level geometry, tested one pair at a time) with a circle or
// an ellipse.
template <class X, class Y>
constexpr bool core_with_round =
    on_cores<X> && !std::is_same_v<X, Segment> && (std::is_same_v<Y, Circle> || std::is_same_v<Y, Ellipse>);

// Whether the batched overlap tests (batch.h) take the pair of kinds, either way round: any two of
// rectangles, circles and ellipses, a polygon or a capsule with a circle or an ellipse, and two
// polygons. Other pairs are tested one at a time.
template <class X, class Y>
constexpr bool batched =
    (one_of_first_kinds<X> && one_of_first_kinds<Y>) || core_with_round<X, Y> || core_with_round<Y, X> ||
    (std::is_same_v<X, ConvexPolygon> && std::is_same_v<Y, ConvexPolygon>);

inline std::array<double, 3> key(const Circle& c) { return {c.center.x(), c.center.y(), c.radius}; }
inline std::array<double, 5> key(const Ellipse& e) { return {e.center.x(), e.center.y(), e.a, e.b, e.angle}; }
inline std::array<double, 5> key(const Rect& r) {
  return {r.center.x(), r.center.y(), r.half_extents.x(), r.half_extents.y(), r.angle};
}
inline std::array<double, 5> key(const Capsule& c) {
  return {c.center.x(), c.center.y(), c.half_length, c.radius, c.angle};
}
inline std::array<double, 5> key(const Segment& s) {
  return {s.center.x(), s.center.y(), s.end.x(), s.end.y(), s.angle};
}
// Whether x comes before y, the order the kernels take two shapes of one kind in.
template <class T>
bool precedes(const T& x, const T& y) {
  return key(x) < key(y);
}
// A polygon's pose, then its outline's radius, count and vertices (never its address, which would
// order a replay differently): the outline is read only where the poses tie, as copies of one
// polygon do.
inline bool precedes(const ConvexPolygon& p, const ConvexPolygon& q) {
  const auto pose = [](const ConvexPolygon& x) { return std::array<double, 3>{x.center.x(), x.center.y(), x.angle}; };
  if (pose(p) != pose(q)) return pose(p) < pose(q);
  const auto outline = [](const ConvexPolygon& x) {
    std::array<double, 2 + 2 * kMaxPolygonVertices> k{x.radius(), static_cast<double>(x.count())};
    for (int i = 0; i < x.count(); ++i) k[2 + 2 * i] = x.vertices()[i].x(), k[3 + 2 * i] = x.vertices()[i].y();
    return k;
  };
  return outline(p) < outline(q);
}

}  // namespace collide2d::detail
