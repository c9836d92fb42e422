/// @file
/// Where a ray first meets a solid shape: exact for circles and ellipses (the root of the ray's
/// quadratic against the curve, not a polygon), slabs for rectangles, the faces for polygons, and
/// the offset faces and the vertices' circles for rounded polygons and capsules.
#pragma once

#include <collide2d/chain.h>
#include <collide2d/shapes.h>

#include <optional>

namespace collide2d {

/// Where a ray meets a shape.
struct RayShapeHit {
  double distance = 0.0;  ///< t at the hit
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::Zero();  ///< outward unit normal at the hit; zero exactly when contains(shape, origin)
};

/// The first point of the shape on the ray origin + t direction, 0 <= t <= max_distance, or nullopt.
/// A ray that starts in the shape (contains(shape, origin)) hits it at t = 0. Contract: a valid shape, a finite origin,
/// a unit direction and max_distance >= 0; nothing is validated (World::ray_cast validates).
std::optional<RayShapeHit> ray_cast(const Shape& shape, const Vec2& origin, const Vec2& direction, double max_distance);

/// The ray's hit on the chain segment's front, or nullopt for a ray from behind its line.
/// A ray from behind passes through; else the segment's ray_cast(), with its contract.
std::optional<RayShapeHit> ray_cast(const ChainSegment& s, const Vec2& origin, const Vec2& direction,
                                    double max_distance);

}  // namespace collide2d
