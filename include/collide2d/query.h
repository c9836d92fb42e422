/// @file
/// The narrow phase for two shapes of any kinds, in either order: overlap, distance, contact, and
/// the gap between boundary curves.
///
/// Every function here validates its shapes and throws InvalidShape (naming the field) for NaN,
/// infinity or a size out of range. Each pair runs the exact kernel of its kinds (kernels.h), two
/// shapes of one kind put in a fixed order first, so that swapping A and B swaps the result bit for
/// bit. Points and normals are in the world frame. docs/algorithms/README.md gives each kernel's method and
/// docs/accuracy.md the bounds the tests assert.
#pragma once

#include <collide2d/chain.h>
#include <collide2d/shapes.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <stdexcept>

namespace collide2d {

/// The distance between two solids A and B, in the order the query was given.
/// Apart: `distance` > 0 and point_a, point_b are closest points on the boundaries, |point_b -
/// point_a| = distance to rounding; a pair apart by less than its rounding still has a distance of
/// at least the smallest double, so that 0 always means overlapping. Overlapping (touching
/// included): distance 0 and point_a = point_b, a point of both solids.
struct DistanceResult {
  bool overlapping = false;
  double distance = 0.0;
  Vec2 point_a = Vec2::Zero();
  Vec2 point_b = Vec2::Zero();

  /// The same result for the query (B, A).
  DistanceResult swapped() const { return {overlapping, distance, point_b, point_a}; }

  /// An overlapping result with `witness` as the common point.
  static DistanceResult touching(const Vec2& witness) { return {true, 0.0, witness, witness}; }
  /// A result apart, its distance raised to the smallest double if it rounded to 0.
  static DistanceResult apart(double distance, const Vec2& a, const Vec2& b) {
    return {false, std::max(distance, std::numeric_limits<double>::denorm_min()), a, b};
  }
};

/// What a contact point of two rectangles is made of: the kind of contact and two indices, stable
/// while the same features touch (for warm-starting a solver). A rectangle's faces are numbered +x 0,
/// +y 1, -x 2, -y 3 in its own axes; its corners (-,-) 0, (+,-) 1, (+,+) 2, (-,+) 3. A point of an
/// incident face cut by a side plane of the reference face is corner 4 (at that face's lower end, in
/// the reference's axes) or 5. Curved contacts have id 0.
enum class FeatureKind : std::uint8_t {
  curved = 0,
  face_of_a = 1,      ///< first: A's reference face; second: B's corner (or cut point)
  face_of_b = 2,      ///< first: B's reference face; second: A's corner (or cut point)
  corner_corner = 3,  ///< first: A's corner; second: B's corner (rectangles apart, closest at corners)
};

/// The id of a contact point made of `kind`, `first` and `second`.
constexpr std::uint32_t feature_id(FeatureKind kind, int first, int second) {
  return static_cast<std::uint32_t>(kind) << 16 | static_cast<std::uint32_t>(first) << 8 |
         static_cast<std::uint32_t>(second);
}
/// The kind of a feature id.
constexpr FeatureKind feature_kind(std::uint32_t id) { return static_cast<FeatureKind>(id >> 16); }
/// The id of the same features for the pair (B, A).
// A face of A and a face of B trade kinds (1 and 2, the same two bits flipped); two corners trade
// places; a curved point has no features. Inline: every contact of a pair given in the other order
// renames its points' features.
constexpr std::uint32_t swapped_feature(std::uint32_t id) {
  switch (feature_kind(id)) {
    case FeatureKind::face_of_a:
    case FeatureKind::face_of_b:
      return id ^ 3u << 16;
    case FeatureKind::corner_corner:
      return (id & 0xffff0000u) | (id & 0xffu) << 8 | (id >> 8 & 0xffu);
    case FeatureKind::curved:
      break;
  }
  return id;
}

/// One point of a contact manifold.
struct ContactPoint {
  Vec2 point_a = Vec2::Zero();  ///< on A (for a manifold point: on A's face or A's corner)
  Vec2 point_b = Vec2::Zero();  ///< on B; point_b - point_a = separation * normal
  double separation = 0.0;
  std::uint32_t id = 0;  ///< feature_id() of the features that make it
};

/// The contact of two solids: their signed distance, the normal and the points.
///
/// separation = max over unit u of u.(c_B - c_A) - h_A(u) - h_B(-u) (h the support functions):
/// apart, the distance; overlapping, minus the penetration depth (the length of the shortest
/// translation of B that leaves the solids only touching); 0 when they touch; continuous through
/// contact. The normal is the maximiser. Where it is not unique (concentric shapes, symmetric
/// crossings, parallel faces) any maximiser is returned and the separation is exact all the same.
/// The sign of a separation within a few u of the pair's scale is rounding: overlaps() is the exact
/// verdict there.
struct Contact {
  double separation = 0.0;      ///< > 0 apart, < 0 overlapping (minus the depth)
  Vec2 normal = Vec2::UnitX();  ///< unit, from A to B: moving B by -separation * normal leaves them touching
  /// Apart: the closest points. Overlapping: the deepest points, A's support point along `normal`
  /// and B's along -normal (where a support set is a face, its point facing the other shape's
  /// deepest point). point_b - point_a = separation * normal. Where two rectangles' deepest corner
  /// lies beyond the reference face's ends, the incident face's deepest point within them stands in
  /// for it, so that both points stay on their shapes.
  Vec2 point_a = Vec2::Zero();
  Vec2 point_b = Vec2::Zero();
  /// The manifold: one point for curved pairs (the one above); for two rectangles the points of the
  /// incident face clipped to the reference face (Box2D's b2CollidePolygons), deepest first, each
  /// with its own separation (two for a face resting on a face). The reference face is A's deepest
  /// unless B's is deeper by more than 1e-9 of the sum of the half extents, so that ids hold where
  /// the faces tie; separation and normal stay the exact maximum. Empty (size 0) for a pair apart
  /// by more than ContactOptions::max_separation: see beyond().
  std::array<ContactPoint, 2> manifold{};
  int manifold_size = 1;
  int evaluations = 0;  ///< support evaluations of a curved pair's search (0 for closed forms)

  /// The manifold's points.
  std::span<const ContactPoint> points() const { return {manifold.data(), static_cast<std::size_t>(manifold_size)}; }
  /// Whether the pair lies beyond ContactOptions::max_separation (an empty manifold).
  bool empty() const { return manifold_size == 0; }
  /// The same contact for the pair (B, A).
  Contact swapped() const;
  /// A one-point contact.
  static Contact of(double separation, const Vec2& normal, const Vec2& point_a, const Vec2& point_b,
                    std::uint32_t id = 0);
  /// No contact: the solids are apart by more than the caller's max_separation. `separation` is a
  /// lower bound of their distance that shows it; the normal and the points are not computed and
  /// stay at their defaults. (A kernel that computes the whole contact anyway, as the closed forms
  /// do, returns it with an empty manifold instead: read nothing but the separation of an empty
  /// contact.)
  static Contact beyond(double lower_bound);
};

// Inline: a batch writes thousands of contacts, and a call out of line built each one and copied it.
inline Contact Contact::beyond(double lower_bound) {
  Contact c;
  c.separation = lower_bound;
  c.manifold_size = 0;
  return c;
}

inline Contact Contact::of(double separation, const Vec2& normal, const Vec2& point_a, const Vec2& point_b,
                           std::uint32_t id) {
  Contact c;
  c.separation = separation;
  c.normal = normal;
  c.point_a = point_a;
  c.point_b = point_b;
  c.manifold[0] = {point_a, point_b, separation, id};
  return c;
}

/// What a contact query may use beyond the two shapes.
struct ContactOptions {
  /// How far beyond the deepest point a manifold keeps points: 0 keeps only the touching.
  /// A rectangle pair's manifold keeps, beside the deepest point, the points whose separation is at
  /// most max(deepest, 0) + margin: 0 keeps the points touching or overlapping as deep; a speculative
  /// solver passes its margin.
  double margin = 0.0;
  /// A direction near the expected normal (last frame's): two ellipses start their search there
  /// and end sooner. Any direction gives the same contact to rounding; zero means none. Other pairs
  /// ignore it. Must be finite.
  Vec2 guess = Vec2::Zero();
  /// No contact for a pair apart by more than this: Contact::beyond, an empty manifold.
  /// As Box2D's manifold is empty beyond its margin. The kernels stop as soon as a lower bound of the
  /// separation shows it, and compute the rest only for the pairs within it. A lower bound must
  /// exceed the limit by 64 u of the pair's scale (more than its rounding), so that
  /// `contact(a, b, {.max_separation = m})` and `contact(a, b)` agree to the bit on every pair
  /// whose separation, as the query without a limit computes it, is at most m. Must not be NaN.
  double max_separation = std::numeric_limits<double>::infinity();
  /// How far the contact may lie from the exact one, in length units; 0 is the exact contact.
  /// A pair with an ellipse stops its iterations once the separation and both points are certified
  /// within it and the normal within tolerance / size rad (size: the larger reach_of); pairs without
  /// an ellipse ignore it. The verdict never changes: separation <= 0 exactly when overlaps() says
  /// so, and point_b - point_a = separation * normal still holds. Must be finite and not negative.
  double tolerance = 0.0;
};

/// Thrown for a query the pair does not support (the boundary distance of a rectangle).
class UnsupportedPair : public std::logic_error {
 public:
  using std::logic_error::logic_error;
};

/// Whether the solids share a point (touching counts). Computes nothing beyond the verdict.
bool overlaps(const Shape& a, const Shape& b);
/// Whether the solid shape meets the closed box, which may have no width or height.
/// A box of no width or height is a segment or a point. Exact up to the rounding of the shape's
/// coordinates. Throws InvalidShape for an invalid box too.
bool overlaps(const Shape& shape, const Aabb& box);
/// The distance and closest points, or 0 and a common point when the solids overlap.
DistanceResult distance(const Shape& a, const Shape& b);
/// Circles and ellipses: the gap between the boundary curves (the solid distance for disjoint
/// shapes, the gap of a shape nested in another), or 0 and a common point when the curves meet.
/// Throws UnsupportedPair for a rectangle.
DistanceResult boundary_distance(const Shape& a, const Shape& b);
/// The signed distance, normal and points (see Contact). Throws std::invalid_argument for a guess
/// that is not finite.
Contact contact(const Shape& a, const Shape& b, const ContactOptions& options = {});

/// The contact of the chain segment A with the shape B, under the rules of chain.h; an
/// empty contact (Contact::empty(), its separation infinite) where the rules give none. Validates
/// as contact() does; throws UnsupportedPair for a segment B (level geometry never pairs).
Contact contact(const ChainSegment& a, const Shape& b, const ContactOptions& options = {});
/// The same, given each shape's Orientation::of(angle); nothing is validated.
Contact contact(const ChainSegment& a, const Orientation& a_orientation, const Shape& b,
                const Orientation& b_orientation, const ContactOptions& options = {});

}  // namespace collide2d
