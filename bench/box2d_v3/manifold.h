// Box2D v3's manifold of any pair of collide2d's shapes posed as v3's (bench/box2d_v3/shapes.h), in
// world coordinates: the manifold function of the pair's kinds, called with the shapes in the order
// it takes them (as v3's World orders a contact's shapes), its normal turned to point from the first
// shape given to the second. Shared by bench_contact's race and the report's v3 rows.
#pragma once

#include "bench/box2d_v3/shapes.h"

#include <box2d/collision.h>
#include <box2d/math_functions.h>

#include <cstddef>
#include <type_traits>
#include <vector>

namespace collide2d::box2d_v3 {

// v3's manifold function of each order of shapes it takes (none where it takes the other order).
template <class A, class B>
constexpr std::nullptr_t kManifold = nullptr;
template <>
constexpr auto kManifold<b2Circle, b2Circle> = b2CollideCircles;
template <>
constexpr auto kManifold<b2Capsule, b2Circle> = b2CollideCapsuleAndCircle;
template <>
constexpr auto kManifold<b2Segment, b2Circle> = b2CollideSegmentAndCircle;
template <>
constexpr auto kManifold<b2Polygon, b2Circle> = b2CollidePolygonAndCircle;
template <>
constexpr auto kManifold<b2Capsule, b2Capsule> = b2CollideCapsules;
template <>
constexpr auto kManifold<b2Segment, b2Capsule> = b2CollideSegmentAndCapsule;
template <>
constexpr auto kManifold<b2Polygon, b2Capsule> = b2CollidePolygonAndCapsule;
template <>
constexpr auto kManifold<b2Polygon, b2Polygon> = b2CollidePolygons;
template <>
constexpr auto kManifold<b2Segment, b2Polygon> = b2CollideSegmentAndPolygon;
template <>
constexpr auto kManifold<b2ChainSegment, b2Circle> = b2CollideChainSegmentAndCircle;
template <>
constexpr auto kManifold<b2ChainSegment, b2Capsule> = b2CollideChainSegmentAndCapsule;
template <>
constexpr auto kManifold<b2ChainSegment, b2Polygon> = b2CollideChainSegmentAndPolygon;

template <class A, class B>
constexpr bool kTakesInOrder = !std::is_null_pointer_v<std::remove_const_t<decltype(kManifold<A, B>)>>;

// The manifold of a pair v3 takes in this order; a chain segment's simplex cache starts empty.
template <class A, class B>
b2LocalManifold collide(const A& a, const B& b, b2Transform xf) {
  if constexpr (std::is_invocable_v<decltype(kManifold<A, B>), const A*, const B*, b2Transform, b2SimplexCache*>) {
    b2SimplexCache cache{};
    return kManifold<A, B>(&a, &b, xf, &cache);
  } else {
    return kManifold<A, B>(&a, &b, xf);
  }
}

// What collide2d's contact returns, in v3's float: the normal, the manifold's points in world
// coordinates and their separations.
struct WorldManifold {
  b2Vec2 normal;
  b2Vec2 points[2];
  float separations[2];
  int count;
};

template <class A, class B>
WorldManifold world_manifold(const Posed<A>& a, const Posed<B>& b) {
  const b2LocalManifold local = collide(a.shape, b.shape, b2InvMulTransforms(a.transform, b.transform));
  WorldManifold out;
  out.normal = b2RotateVector(a.transform.q, local.normal);
  out.count = local.pointCount;
  for (int i = 0; i < local.pointCount; ++i) {
    out.points[i] = b2TransformPoint(a.transform, local.points[i].point);
    out.separations[i] = local.points[i].separation;
  }
  return out;
}

// Each shape as v3's, an ellipse as its inscribed polygon of `sides` vertices.
template <class S>
auto posed_shapes(const std::vector<S>& shapes, int sides = 8) {
  std::vector<decltype(posed(shapes[0]))> out;
  for (const S& s : shapes) {
    if constexpr (std::is_same_v<S, Ellipse>) {
      out.push_back(posed(s, sides));
    } else {
      out.push_back(posed(s));
    }
  }
  return out;
}

// The manifold of a and b whichever order v3 takes them in, its normal from a to b.
template <class A, class B>
WorldManifold manifold(const Posed<A>& a, const Posed<B>& b) {
  if constexpr (kTakesInOrder<A, B>) {
    return world_manifold(a, b);
  } else {
    WorldManifold out = world_manifold(b, a);
    out.normal = b2Neg(out.normal);
    return out;
  }
}

}  // namespace collide2d::box2d_v3
