// Private: the order in which kernels take two shapes of one kind (across kinds, their rank in
// shapes/kinds.h decides): by key, a total order on the shapes of a kind (precedes()). Same-kind
// pairs are put in this order before the kernel runs (dispatch.h, and the batch in
// overlap_pairs.h), so that swapping A and B swaps the result exactly, bit for bit, whatever frame
// the kernel uses.
#pragma once

#include <collide2d/shapes.h>

#include <array>
#include <type_traits>

namespace collide2d::detail {

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
