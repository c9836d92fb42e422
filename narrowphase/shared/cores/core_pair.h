// Private: what the methods on a pair of cores share, for every pair of core types (a core of eight
// slots or a segment's of two, convex_core.h): the separating axes, the nearest features of two
// disjoint cores, the overlap verdict that the overlap test and the distance both take, and a
// reference face clipped against the incident one. The methods themselves live with their queries:
// overlap/overlap_cores.cpp, distance/distance_cores.cpp and contact/contact_cores.cpp, each
// instantiating them for every pair of core types.
#pragma once

#include "narrowphase/shared/cores/convex_core.h"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

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
template <class X>
Plane plane_of(const X& x, const Axis& axis) {
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
// Of the projections at(0) ... at(count - 1).
template <class At>
Extremes extremes_of(At at, int count) {
  Extremes e{at(0), at(0)};
  for (int j = 1; j < count; ++j) {
    const double p = at(j);
    e.at_least = p < e.least ? j : e.at_least;
    e.at_most = p > e.most ? j : e.at_most;
    e.least = std::min(e.least, p);
    e.most = std::max(e.most, p);
  }
  return e;
}
// Core y's projections on the direction (ax, ay). A rectangle's four are -s, d, s and -d for the
// two sums s and d of its half extents' products (its vertices' coordinates are those negated or
// not, and rounding is symmetric: the same bits), so the greatest is m, the larger of |s| and |d|,
// and the least -m, each first at the first vertex that has it.
template <class Y>
Extremes extremes_along(double ax, double ay, const Y& y) {
  if constexpr (std::is_same_v<Y, OwnFrameCore<Rect>>) {
    const double a = ax * y.v[2].x(), b = ay * y.v[2].y(), s = a + b, d = a - b;
    const double m = std::max(std::abs(s), std::abs(d));
    return {-m, m, s == m ? 0 : d == -m ? 1 : s == -m ? 2 : 3, s == -m ? 0 : d == m ? 1 : s == m ? 2 : 3};
  } else {
    return extremes_of([&](int j) { return ax * y.v[j].x() + ay * y.v[j].y(); }, y.count);
  }
}
// Core y's coordinates along x and y: its projections on a rectangle's normals, whose zero component
// adds nothing but a zero's sign. An eight-slot core's in SIMD lanes.
template <class Y>
std::array<Extremes, 2> coordinate_extremes(const Y& y) {
  if constexpr (std::is_same_v<Y, Core>) {
    return coordinate_extremes_in_lanes(y);
  } else {
    const auto along = [&y](int k) { return extremes_of([&](int j) { return y.v[j][k]; }, y.count); };
    return {along(0), along(1)};
  }
}

// The first of the axes beyond `stop`, else the first of the greatest, kept in selects: which axis
// is the greatest is a coin toss, which a branch would mispredict.
template <std::size_t N>
BestAxis pick_axis(const std::array<BestAxis, N>& axes, double stop) {
  double most = -std::numeric_limits<double>::infinity();
  int k = -1;
  for (int i = 0; i < static_cast<int>(N); ++i) {
    const double s = axes[i].s;
    if (s > stop) return axes[i];
    const bool greater = s > most;
    most = greater ? s : most;
    k = greater ? i : k;
  }
  return k < 0 ? BestAxis{} : axes[k];
}

// Core y's best axis against x (BestAxis). In SIMD lanes: an eight-slot core's (against a rectangle
// in its own frame, from its projections' two sums), a polygon's in its own frame (its outline's
// normals and offsets n.v, which are the lanes': the slots past its faces repeat its first, whose
// separation no later one beats) and a segment's against a polygon. One at a time, with the same
// products, sums and minima, so that they agree to the bit: a rectangle's faces in its own frame
// from y's coordinates, and a segment's four axes against a segment or a rectangle, which come in
// opposite pairs (its faces' normals, then its ends' directions, each the other negated to the
// bit), so that y's least projection on one is its greatest on the other negated.
template <class X, class Y>
BestAxis best_axis(const X& x, const Y& y, double stop) {
  if constexpr (std::is_same_v<X, OwnFrameCore<ConvexPolygon>>) {
    return best_axis(x.n, x.offsets, y.v.data(), y.count, stop);
  } else if constexpr (std::is_same_v<X, Core> && std::is_same_v<Y, OwnFrameCore<Rect>>) {
    return best_axis(x.ax, x.ay, x.ad, y.v[2], stop);  // v[2] = (hx, hy)
  } else if constexpr (std::is_same_v<X, OwnFrameCore<Rect>>) {
    // The faces' normals (0, -1), (1, 0), (0, 1), (-1, 0).
    const auto [ex, ey] = coordinate_extremes(y);
    return pick_axis(std::array<BestAxis, 4>{{{-ey.most - x.offsets[0], 0, ey.at_most},
                                              {ex.least - x.offsets[1], 1, ex.at_least},
                                              {ey.least - x.offsets[2], 2, ey.at_least},
                                              {-ex.most - x.offsets[3], 3, ex.at_most}}},
                     stop);
  } else if constexpr (std::is_same_v<X, Core> || std::is_same_v<Y, Core> ||
                       std::is_same_v<Y, OwnFrameCore<ConvexPolygon>>) {
    return best_axis(x.ax, x.ay, x.ad, y.v.data(), y.count, stop);
  } else {
    const Extremes face = extremes_along(x.ax[0], x.ay[0], y), end = extremes_along(x.ax[3], x.ay[3], y);
    return pick_axis(std::array<BestAxis, 4>{{{face.least - x.ad[0], 0, face.at_least},
                                              {-face.most - x.ad[1], 1, face.at_most},
                                              {-end.most - x.ad[2], 2, end.at_most},
                                              {end.least - x.ad[3], 3, end.at_least}}},
                     stop);
  }
}

// The best axis, or the first beyond `stop`: past it, the caller needs no other (the overlap test,
// whose pair is apart).
template <class X, class Y>
Axis best_axis_of(const X& x, const Y& y, double stop) {
  if (x.axes() == 0) return {};  // a point core has no axis
  const BestAxis best = best_axis(x, y, stop);
  const int faces = x.faces();
  return best.axis < faces ? Axis{best.s, best.axis, 0, best.vertex} : Axis{best.s, -1, best.axis - faces, best.vertex};
}

// A's best axis against B and B's against A, or the first beyond `stop`: past it, the caller needs
// no other (a pair shown apart, or beyond a contact's limit).
template <class P>
Axes axes_of(const P& p, double stop = std::numeric_limits<double>::infinity()) {
  const Axis of_a = best_axis_of(p.a, p.b, stop);
  return {of_a, of_a.s > stop ? Axis{} : best_axis_of(p.b, p.a, stop)};
}

// The nearest points of two disjoint cores, in A's frame, and what they lie on: a vertex, or the
// inside of an edge (the other's vertex then lies over that edge).
struct Closest {
  double squared = std::numeric_limits<double>::infinity();
  Vec2 on_a = Vec2::Zero(), on_b = Vec2::Zero();
  int a_edge = -1, b_edge = -1;    // the edge whose inside holds the point, else -1
  int a_vertex = 0, b_vertex = 0;  // else the vertex
};

// Every edge of a core once: a segment's one edge, a point's none.
template <class C>
int edges(const C& c) {
  return c.count == 2 ? 1 : c.faces();
}

// Each vertex of `from` against each edge of `to`, into `best` with the sides as `from_is_a` says.
template <class F, class T>
void vertex_edge(const F& from, const T& to, bool from_is_a, Closest& best) {
  for (int j = 0; j < from.count; ++j) {
    const Vec2& w = from.v[j];
    for (int i = 0; i < edges(to); ++i) {
      const Vec2 &a = to.v[i], &b = to.v[to.next(i)];
      const Vec2 e = b - a;
      const double length = e.squaredNorm();  // 0 where rounding has collapsed an edge far from the origin
      const double t = length > 0.0 ? std::clamp((w - a).dot(e) / length, 0.0, 1.0) : 0.0;
      const Vec2 q = t == 0.0 ? a : t == 1.0 ? b : Vec2(a + t * e);
      const double d = (w - q).squaredNorm();
      if (!(d < best.squared)) continue;
      const int edge = t > 0.0 && t < 1.0 ? i : -1;
      const int vertex = t == 1.0 ? to.next(i) : i;
      best = from_is_a ? Closest{d, w, q, -1, edge, j, vertex} : Closest{d, q, w, edge, -1, vertex, j};
    }
  }
}

template <class P>
Closest nearest_features(const P& p) {
  Closest best;
  vertex_edge(p.a, p.b, true, best);
  vertex_edge(p.b, p.a, false, best);
  if (p.a.count == 1 && p.b.count == 1) best = {(p.b.v[0] - p.a.v[0]).squaredNorm(), p.a.v[0], p.b.v[0], -1, -1, 0, 0};
  return best;
}

// Where w lies along x's face i: over it (0), before its start (-1) or beyond its end (1).
template <class X>
int side_of(const X& x, int i, const Vec2& w) {
  return along_face(x.n[i], x.v[i], x.v[x.next(i)], w);
}

// Whether core x lies farthest along d at its vertex k (a point core's one vertex is farthest along
// every direction).
template <class X>
bool farthest_at(const X& x, int k, const Vec2& d) {
  return farthest_at(x.v[x.prev(k)], x.v[k], x.v[x.next(k)], d);
}

// Apart, the nearest points where y's witness w of x's face i does not lie over the face (`side`,
// side_of's), x A's core if x_is_a. The cores' difference y - x has the face w - (face i) at the
// greatest separation, and its separation along a direction falls away on either side of its
// greatest (the set of directions along which it is at least c > 0 is an arc), so its nearest
// point to the origin lies on that face: here at its end, the vertex of x beyond which w lies, and
// w. Checked (each vertex is its core's farthest along the line between them, which makes them
// nearest), as rounding or parallel faces can take the greatest separation to another face; else
// every vertex–edge pair is searched.
template <class P>
Closest beside_face(const P& p, bool x_is_a, const Axis& axis, int side) {
  const auto on = [&](const auto& x, const auto& y) {
    const Vec2& w = y.v[axis.vertex];
    const int e = side < 0 ? axis.face : x.next(axis.face);
    const Vec2 d = w - x.v[e];
    if (!farthest_at(x, e, d) || !farthest_at(y, axis.vertex, Vec2(-d))) return nearest_features(p);
    return x_is_a ? Closest{d.squaredNorm(), x.v[e], w, -1, -1, e, axis.vertex}
                  : Closest{d.squaredNorm(), w, x.v[e], -1, -1, axis.vertex, e};
  };
  return x_is_a ? on(p.a, p.b) : on(p.b, p.a);
}

// The cores' distance and nearest points, apart: the best face's when its witness vertex lies over
// the face, else beside it.
template <class P>
Closest gap(const P& p, const Axes& axes) {
  const Axis& best = axes.best();
  if (best.face < 0) return nearest_features(p);
  const bool ref_a = !axes.b_best();
  const auto on = [&](const auto& x, const auto& y) {
    const Vec2& w = y.v[best.vertex];
    if (const int side = side_of(x, best.face, w); side != 0) return beside_face(p, ref_a, best, side);
    const Vec2 q = w - best.s * x.n[best.face];
    return ref_a ? Closest{best.s * best.s, q, w, best.face, -1, 0, best.vertex}
                 : Closest{best.s * best.s, w, q, -1, best.face, best.vertex, 0};
  };
  return ref_a ? on(p.a, p.b) : on(p.b, p.a);
}

// The two radii, which the cores' separations leave out.
template <class P>
double radii(const P& p) {
  return p.a.radius + p.b.radius;
}

// Whether the solids overlap, from the cores' axes and, where those leave it open, their gap: the
// one verdict of the overlap test and the distance, so that they agree to the bit.
struct CoreVerdict {
  bool overlapping = false;
  Closest gap;  // the cores' nearest points, where the verdict needed them (else squared is infinite)
};
// The axes settle most pairs; a pair apart by less than the radii needs its cores' gap. Inline: the
// overlap test, which reads only the verdict, then never builds the gap.
template <class P>
CoreVerdict verdict(const P& p, const Axes& axes) {
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

// The height over a face's line where an edge from heights b0 to b1 at positions a0 to a1 along
// the face crosses the side plane at `limit`.
inline double height_at(double limit, double a0, double b0, double a1, double b1) {
  return b0 + (b1 - b0) * ((limit - a0) / (a1 - a0));
}

// The point where an edge of y, from heights b0 to b1 over face x's line at positions a0 to a1
// along it, crosses the side plane at `limit`: on the plane exactly, in the face's coordinates
// (interpolated, its position along the face would carry the rounding of the whole edge).
inline Clipped cut(const Vec2& v0, const Vec2& t, const Vec2& n, double limit, double a0, double b0, double a1,
                   double b1, int id) {
  const double b = height_at(limit, a0, b0, a1, b1);
  return {v0 + limit * t + b * n, b, id};
}

// The reference face i of core x and the incident face of core y clipped to its side planes.
template <class X, class Y>
FaceClip clip_face(const X& x, int i, const Y& y) {
  const Vec2 &n = x.n[i], &v0 = x.v[i];
  const Vec2 t = perp(n);
  const double length = t.dot(x.v[x.next(i)] - v0);
  int k = 0;
  double least = y.faces() > 0 ? y.n[0].dot(n) : 0.0;
  for (int j = 1; j < y.faces(); ++j) {
    const double along = y.n[j].dot(n);
    k = along < least ? j : k;  // selects, not branches: which face is the incident one is a coin toss
    least = std::min(least, along);
  }
  const int ends = y.count == 1 ? 1 : 2;
  std::array<Clipped, 2> end;
  std::array<double, 2> a{};
  for (int e = 0; e < ends; ++e) {
    const int vertex = e == 0 ? k : y.next(k);
    end[e] = {y.v[vertex], n.dot(y.v[vertex]) - n.dot(v0), vertex};  // as the axes measure it
    a[e] = t.dot(y.v[vertex] - v0);
  }
  FaceClip out;
  out.deep = ends == 2 && end[1].b < end[0].b ? end[1] : end[0];
  for (int e = 0; e < ends; ++e) {
    if (a[e] >= 0.0 && a[e] <= length) {
      out.kept[out.count++] = end[e];
      continue;
    }
    const int other = 1 - e;
    const bool below = a[e] < 0.0;
    if (ends == 1 || (below ? a[other] < 0.0 : a[other] > length)) continue;  // wholly beyond that plane
    out.kept[out.count++] =
        cut(v0, t, n, below ? 0.0 : length, a[e], end[e].b, a[other], end[other].b, below ? kCutAtStart : kCutAtEnd);
  }
  if (out.count == 2 && out.kept[1].b < out.kept[0].b) std::swap(out.kept[0], out.kept[1]);
  return out;
}

}  // namespace collide2d::detail
