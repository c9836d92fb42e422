// Private: the core shapes as rounded convex cores, the method that settles the pairs of them that
// have no kernel of their own, and the one that settles such a shape against an ellipse.
//
// A rectangle, a convex polygon, a capsule and a circle are each a convex core (a polygon of 3 to 8
// vertices, a segment of 2, or a point) grown by a radius (0 for the sharp polygons). Every pair
// of them is settled on the two cores, B's placed in A's frame:
// - separating axes (the faces' normals of both cores; a segment also its own direction, the end
//   faces its Minkowski sums with a point or a parallel segment have) give the cores' signed
//   distance wherever they overlap, the deepest way out being along one of those axes, and a lower
//   bound of their distance where they do not;
// - apart, that bound is the distance when the best face's witness vertex lies over the face (a
//   point of the face is then that far from it), and otherwise the nearest features are found among
//   every vertex–edge pair (a closest pair of two disjoint convex polygons always has a vertex);
// - a rounded pair's signed distance is its cores' minus the two radii, along the same normal.
// The manifold is Box2D's (E. Catto, b2ClipPolygons): the incident face, the other core's face most
// opposed to the reference face, clipped to the reference face's side planes.
//
// Against an ellipse, the separation along a direction u is, wherever A's support point is its
// vertex v (the cone of directions between the normals of v's two faces), the separation of the
// point v and the ellipse along u, less A's radius. Its maxima over the cone are at the cone's ends
// (face normals, where the ellipse's support point lies over the face) or at a normal of the
// ellipse through v inside the cone: the point's nearest foot on the ellipse (Eberly's
// point–ellipse root) or, inside the evolute, the other local one. The largest of those is the
// signed distance, with no search and no local maximum to mistake for the global one.
#pragma once

#include <collide2d/query.h>
#include <collide2d/shapes.h>

#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/lanes.h"
#include "shapes/internal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <type_traits>

namespace collide2d::detail {

// A core shape's (or a circle's) two discs about its centre: the reach, the largest |vertex| plus
// the radius, and the inner radius, that of a disc within the solid (-1 where the core does not hold
// the centre).
struct Discs {
  double reach, inner;
};
inline Discs discs_of(const Rect& r) {
  return {r.half_extents.norm(), std::min(r.half_extents.x(), r.half_extents.y())};
}
inline Discs discs_of(const ConvexPolygon& p) { return {p.outline->reach, p.outline->inner}; }
inline Discs discs_of(const Capsule& c) { return {c.half_length + c.radius, c.radius}; }
inline Discs discs_of(const Circle& c) { return {c.radius, c.radius}; }
inline Discs discs_of(const Segment& s) { return {s.end.norm(), -1.0}; }

// Every slot folded into one by `pick`, neighbours paired off as a tree: a tree keeps the chain of
// dependent picks short, and as the left of each pair holds the earlier slots, a pick that keeps
// the left on ties keeps the first of equals.
template <class T, std::size_t N, class Pick>
T tree_fold(std::array<T, N> slots, Pick pick) {
  static_assert(N > 0 && (N & (N - 1)) == 0, "a power of two");
  for (std::size_t width = N; width > 1; width /= 2) {
    for (std::size_t i = 0; i < width / 2; ++i) slots[i] = pick(slots[2 * i], slots[2 * i + 1]);
  }
  return slots[0];
}

// A core in the frame of the pair's shape A: its vertices counter-clockwise (the slots past the
// count repeating the first), each face's outward unit normal (face i from vertex i to vertex
// i + 1), and the radius around it. A segment has two faces, one each way; in a core of eight slots,
// the normals' slots 2 and 3 hold its directions from its first end to its second and back (each
// end's half turn of directions is two quarter turns about them), which the methods on an ellipse
// read; a point has none. The normals' slots past those hold a polygon's first face's normal again,
// other shapes' zero.
//
// A core of two slots (SegmentCore) is a segment's alone, its count known when compiled: a pair of
// cores takes it for a capsule or a segment (core_pair()), a quarter of the slots to build and read.
template <int Slots>
struct CoreCount {
  int count = 0;
};
template <>
struct CoreCount<2> {
  static constexpr int count = 2;
};

template <int Slots>
struct BasicCore : CoreCount<Slots> {
  static constexpr int kSlots = Slots;
  static constexpr int kAxes = Slots == 2 ? 4 : Slots;  // a segment's two faces and two ends

  // Every slot is set by core_of(): left uninitialised here, as a pair is made on every query.
  std::array<Vec2, Slots> v;
  // v's coordinates apart, for the lanes of the methods on an ellipse (face_supports.cpp,
  // core_ellipse.cpp), the axes and a rectangle's faces (coordinate_extremes()).
  std::array<double, Slots> x, y;
  std::array<Vec2, Slots> n;
  // The separating axes (the faces, then a segment's two ends, away from the other): directions
  // and offsets (the direction's dot product with the axis' point of the core) apart, for their
  // vector kernel; past axes(), no direction and an infinite offset, so that no other core is
  // ever found separated along them.
  std::array<double, kAxes> ax, ay, ad;
  double radius = 0.0;
  double largest = 0.0;        // extent()'s, set with the vertices
  Discs discs{0.0, -1.0};      // about its own centre
  Vec2 center = Vec2::Zero();  // its own centre, in the frame

  int faces() const { return this->count == 1 ? 0 : this->count; }
  int axes() const { return faces() + (this->count == 2 ? 2 : 0); }
  int next(int i) const { return i + 1 == this->count ? 0 : i + 1; }
  int prev(int i) const { return i == 0 ? this->count - 1 : i - 1; }
  // The largest coordinate of a vertex, by magnitude.
  double extent() const { return largest; }
};
using Core = BasicCore<kMaxPolygonVertices>;
using SegmentCore = BasicCore<2>;

// A rectangle's or a polygon's core read in its own frame, as the pair's A takes it: nothing to
// place and no axes to set, a polygon's vertices, normals and offsets its outline's (read in place)
// and a rectangle's four vertices built from its half extents. Its axes are its faces, which
// best_axis() measures with the products and sums an eight-slot core's lanes take, so that the
// pair's contact, distance and verdict are an eight-slot core's to the bit.
template <class Shape>
struct OwnFrameCore {
  using Slots = std::conditional_t<std::is_same_v<Shape, Rect>, std::array<Vec2, 4>,
                                   const std::array<Vec2, kMaxPolygonVertices>&>;
  Slots v, n;
  std::conditional_t<std::is_same_v<Shape, Rect>, std::array<double, 4>, const std::array<double, kMaxPolygonVertices>&>
      offsets;  // each face's n.v
  int count;
  double radius;
  Discs discs;

  int faces() const { return count; }
  int axes() const { return count; }
  int next(int i) const { return i + 1 == count ? 0 : i + 1; }
  int prev(int i) const { return i == 0 ? count - 1 : i - 1; }
  // The largest coordinate of a vertex, by magnitude (BasicCore::extent()'s).
  double extent() const {
    if constexpr (std::is_same_v<Shape, Rect>) return std::max(v[2].x(), v[2].y());  // (hx, hy)
    double reach = 0.0;
    for (const Vec2& p : v) reach = std::max(reach, std::max(std::abs(p.x()), std::abs(p.y())));
    return reach;
  }
};
template <class C>
constexpr bool kOwnFrame = std::is_same_v<C, OwnFrameCore<Rect>> || std::is_same_v<C, OwnFrameCore<ConvexPolygon>>;

// Where the point w lies along the face from v0 to v1 of outward normal n: over it (0, between its
// side planes), before v0 (-1) or beyond v1 (1).
inline int along_face(const Vec2& n, const Vec2& v0, const Vec2& v1, const Vec2& w) {
  const Vec2 t = perp(n);
  const double at = t.dot(w - v0);
  return at >= 0.0 ? (at <= t.dot(v1 - v0) ? 0 : 1) : -1;
}

// Whether a convex outline lies farthest along d at its vertex v, between `before` and `after`
// (d is in the vertex's normal cone).
inline bool farthest_at(const Vec2& before, const Vec2& v, const Vec2& after, const Vec2& d) {
  return d.dot(v - before) >= 0.0 && d.dot(v - after) >= 0.0;
}

// Where shape B's local points go in A's frame; A's own placement is the identity.
struct Placement {
  Rotation<double> rot;
  Vec2 offset = Vec2::Zero();

  // Where a shape posed at `center` and `o` goes in the frame posed at `frame_center` and `frame`.
  static Placement of(const Vec2& center, const Orientation& o, const Vec2& frame_center, const Orientation& frame) {
    const Rotation<double> f = Rotation<double>::of(frame);
    return {Rotation<double>::of(o).relative_to(f), offset_of(center, frame_center, f)};
  }
  // The offset alone, which the discs about two centres need.
  static Vec2 offset_of(const Vec2& center, const Vec2& frame_center, const Rotation<double>& frame) {
    return frame.apply_inverse(Vec2(center - frame_center));
  }
  bool moves() const { return rot.c != 1.0 || rot.s != 0.0 || offset != Vec2::Zero(); }
  Vec2 point(const Vec2& p) const { return offset + rot.apply(p); }
  Vec2 direction(const Vec2& d) const { return rot.apply(d); }
};

// Whether a disc of radius `reaches` about a point `offset` from another point may lie beyond the
// contact limit from it: false, with no square root, where the offset is within the limit plus the
// reach.
inline bool may_pass_limit(const Vec2& offset, double reaches, const ContactOptions& options) {
  const double near = options.max_separation + reaches;
  return !(near >= 0.0 && !(offset.squaredNorm() > near * near));
}

// Where the discs of two reaches (Discs::reach) whose centres lie `offset` apart are beyond the
// contact limit, the gap between them, a lower bound of the solids' distance that passes it.
inline std::optional<double> discs_beyond(const Vec2& offset, double reaches, const ContactOptions& options) {
  if (!may_pass_limit(offset, reaches, options)) return std::nullopt;
  const double d = offset.norm();
  if (!beyond_limit(d - reaches, d + reaches, options)) return std::nullopt;
  return d - reaches;
}

// A capsule's core: its segment's two ends in its own frame.
inline std::array<Vec2, 2> segment_of(const Capsule& c) { return {Vec2(-c.half_length, 0), Vec2(c.half_length, 0)}; }
// Its two faces' outward normals: from the first end to the second, and back.
inline std::array<Vec2, 2> segment_normals() { return {Vec2(0, -1), Vec2(0, 1)}; }
// A segment's core: its two points in its own frame, the first at the origin.
inline std::array<Vec2, 2> segment_of(const Segment& s) { return {Vec2::Zero(), s.end}; }
// Its normals in the slots a core keeps them (Core::n): its two faces' outward normals (right of its
// direction, then left), then its direction from the first point to the second, and back.
inline std::array<Vec2, 4> segment_normals(const Segment& s) {
  const Vec2 d = s.end.normalized(), right(d.y(), -d.x());
  return {right, -right, d, -d};
}

// A core shape's core as the lanes take it: every vertex slot (those past the count repeating the
// first), the count and the radius.
inline const std::array<Vec2, kMaxPolygonVertices>& slots_of(const ConvexPolygon& p) { return p.outline->vertices; }
inline std::array<Vec2, 2> slots_of(const Capsule& c) { return segment_of(c); }
inline int count_of(const ConvexPolygon& p) { return p.count(); }
inline int count_of(const Capsule&) { return 2; }
inline double radius_of(const ConvexPolygon& p) { return p.radius(); }
inline double radius_of(const Capsule& c) { return c.radius; }

// The least and greatest of a core's vertices' projections, and the first vertex at each.
struct Extremes {
  double least, most;
  int at_least = 0, at_most = 0;
};
// An eight-slot core's least and greatest coordinates along x, then along y, in SIMD lanes
// (best_axis.cpp): the slots past its count repeat its first vertex.
std::array<Extremes, 2> coordinate_extremes_in_lanes(const Core& c);

// Core y's greatest separation along an axis of core x (its least projection on the axis' direction
// less the axis' offset), or the first beyond `stop`; the axis (a slot of Core::ax) and y's first
// vertex there. Four or eight axes at once in SIMD lanes (best_axis.cpp), given by their
// directions and offsets apart, y's `y_count` vertices by y.
struct BestAxis {
  double s = -std::numeric_limits<double>::infinity();
  int axis = 0;
  int vertex = 0;
};
template <std::size_t N>
using AxisLanes = std::array<double, N>;
BestAxis best_axis(const AxisLanes<4>& ax, const AxisLanes<4>& ay, const AxisLanes<4>& ad, const Vec2* y, int y_count,
                   double stop);
BestAxis best_axis(const AxisLanes<kMaxPolygonVertices>& ax, const AxisLanes<kMaxPolygonVertices>& ay,
                   const AxisLanes<kMaxPolygonVertices>& ad, const Vec2* y, int y_count, double stop);
// Against a rectangle about the origin of these half extents, in place of y's vertices.
BestAxis best_axis(const AxisLanes<kMaxPolygonVertices>& ax, const AxisLanes<kMaxPolygonVertices>& ay,
                   const AxisLanes<kMaxPolygonVertices>& ad, const Vec2& half_extents, double stop);
// The directions as a polygon outline's normals (PolygonOutline::normals), the offsets its faces'.
BestAxis best_axis(const std::array<Vec2, kMaxPolygonVertices>& normals, const AxisLanes<kMaxPolygonVertices>& ad,
                   const Vec2* y, int y_count, double stop);

// A segment's two end axes (Core::ax, ay, ad slots 2 and 3), as plane_of() gives them: slot 2 the
// first end, facing back along the segment, slot 3 the second, facing on; their offsets written
// out rather than through a Plane, which the compiler builds in memory.
template <class C>
void set_end_axes(C& c) {
  const Vec2 e = perp(c.n[0]);
  c.ax[2] = -e.x(), c.ay[2] = -e.y(), c.ad[2] = -e.x() * c.x[0] + -e.y() * c.y[0];
  c.ax[3] = e.x(), c.ay[3] = e.y(), c.ad[3] = e.x() * c.x[1] + e.y() * c.y[1];
}

// Fills an eight-slot core's vertices, their coordinates apart, its normals (those past
// `normal_count` zero) and its faces' axes from a shape's slots placed by `at`: every slot at once
// in SIMD lanes (place_core.cpp).
void place_slots(const std::array<Vec2, kMaxPolygonVertices>& vertices,
                 const std::array<Vec2, kMaxPolygonVertices>& normals, int normal_count, int faces, const Placement& at,
                 Core& c);

// Every core comes with its axes (Core::ax, ay, ad), which a pair of cores reads on every query.
Core core_of(const Rect& r, const Placement& at);
Core core_of(const ConvexPolygon& p, const Placement& at);
template <class C = Core>
C core_of(const Capsule& c, const Placement& at);
template <class C = Core>
C core_of(const Segment& s, const Placement& at);
Core core_of(const Circle& c, const Placement& at);
inline OwnFrameCore<Rect> own_frame_core(const Rect& r) {
  const double hx = r.half_extents.x(), hy = r.half_extents.y();
  return {{{{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}}},
          {{{0, -1}, {1, 0}, {0, 1}, {-1, 0}}},
          {hy, hx, hy, hx},
          4,
          0.0,
          discs_of(r)};
}
inline OwnFrameCore<ConvexPolygon> own_frame_core(const ConvexPolygon& p) {
  const PolygonOutline& o = *p.outline;
  return {o.vertices, o.normals, o.offsets, o.count, o.radius, discs_of(p)};
}

// The core a pair of cores takes for a shape: a capsule's and a segment's in two slots.
template <class A>
using PairCore = std::conditional_t<std::is_same_v<A, Capsule> || std::is_same_v<A, Segment>, SegmentCore, Core>;
template <class A>
PairCore<A> pair_core_of(const A& shape, const Placement& at) {
  if constexpr (std::is_same_v<PairCore<A>, SegmentCore>) {
    return core_of<SegmentCore>(shape, at);
  } else {
    return core_of(shape, at);
  }
}

// The core a pair of cores takes for its shape A, which stays where it is: a rectangle's or a
// polygon's read in its own frame.
template <class A>
using FirstCore =
    std::conditional_t<std::is_same_v<A, Rect> || std::is_same_v<A, ConvexPolygon>, OwnFrameCore<A>, PairCore<A>>;
template <class A>
FirstCore<A> first_core_of(const A& shape) {
  if constexpr (kOwnFrame<FirstCore<A>>) {
    return own_frame_core(shape);
  } else {
    return pair_core_of(shape, Placement{});
  }
}

// A pair of cores' scale, what their rounding is a few u of: the larger core's largest coordinate
// (B's offset and size within it), twice, and the two radii.
inline double pair_scale(double extent, double radii) { return 2 * extent + radii; }
// The rounding a face's contact allows for between the clipped incident face and the nearest
// features apart (contact_cores.cpp's face_contact, contact_capsule_capsule.cpp).
inline double face_rounding(double scale) { return 8 * std::numeric_limits<double>::epsilon() * scale; }

// A pair of core shapes: A's core in its own frame, B's in A's, and A's pose to go back to the world.
template <class X, class Y>
struct CorePairOf {
  X a;
  Y b;
  Rotation<double> a_rot;
  Vec2 a_center = Vec2::Zero();
  // The caller gave B first: a contact is written in the caller's order, B's points first and the
  // normal from B to A, as Contact::swapped() would turn it.
  bool swapped = false;

  Vec2 world_point(const Vec2& p) const { return a_center + a_rot.apply(p); }
  Vec2 world_direction(const Vec2& d) const { return a_rot.apply(d); }
  // The pair's scale: the offset of B and both cores' sizes, what their rounding is a few u of.
  double scale() const { return pair_scale(std::max(a.extent(), b.extent()), a.radius + b.radius); }
};

// The pair, B placed in A's frame by `at`; `swapped`: the caller gave B first (CorePairOf::swapped).
template <class A, class B>
CorePairOf<FirstCore<A>, PairCore<B>> core_pair(const A& a, const Orientation& ao, const B& b, const Placement& at,
                                                bool swapped = false) {
  return {first_core_of(a), pair_core_of(b, at), Rotation<double>::of(ao), a.center, swapped};
}
template <class A, class B>
CorePairOf<FirstCore<A>, PairCore<B>> core_pair(const A& a, const Orientation& ao, const B& b, const Orientation& bo) {
  return core_pair(a, ao, b, Placement::of(b.center, bo, a.center, ao));
}

// The disc test (disc_filter-inl.h) on one pair, before any core is built: the fields from the two
// shapes (B's centre in A's frame, as core_pair() and CoreEllipse::of place it, and each shape's
// discs), and the verdict where the discs settle it. The overlap tests below take the pairs it
// leaves.
template <class A, class B>
DiscPairLanes<double> disc_lanes(const A& a, const Orientation& ao, const B& b, const Orientation& bo) {
  const Vec2 o = Placement::of(b.center, bo, a.center, ao).offset;
  const Discs da = discs_of(a), db = discs_of(b);
  return {o.x(), o.y(), da.reach, da.inner, db.reach, db.inner};
}
template <class A>
DiscEllipseLanes<double> disc_lanes(const A& a, const Orientation& ao, const Ellipse& e, const Orientation& eo) {
  const Vec2 o = Placement::of(a.center, ao, e.center, eo).offset;
  const Discs d = discs_of(a);
  return {o.x(), o.y(), d.reach, d.inner, e.a, e.b};
}
std::optional<bool> disc_verdict(const DiscPairLanes<double>& discs);
std::optional<bool> disc_verdict(const DiscEllipseLanes<double>& discs);

// The methods on a pair of cores (core_pair.h holds what they share): overlap/overlap_cores.cpp,
// distance/distance_cores.cpp, contact/contact_cores.cpp; each for every pair of core types.
template <class X, class Y>
bool core_overlap(const CorePairOf<X, Y>& p);
template <class X, class Y>
DistanceResult core_distance(const CorePairOf<X, Y>& p);
// The contact of the pair where the discs about the centres leave it open (the form on shapes below
// tries them first).
template <class X, class Y>
Contact core_contact(const CorePairOf<X, Y>& p, const ContactOptions& options);
// The contact on A's face i with its normal held there: B's deepest point over the face (between
// its side planes) and B's incident face clipped to it; empty, its separation infinite, where no
// point of B's core lies over the face.
template <class X, class Y>
Contact core_face_contact(const CorePairOf<X, Y>& p, int i, const ContactOptions& options);
// The contact of two core shapes: B's offset alone first, and the discs about the two centres, which
// settle a pair beyond the limit before any core is built. `swapped`: the caller gave B first, and
// the contact is written in its order.
template <class A, class B>
Contact core_contact(const A& a, const Orientation& ao, const B& b, const Orientation& bo,
                     const ContactOptions& options, bool swapped = false) {
  const Rotation<double> frame = Rotation<double>::of(ao);
  const Vec2 offset = Placement::offset_of(b.center, a.center, frame);
  if (has_limit(options)) {
    if (const auto gap = discs_beyond(offset, discs_of(a).reach + discs_of(b).reach, options)) {
      return Contact::beyond(*gap);
    }
  }
  return core_contact(core_pair(a, ao, b, Placement{Rotation<double>::of(bo).relative_to(frame), offset}, swapped),
                      options);
}

// A core shape A against an ellipse B (core_ellipse.cpp): A's core in the ellipse's frame, where the
// ellipse is centred at the origin with semi-axis a along x and b along y.
struct CoreEllipse {
  Core core;
  double a = 1.0, b = 1.0;
  Rotation<double> e_rot;
  Vec2 e_center = Vec2::Zero();

  template <class A>
  static CoreEllipse of(const A& shape, const Orientation& ao, const Ellipse& e, const Orientation& eo) {
    return {core_of(shape, Placement::of(shape.center, ao, e.center, eo)), e.a, e.b, Rotation<double>::of(eo),
            e.center};
  }
  Vec2 world_point(const Vec2& p) const { return e_center + e_rot.apply(p); }
  Vec2 world_direction(const Vec2& d) const { return e_rot.apply(d); }
};

// Along each face normal n of a core, an ellipse's (semi-axes a along x and b along y, centred at the
// origin): its support value h, its support point q along -n, its radius of curvature there,
// (ab)^2 / h^3, and the face's separation from it, n.(q - v) = -h - n.v for the face's first vertex
// v. Every slot at once in SIMD lanes (face_supports.cpp); the slots past the faces hold no face.
struct FaceSupports {
  std::array<double, kMaxPolygonVertices> h, rho, qx, qy, s;
};
void face_supports(const Core& c, double a, double b, FaceSupports& out);
// Bit k set where vertex k's cone of a polygon core certainly holds no separation above s against
// the ellipse (arc_bound-inl.h on the arc from face k - 1's normal to face k's), every vertex at once
// in SIMD lanes; least_rho the ellipse's least radius of curvature.
std::uint32_t cones_within(const Core& c, const FaceSupports& along, double least_rho, double a, double b, double s);

// The methods on a core and an ellipse (core_ellipse.h holds what they share):
// overlap/overlap_core_ellipse.cpp, distance/distance_core_ellipse.cpp, contact/contact_core_ellipse.cpp.
bool core_ellipse_overlap(const CoreEllipse& p);
DistanceResult core_ellipse_distance(const CoreEllipse& p);
Contact core_ellipse_contact(const CoreEllipse& p, const ContactOptions& options);

}  // namespace collide2d::detail
