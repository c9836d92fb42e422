// The Box2D 2.4.1 baseline: our shapes as Box2D shapes, ellipses as polygons.
//
// An ellipse becomes an N-gon: inscribed (vertices on the curve at N evenly spaced parameters) or
// circumscribed (the affine image of the regular N-gon around the unit circle, so it contains the
// ellipse). For convex shapes the true distance lies between the distance of the circumscribed
// approximations and that of the inscribed ones. Coordinates are taken relative to a common origin
// (the first shape's centre) before they are rounded to Box2D's float.
//
// Box2D gives every b2PolygonShape a skin of b2_polygonRadius (about 1 cm) and b2TestOverlap uses
// shape radii; the polygons built here have radius 0, so overlap means the polygons themselves meet,
// except a capsule's, a box rounded by its radius (Box2D 2.4.1 has no capsule; to_box2d says how
// near it comes).
#pragma once

#include <collide2d/shapes.h>
#include <collide2d/time_of_impact.h>

#include <box2d/b2_broad_phase.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_polygon_shape.h>
#include <box2d/b2_time_of_impact.h>

#include <cstdint>
#include <optional>
#include <span>
#include <unordered_set>
#include <vector>

namespace collide2d::baseline {

enum class Fit { inscribed, circumscribed };

// A shape as Box2D sees it: a vertex cloud and a radius (a circle is one vertex and its radius).
struct Polygon {
  std::vector<b2Vec2> vertices;
  float radius = 0.0f;
};

// A box in Box2D's float, rounded to nearest.
b2AABB to_box2d(const Aabb& box);

// A capsule's Box2D equivalent, a rounded box: its half width w (to_box2d).
inline constexpr double kCapsuleBoxHalfWidth = 0.003;

// `sides` applies to ellipses (any N >= 3); rectangles have 4 vertices and circles are exact; a
// capsule is a box of half extents (h + w, w) rounded by r - w, within 0.42 w = 0.0013 of it; a
// segment is its two points (a two-sided b2EdgeShape).
Polygon to_box2d(const Shape& shape, int sides, Fit fit, const Vec2& origin);

// b2Distance between the two polygons (their radii included), in double.
double box2d_distance(const Polygon& a, const Polygon& b);

// One shape as a b2PolygonShape with the polygon's radius (at most b2_maxPolygonVertices = 8
// vertices), a circle as a b2CircleShape, or a segment as a two-sided b2EdgeShape.
struct Box2dShape {
  b2PolygonShape polygon;
  b2CircleShape circle;
  b2EdgeShape edge;
  bool round = false;
  bool is_edge = false;
  const b2Shape* shape() const {
    if (is_edge) return &edge;
    return round ? static_cast<const b2Shape*>(&circle) : &polygon;
  }
};
Box2dShape to_box2d_shape(const Polygon& p);

// An open chain of points (the first and last ghosts only, as ours) as Box2D's b2ChainShape, points
// taken from `origin`: its child edges, one-sided with their ghost vertices (GetChildEdge), radius 0.
std::vector<Box2dShape> to_box2d_chain(std::span<const Vec2> points, const Vec2& origin);

// The same pair as Box2dShapes, and b2TestOverlap on them.
struct ShapePair {
  Box2dShape side[2];
  const b2Shape* shape(int i) const { return side[i].shape(); }
};
ShapePair to_box2d_shapes(const Polygon& a, const Polygon& b);
bool box2d_overlap(const ShapePair& pair);
// b2TestOverlap on every pair of the list, in one loop: Box2D's fastest way through a list of
// pairs, the rival of collide2d's batches. overlapping[i] is 1 or 0.
void box2d_overlaps(std::span<const ShapePair> pairs, std::span<std::uint8_t> overlapping);

// Box2D's contact manifold for the pair: b2CollidePolygons, b2CollidePolygonAndCircle,
// b2CollideCircles, b2CollideEdgeAndPolygon or b2CollideEdgeAndCircle by kind (a circle first is
// passed second, and an edge second first, so the manifold is then B's against A's). With radius-0
// polygons Box2D keeps only points that overlap or touch.
void box2d_manifold(const ShapePair& pair, b2Manifold* manifold);
// box2d_manifold on every pair of the list, in one loop (the rival of the batched contacts).
void box2d_manifolds(std::span<const ShapePair> pairs, std::span<b2Manifold> manifolds);

// The manifold read through b2WorldManifold: its least point separation (the signed distance
// along its normal), the normal from A to B, and that point (midway between the two surfaces, in
// the polygons' frame); nullopt when it has no point.
struct Box2dContact {
  double separation;
  Vec2 normal;
  Vec2 point;
};
std::optional<Box2dContact> box2d_contact(const ShapePair& pair);

// b2TimeOfImpact's shapes and sweeps for two shapes moving over one step: each an N-gon (a circle a
// point with its radius) in its own frame, swept by a b2Sweep from its pose at t = 0 by its motion,
// centres relative to A's start.
struct ToiPair {
  Polygon a;
  Polygon b;
  b2Sweep sweep_a;
  b2Sweep sweep_b;
};
ToiPair to_box2d_toi(const Shape& a, const Motion& ma, const Shape& b, const Motion& mb, int sides, Fit fit);
// b2TimeOfImpact on the pair (tMax 1; the proxies are set per call, a few stores); out->t is in [0, 1].
void box2d_time_of_impact(const ToiPair& pair, b2TOIOutput* out);

// Box2D's dynamic-tree broad phase, driven the way b2World drives it: MoveProxy for every moved
// box (Box2D fattens by b2_aabbMargin = 0.1, and predicts along the displacement), UpdatePairs to
// collect the new pairs, and, as b2ContactManager::Collide does, a TestOverlap on every known pair
// to drop those whose fat boxes parted. The result is the current pair set the sweep and prune
// keeps. Boxes are numbered 0, 1, ... in insertion order.
class Box2dBroadPhase {
 public:
  explicit Box2dBroadPhase(double = 0.0) {}
  std::vector<std::uint32_t> insert_batch(const std::vector<Aabb>& boxes);
  void move(std::uint32_t id, const Aabb& box) { move(id, to_box2d(box)); }
  void move(std::uint32_t id, const b2AABB& box);
  void update();
  void AddPair(void* a, void* b);  // called by b2BroadPhase::UpdatePairs
  std::size_t pair_count() const { return pairs_.size(); }
  // Each pair as first << 32 | second, first < second, in no order.
  const std::unordered_set<std::uint64_t>& pairs() const { return pairs_; }

 private:
  b2BroadPhase tree_;
  std::vector<int32> proxy_;
  std::vector<b2Vec2> centre_;
  std::unordered_set<std::uint64_t> pairs_;
};

}  // namespace collide2d::baseline
