// Box2D v3's contacts for the speed-against-error report (bench/report.cpp), behind a header free of
// Box2D's types: the report also races 2.4.1, whose headers share v3's type names.
#pragma once

#include <collide2d/shapes.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace collide2d::box2d_v3 {

// A manifold's deepest point: its separation, the normal from the first shape to the second, and
// the point (midway between the surfaces).
struct Deepest {
  double separation;
  Vec2 normal;
  Vec2 point;
};

// v3's manifold of a[k] and b[k] as a function of k, none where it has no points; each ellipse is its
// inscribed polygon of `sides` (3 to 8) vertices, and the shapes are posed as v3's once, here
// (bench/box2d_v3/shapes.h).
// Defined for A = Rect, Circle, Ellipse, ConvexPolygon, Capsule, Segment.
using Manifolds = std::function<std::optional<Deepest>(std::size_t)>;
template <class A>
Manifolds manifolds(const std::vector<A>& a, const std::vector<Ellipse>& b, int sides);

}  // namespace collide2d::box2d_v3
