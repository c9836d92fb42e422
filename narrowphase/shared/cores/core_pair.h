// Private: what the methods on a pair of cores share (narrowphase/shared/cores/convex_core.cpp):
// the separating axes, the nearest features of two disjoint cores, the overlap verdict that the
// overlap test and the distance both take, and a reference face clipped against the incident one.
// The methods themselves live with their queries: overlap/overlap_cores.cpp,
// distance/distance_cores.cpp and contact/contact_cores.cpp.
#pragma once

#include "narrowphase/shared/cores/convex_core.h"

#include <limits>

namespace collide2d::detail {

// A separating axis of core x against core y: a face of x, or a segment's end (face -1, the end's
// vertex `end`), with y's separation along it and y's deepest vertex there (the first at it).
struct Axis {
  double s = -std::numeric_limits<double>::infinity();
  int face = -1;
  int end = 0;
  int vertex = 0;
};

// The axis' outward direction and a point of x on it.
struct Plane {
  Vec2 normal, origin;
};
inline Plane plane_of(const Core& x, const Axis& axis) {
  if (axis.face >= 0) return {x.n[axis.face], x.v[axis.face]};
  const Vec2 e = perp(x.n[0]);
  return {axis.end == 1 ? e : Vec2(-e), x.v[axis.end]};
}

// The two cores' axes: A's best against B and B's best against A.
struct Axes {
  Axis of_a, of_b;
  double s() const { return std::max(of_a.s, of_b.s); }
  bool b_best() const { return of_b.s > of_a.s; }
  const Axis& best() const { return b_best() ? of_b : of_a; }
};
// A's best axis against B and B's against A, or the first beyond `stop`: past it, the caller needs
// no other (a pair shown apart, or beyond a contact's limit).
Axes axes_of(const CorePair& p, double stop = std::numeric_limits<double>::infinity());

// The nearest points of two disjoint cores, in A's frame, and what they lie on: a vertex, or the
// inside of an edge (the other's vertex then lies over that edge).
struct Closest {
  double squared = std::numeric_limits<double>::infinity();
  Vec2 on_a = Vec2::Zero(), on_b = Vec2::Zero();
  int a_edge = -1, b_edge = -1;    // the edge whose inside holds the point, else -1
  int a_vertex = 0, b_vertex = 0;  // else the vertex
};
Closest nearest_features(const CorePair& p);

// Where w lies along x's face i: over it (0), before its start (-1) or beyond its end (1).
inline int side_of(const Core& x, int i, const Vec2& w) { return along_face(x.n[i], x.v[i], x.v[x.next(i)], w); }

// Apart, the nearest points where y's witness w of x's face i does not lie over the face (`side`,
// side_of's), x A's core if x_is_a.
Closest beside_face(const CorePair& p, bool x_is_a, const Axis& axis, int side);
// The cores' distance and nearest points, apart: the best face's when its witness vertex lies over
// the face, else beside it.
Closest gap(const CorePair& p, const Axes& axes);

// The two radii, which the cores' separations leave out.
inline double radii(const CorePair& p) { return p.a.radius + p.b.radius; }

// Whether the solids overlap, from the cores' axes and, where those leave it open, their gap: the
// one verdict of the overlap test and the distance, so that they agree to the bit.
struct CoreVerdict {
  bool overlapping = false;
  Closest gap;  // the cores' nearest points, where the verdict needed them (else squared is infinite)
};
// The axes settle most pairs; a pair apart by less than the radii needs its cores' gap. Inline: the
// overlap test, which reads only the verdict, then never builds the gap.
inline CoreVerdict verdict(const CorePair& p, const Axes& axes) {
  const double s = axes.s();
  if (s <= 0.0) return {true, {}};
  if (s > radii(p)) return {false, {}};
  const Closest c = gap(p, axes);
  return {c.squared <= radii(p) * radii(p), c};
}

// The feature number of a point where a side plane of the reference face cut the incident face:
// at the face's first vertex's end, or at its second's.
constexpr int kCutAtStart = kMaxPolygonVertices;
constexpr int kCutAtEnd = kMaxPolygonVertices + 1;

// One point of a manifold on the reference face: the incident core's point `on_y` with its
// separation `b` from the face's line and its feature number.
struct Clipped {
  Vec2 on_y = Vec2::Zero();
  double b = 0.0;
  int id = 0;
};

// The reference face i of core x and the incident face of core y (its one vertex for a point),
// clipped to the face's side planes.
struct FaceClip {
  Clipped deep;                 // the incident face's deeper end, before clipping
  std::array<Clipped, 2> kept;  // the clipped ends, deeper first
  int count = 0;                // 0 when the incident face lies beyond a side plane
};

// The point where an edge of y, from heights b0 to b1 over face x's line at positions a0 to a1
// along it, crosses the side plane at `limit`: on the plane exactly, in the face's coordinates
// (interpolated, its position along the face would carry the rounding of the whole edge).
inline Clipped cut(const Vec2& v0, const Vec2& t, const Vec2& n, double limit, double a0, double b0, double a1,
                   double b1, int id) {
  const double b = b0 + (b1 - b0) * ((limit - a0) / (a1 - a0));
  return {v0 + limit * t + b * n, b, id};
}

// The reference face i of core x and the incident face of core y clipped to its side planes.
FaceClip clip_face(const Core& x, int i, const Core& y);

}  // namespace collide2d::detail
