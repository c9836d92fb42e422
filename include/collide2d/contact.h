// Contacts: how far apart two solid shapes are, or how deep they overlap, along which normal, and
// where; exact for every pair of collide2d's shapes (no polygon stands in for a curve).
//
// The signed distance of convex solids A and B is
//   separation = max over unit u of  u.(c_B - c_A) - h_A(u) - h_B(-u)      (h the support function)
// for pairs apart and overlapping alike: apart, the distance; overlapping, minus the penetration
// depth (the length of the shortest translation of B that leaves the solids only touching); 0 when
// they touch. It is continuous through contact. The maximiser is the normal. Two ellipses find the
// global maximum by a climb that a bound over every direction certifies, else by branch and bound
// over arcs of directions (narrowphase/deepest_direction.h says why no local maximum can pass for
// it); a rectangle and an ellipse by settling each quarter turn between the rectangle's face normals
// in closed form (narrowphase/contact_rect_ellipse.cpp); rectangle pairs by their face normals.
//
// Where the maximiser is not unique (concentric shapes, symmetric crossings, a rectangle's face
// against a parallel face) any maximiser is a correct normal, and the separation is exact all the
// same. The sign of a separation within a few u of the pair's scale (|c_B - c_A| + both sizes) is
// rounding: overlaps() is the exact verdict there.
#pragma once

#include <collide2d/shapes.h>

#include <array>
#include <cstdint>
#include <span>

namespace collide2d {

// Feature ids of rectangle–rectangle contact points: the kind of contact and two indices, stable
// while the same features touch, for warm-starting a solver. Faces of a rectangle are numbered
// +x 0, +y 1, -x 2, -y 3 in its own axes, corners (-,-) 0, (+,-) 1, (+,+) 2, (-,+) 3; a point of an
// incident face cut by a side plane of the reference face is 4 (at that face's lower end, in the
// reference's axes) or 5. Curved contacts have id 0.
enum class FeatureKind : std::uint8_t {
  curved = 0,
  face_of_a = 1,      // first: A's reference face; second: B's corner (or cut point)
  face_of_b = 2,      // first: B's reference face; second: A's corner (or cut point)
  corner_corner = 3,  // first: A's corner; second: B's corner (rectangles apart, closest at corners)
};

constexpr std::uint32_t feature_id(FeatureKind kind, int first, int second) {
  return static_cast<std::uint32_t>(kind) << 16 | static_cast<std::uint32_t>(first) << 8 |
         static_cast<std::uint32_t>(second);
}
constexpr FeatureKind feature_kind(std::uint32_t id) { return static_cast<FeatureKind>(id >> 16); }
// The id of the same features for the pair (B, A).
std::uint32_t swapped_feature(std::uint32_t id);

struct ContactPoint {
  Vec2 point_a = Vec2::Zero();  // on A (for a manifold point: on A's face or A's corner)
  Vec2 point_b = Vec2::Zero();  // on B; point_b - point_a = separation * normal
  double separation = 0.0;
  std::uint32_t id = 0;
};

struct Contact {
  double separation = 0.0;           // signed distance: > 0 apart, < 0 overlapping (minus the depth)
  Vec2 normal = Vec2::UnitX();       // unit, from A to B: moving B by -separation * normal leaves them touching
  // Apart: the closest points. Overlapping: the deepest points, the support point of A along
  // `normal` and of B along -normal (where a support set is a whole face, the point of it facing the
  // other shape's deepest point). point_b - point_a = separation * normal. One exception keeps both
  // points on their shapes: where two rectangles' deepest corner lies beyond the reference face's
  // ends, the incident face's deepest point within them stands in for it.
  Vec2 point_a = Vec2::Zero();
  Vec2 point_b = Vec2::Zero();
  // The manifold a solver stacks with: one point for curved pairs (the one above); for two
  // rectangles the points of the incident face clipped to the reference face (Box2D's
  // b2CollidePolygons), deepest first, each with its own separation (two for a face resting on a
  // face).
  std::array<ContactPoint, 2> manifold{};
  int manifold_size = 1;
  int evaluations = 0;     // support evaluations of the curved search (0 for closed forms)

  std::span<const ContactPoint> points() const { return {manifold.data(), static_cast<std::size_t>(manifold_size)}; }
  // The same contact for the pair (B, A).
  Contact swapped() const;
  // The single-point contact from the signed distance, normal, the two points and their feature id.
  static Contact of(double separation, const Vec2& normal, const Vec2& point_a, const Vec2& point_b,
                    std::uint32_t id = 0);
};

// Inline: a batch writes thousands of contacts, and each call out of line built the contact and
// copied it again.
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

struct ContactOptions {
  // Rectangle manifolds keep, beside the deepest point, the points whose separation is at most
  // max(deepest, 0) + margin: 0 keeps the points touching or overlapping as deep; a speculative
  // solver passes its margin.
  double margin = 0.0;
  // A direction near the normal expected (the last frame's, or the last step's of a time of
  // impact): the search of two ellipses starts its climb there instead of on the line of centres,
  // and ends sooner. Any direction gives the same answer up to rounding; zero: none. Other pairs
  // need no start and ignore it.
  Vec2 guess = Vec2::Zero();
};

// The typed kernels, shapes in the dispatch order of query.h. They assume valid shapes. Each has
// an overload taking the orientations (Orientation::of(angle)) the caller keeps, as Box2D keeps
// b2Rot: it skips the cosines and sines, and returns the same result bit for bit.
Contact contact_circle_circle(const Circle& a, const Circle& b);
Contact contact_rect_circle(const Rect& a, const Circle& b);
Contact contact_rect_circle(const Rect& a, const Orientation& a_orientation, const Circle& b);
Contact contact_rect_rect(const Rect& a, const Rect& b, const ContactOptions& options = {});
Contact contact_rect_rect(const Rect& a, const Orientation& a_orientation, const Rect& b,
                          const Orientation& b_orientation, const ContactOptions& options = {});
Contact contact_rect_ellipse(const Rect& a, const Ellipse& b, const ContactOptions& options = {});
Contact contact_rect_ellipse(const Rect& a, const Orientation& a_orientation, const Ellipse& b,
                             const Orientation& b_orientation, const ContactOptions& options = {});
Contact contact_circle_ellipse(const Circle& a, const Ellipse& b);
Contact contact_circle_ellipse(const Circle& a, const Ellipse& b, const Orientation& b_orientation);
// Batched, for callers with their own pair lists: contacts[i] is bit for bit
// contact_circle_ellipse(circles[i], ellipses[i], ellipse_orientations[i]). The point–ellipse roots
// of 2 to 8 pairs run side by side in SIMD lanes (Google Highway, chosen at run time for the CPU),
// each lane stopping where the one-off root stops; the axis cases go one by one to their closed
// forms. Like the posed one-off kernels it neither validates the shapes nor takes sines and
// cosines (overlap_batch.h says the same). Lists of different lengths throw std::invalid_argument,
// naming the lengths, before anything is written.
void contact_circle_ellipse(std::span<const Circle> circles, std::span<const Ellipse> ellipses,
                            std::span<const Orientation> ellipse_orientations, std::span<Contact> contacts);
Contact contact_ellipse_ellipse(const Ellipse& a, const Ellipse& b, const ContactOptions& options = {});
Contact contact_ellipse_ellipse(const Ellipse& a, const Orientation& a_orientation, const Ellipse& b,
                                const Orientation& b_orientation, const ContactOptions& options = {});

}  // namespace collide2d
