// collide2d's shapes as Box2D v3's, as a game's bodies hold them: each shape in its own frame, placed
// by a float transform. A circle about its centre; a capsule along its x axis; a rectangle as
// b2MakeBox; a convex polygon through b2ComputeHull and b2MakePolygon with its radius; an ellipse as
// the polygon inscribed in it, vertices at 8 (or 5 to 7) evenly spaced parameters (v3's polygons
// have at most 8); a segment and a chain segment from their first point.
//
// Box2D 2.4.1's headers share v3's type names (b2Vec2, b2Manifold): a file that includes this one
// includes no header of 2.4.1's (bench/box2d_baseline.h).
#pragma once

#include <collide2d/chain.h>
#include <collide2d/shapes.h>

#include <box2d/collision.h>
#include <box2d/math_functions.h>

#include <array>
#include <cstddef>
#include <numbers>
#include <span>

namespace collide2d::box2d_v3 {

template <class T>
struct Posed {
  T shape;
  b2Transform transform;
};

inline b2Vec2 to_float(const Vec2& p) { return {static_cast<float>(p.x()), static_cast<float>(p.y())}; }

inline b2Transform transform_of(const Vec2& position, double angle) {
  const Orientation o = Orientation::of(angle);
  return {to_float(position), {static_cast<float>(o.c), static_cast<float>(o.s)}};
}

inline Posed<b2Circle> posed(const Circle& c) {
  return {{{0.0f, 0.0f}, static_cast<float>(c.radius)}, transform_of(c.center, 0.0)};
}

inline Posed<b2Capsule> posed(const Capsule& c) {
  const auto h = static_cast<float>(c.half_length);
  return {{{-h, 0.0f}, {h, 0.0f}, static_cast<float>(c.radius)}, transform_of(c.center, c.angle)};
}

inline Posed<b2Polygon> posed(const Rect& r) {
  return {b2MakeBox(static_cast<float>(r.half_extents.x()), static_cast<float>(r.half_extents.y())),
          transform_of(r.center, r.angle)};
}

// v3's polygon of the points' hull. b2ComputeHull welds points within 4 linear slops (2 cm) and
// drops points within 2 slops of a line, tuned for shapes 0.1 to 10 m across: at the workloads'
// sizes (0.05 to 1, ellipses of aspect up to 10) it would take vertices from a quarter of the
// ellipses' 8-gons and leave some with no hull. The hull is made at 16 times the size and the
// polygon scaled back, by a power of two, so exactly: v3 meets the polygon collide2d is raced on.
inline b2Polygon polygon_of(std::span<const b2Vec2> points, double radius) {
  constexpr float kUp = 16.0f;
  std::array<b2Vec2, B2_MAX_POLYGON_VERTICES> up;
  for (std::size_t k = 0; k < points.size(); ++k) up[k] = b2MulSV(kUp, points[k]);
  const b2Hull hull = b2ComputeHull(up.data(), static_cast<int>(points.size()));
  b2Polygon p = b2MakePolygon(&hull, kUp * static_cast<float>(radius));
  for (int k = 0; k < p.count; ++k) p.vertices[k] = b2MulSV(1.0f / kUp, p.vertices[k]);
  p.centroid = b2MulSV(1.0f / kUp, p.centroid);
  p.radius /= kUp;
  return p;
}

inline Posed<b2Polygon> posed(const ConvexPolygon& p) {
  std::array<b2Vec2, kMaxPolygonVertices> points;
  const std::span<const Vec2> vertices = p.vertices();
  for (std::size_t k = 0; k < vertices.size(); ++k) points[k] = to_float(vertices[k]);
  return {polygon_of(std::span(points).first(vertices.size()), p.radius()), transform_of(p.center, p.angle)};
}

// The ellipse's inscribed polygon of `sides` vertices (3 to 8).
inline Posed<b2Polygon> posed(const Ellipse& e, int sides = 8) {
  std::array<b2Vec2, 8> points;
  for (int k = 0; k < sides; ++k) {
    const Orientation o = Orientation::of(2 * k * std::numbers::pi / sides);
    points[static_cast<std::size_t>(k)] = to_float(Vec2(e.a * o.c, e.b * o.s));
  }
  return {polygon_of(std::span(points).first(static_cast<std::size_t>(sides)), 0.0), transform_of(e.center, e.angle)};
}

inline Posed<b2Segment> posed(const Segment& s) {
  return {{{0.0f, 0.0f}, to_float(s.end)}, transform_of(s.center, s.angle)};
}

inline Posed<b2ChainSegment> posed(const ChainSegment& c) {
  return {{to_float(c.ghost1), {{0.0f, 0.0f}, to_float(c.segment.end)}, to_float(c.ghost2), 0},
          transform_of(c.segment.center, c.segment.angle)};
}

}  // namespace collide2d::box2d_v3
