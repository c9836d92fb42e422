#include "narrowphase/shared/cores/convex_core.h"

#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/frames/unit_vector.h"
#include "narrowphase/shared/lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <span>

namespace collide2d::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The feature number of a point where a side plane of the reference face cut the incident face:
// at the face's first vertex's end, or at its second's.
constexpr int kCutAtStart = kMaxPolygonVertices;
constexpr int kCutAtEnd = kMaxPolygonVertices + 1;

// The core of `count` vertices from the shape's slots: a polygon's outline gives all of them (those
// past the count repeating the first), so that the loops run a fixed length; the slots not given
// repeat the first vertex, and the normals not given are zero.
Core make(int count, std::span<const Vec2> vertices, std::span<const Vec2> normals, double radius, const Discs& discs,
          const Placement& at) {
  Core c;
  c.count = count;
  c.radius = radius;
  c.discs = discs;
  c.center = at.offset;
  if (at.moves()) {
    for (std::size_t i = 0; i < vertices.size(); ++i) c.v[i] = at.point(vertices[i]);
    for (std::size_t i = 0; i < normals.size(); ++i) c.n[i] = at.direction(normals[i]);
  } else {
    std::copy(vertices.begin(), vertices.end(), c.v.begin());
    std::copy(normals.begin(), normals.end(), c.n.begin());
  }
  // The axes' kernel reads all kMaxPolygonVertices.
  std::fill(c.v.begin() + static_cast<std::ptrdiff_t>(vertices.size()), c.v.end(), c.v[0]);
  std::fill(c.n.begin() + static_cast<std::ptrdiff_t>(normals.size()), c.n.end(), Vec2::Zero());
  for (int i = 0; i < kMaxPolygonVertices; ++i) c.x[i] = c.v[i].x(), c.y[i] = c.v[i].y();
  return c;
}

// A separating axis of core x against core y: a face of x, or a segment's end (face -1, the end's
// vertex `end`), with y's separation along it and y's deepest vertex there (the first at it).
struct Axis {
  double s = -kInf;
  int face = -1;
  int end = 0;
  int vertex = 0;
};

// The axis' outward direction and a point of x on it.
struct Plane {
  Vec2 normal, origin;
};
Plane plane_of(const Core& x, const Axis& axis) {
  if (axis.face >= 0) return {x.n[axis.face], x.v[axis.face]};
  const Vec2 e = perp(x.n[0]);
  return {axis.end == 1 ? e : Vec2(-e), x.v[axis.end]};
}

// The best axis, or the first beyond `stop`: past it, the caller needs no other (the overlap test,
// whose pair is apart).
Axis best_axis_of(const Core& x, const Core& y, double stop = kInf) {
  if (x.axes() == 0) return {};  // a point core has no axis
  const BestAxis best = best_axis(x, y, stop);
  const int faces = x.faces();
  return best.axis < faces ? Axis{best.s, best.axis, 0, best.vertex} : Axis{best.s, -1, best.axis - faces, best.vertex};
}

// Every edge of a core once: a segment's one edge, a point's none.
int edges(const Core& c) { return c.count == 2 ? 1 : c.faces(); }

// The nearest points of two disjoint cores, in A's frame, and what they lie on: a vertex, or the
// inside of an edge (the other's vertex then lies over that edge).
struct Closest {
  double squared = kInf;
  Vec2 on_a = Vec2::Zero(), on_b = Vec2::Zero();
  int a_edge = -1, b_edge = -1;    // the edge whose inside holds the point, else -1
  int a_vertex = 0, b_vertex = 0;  // else the vertex
};

// Each vertex of `from` against each edge of `to`, into `best` with the sides as `from_is_a` says.
void vertex_edge(const Core& from, const Core& to, bool from_is_a, Closest& best) {
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

Closest nearest_features(const CorePair& p) {
  Closest best;
  vertex_edge(p.a, p.b, true, best);
  vertex_edge(p.b, p.a, false, best);
  if (p.a.count == 1 && p.b.count == 1) best = {(p.b.v[0] - p.a.v[0]).squaredNorm(), p.a.v[0], p.b.v[0], -1, -1, 0, 0};
  return best;
}

// The two cores' axes: A's best against B and B's best against A.
struct Axes {
  Axis of_a, of_b;
  double s() const { return std::max(of_a.s, of_b.s); }
  bool b_best() const { return of_b.s > of_a.s; }
  const Axis& best() const { return b_best() ? of_b : of_a; }
};
Axes axes_of(const CorePair& p, double stop = kInf) {
  const Axis of_a = best_axis_of(p.a, p.b, stop);
  return {of_a, of_a.s > stop ? Axis{} : best_axis_of(p.b, p.a, stop)};
}

// Where w lies along x's face i: over it (0), before its start (-1) or beyond its end (1).
int side_of(const Core& x, int i, const Vec2& w) { return along_face(x.n[i], x.v[i], x.v[x.next(i)], w); }

// A point core's one vertex is farthest along every direction.
bool farthest_at(const Core& x, int k, const Vec2& d) {
  return detail::farthest_at(x.v[x.prev(k)], x.v[k], x.v[x.next(k)], d);
}

// Apart, the nearest points where y's witness w of x's face i does not lie over the face. The
// cores' difference y - x has the face w - (face i) at the greatest separation, and its
// separation along a direction falls away on either side of its greatest (the set of directions
// along which it is at least c > 0 is an arc), so its nearest point to the origin lies on that
// face: here at its end, the vertex of x beyond which w lies (`side`, side_of's), and w. Checked
// (each vertex is its core's farthest along the line between them, which makes them nearest), as
// rounding or parallel faces can take the greatest separation to another face; else every
// vertex–edge pair is searched.
Closest beside_face(const CorePair& p, bool x_is_a, const Axis& axis, int side) {
  const Core &x = x_is_a ? p.a : p.b, &y = x_is_a ? p.b : p.a;
  const Vec2& w = y.v[axis.vertex];
  const int e = side < 0 ? axis.face : x.next(axis.face);
  const Vec2 d = w - x.v[e];
  if (!farthest_at(x, e, d) || !farthest_at(y, axis.vertex, Vec2(-d))) return nearest_features(p);
  return x_is_a ? Closest{d.squaredNorm(), x.v[e], w, -1, -1, e, axis.vertex}
                : Closest{d.squaredNorm(), w, x.v[e], -1, -1, axis.vertex, e};
}

// The cores' distance and nearest points, apart: the best face's when its witness vertex lies over
// the face, else beside it.
Closest gap(const CorePair& p, const Axes& axes) {
  const Axis& best = axes.best();
  if (best.face < 0) return nearest_features(p);
  const bool ref_a = !axes.b_best();
  const Core &x = ref_a ? p.a : p.b, &y = ref_a ? p.b : p.a;
  const Vec2& w = y.v[best.vertex];
  if (const int side = side_of(x, best.face, w); side != 0) return beside_face(p, ref_a, best, side);
  const Vec2 q = w - best.s * x.n[best.face];
  return ref_a ? Closest{best.s * best.s, q, w, best.face, -1, 0, best.vertex}
               : Closest{best.s * best.s, w, q, -1, best.face, best.vertex, 0};
}

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
Clipped cut(const Vec2& v0, const Vec2& t, const Vec2& n, double limit, double a0, double b0, double a1, double b1,
            int id) {
  const double b = b0 + (b1 - b0) * ((limit - a0) / (a1 - a0));
  return {v0 + limit * t + b * n, b, id};
}

FaceClip clip_face(const Core& x, int i, const Core& y) {
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

// The deepest point of core y over face i of core x (between its side planes): a vertex of y there,
// or where an edge of y crosses a side plane; b infinite where y has none. Where the incident face
// lies wholly beyond a side plane, as one of two faces of y nearly in line may, it stands in for
// its deeper end, which lies off the face.
Clipped deepest_over_face(const Core& x, int i, const Core& y) {
  const Vec2 &n = x.n[i], &v0 = x.v[i];
  const Vec2 t = perp(n);
  const double length = t.dot(x.v[x.next(i)] - v0);
  Clipped best{Vec2::Zero(), std::numeric_limits<double>::infinity(), 0};
  const auto keep = [&best](const Clipped& c) { best = c.b < best.b ? c : best; };
  for (int j = 0; j < y.count; ++j) {
    const int k = y.next(j);
    const double a0 = t.dot(y.v[j] - v0), a1 = t.dot(y.v[k] - v0);
    const double b0 = n.dot(y.v[j]) - n.dot(v0), b1 = n.dot(y.v[k]) - n.dot(v0);  // as the axes measure it
    if (a0 >= 0.0 && a0 <= length) keep({y.v[j], b0, j});
    for (const double limit : {0.0, length}) {
      if ((a0 < limit) != (a1 < limit))
        keep(cut(v0, t, n, limit, a0, b0, a1, b1, limit == 0.0 ? kCutAtStart : kCutAtEnd));
    }
  }
  return best;
}

// Builds contacts in the world from points in A's frame.
struct Writer {
  const CorePair& p;

  // A point of y's core and its foot on x's, the normal from x to y.
  ContactPoint point(bool x_is_a, const Vec2& on_x, const Vec2& on_y, const Vec2& normal, double separation,
                     std::uint32_t id) const {
    const double rx = x_is_a ? p.a.radius : p.b.radius, ry = x_is_a ? p.b.radius : p.a.radius;
    const Vec2 x = p.world_point(Vec2(on_x + rx * normal)), y = p.world_point(Vec2(on_y - ry * normal));
    return x_is_a ? ContactPoint{x, y, separation, id} : ContactPoint{y, x, separation, swapped_feature(id)};
  }
  Contact one(bool x_is_a, const Vec2& on_x, const Vec2& on_y, const Vec2& normal, double separation,
              std::uint32_t id) const {
    const ContactPoint c = point(x_is_a, on_x, on_y, normal, separation, id);
    const Vec2 world = p.world_direction(normal);
    return Contact::of(separation, x_is_a ? world : Vec2(-world), c.point_a, c.point_b, c.id);
  }
};

double radii(const CorePair& p) { return p.a.radius + p.b.radius; }

// Apart, nearest at two vertices, or at a vertex over an edge found by the vertex–edge search.
Contact nearest_contact(const CorePair& p, const Closest& c, const ContactOptions& options);

// The contact on face i of x (A's if x_is_a): the cores' separation s, its main point `main` (a
// point of y's core and its height over the face), and the manifold from the face's clip `c`.
Contact on_face(const CorePair& p, bool x_is_a, int i, double s, const Clipped& main, const FaceClip& c,
                const ContactOptions& options) {
  const Vec2& n = (x_is_a ? p.a : p.b).n[i];
  const auto point = [&](const Clipped& k) {
    // As if x were A: Writer renames the features for B.
    return Writer{p}.point(x_is_a, Vec2(k.on_y - k.b * n), k.on_y, n, k.b - radii(p),
                           feature_id(FeatureKind::face_of_a, i, k.id));
  };
  const ContactPoint first = point(main);
  const Vec2 world = p.world_direction(n);
  Contact out = Contact::of(s - radii(p), x_is_a ? world : Vec2(-world), first.point_a, first.point_b, first.id);
  out.manifold[0] = first;
  const double keep = std::max(out.separation, 0.0) + options.margin;
  int size = 0;
  for (int k = 0; k < c.count; ++k) {
    if (c.kept[k].b - radii(p) <= keep) out.manifold[size++] = point(c.kept[k]);
  }
  out.manifold_size = std::max(size, 1);
  return out;
}

// The contact on the axis' face i of x, y's separation along it s. Apart, s is the distance where
// the axis' witness, y's deepest vertex, lies over the face (the witness itself: of a sliver's
// nearly parallel faces, the incident face the clip takes may not hold it). Where it does not, the
// nearest features beside the face give the distance; the face stays the reference if its clipped
// incident face comes that near (parallel faces, whose ids then hold whichever side of touching the
// pair is), else the nearest features make the contact. Overlapping with the deepest vertex beyond
// the face's ends, the deepest clipped point stands in for it as the main point, or where the clip
// keeps none, the deepest point of y over the face, so that both points lie on their shapes (the
// separation stays s).
Contact face_contact(const CorePair& p, bool x_is_a, const Axis& axis, const ContactOptions& options) {
  const Core &x = x_is_a ? p.a : p.b, &y = x_is_a ? p.b : p.a;
  const int i = axis.face;
  const double s = axis.s;
  const FaceClip c = clip_face(x, i, y);
  if (s > 0) {
    const Vec2& w = y.v[axis.vertex];
    const int side = side_of(x, i, w);
    if (side == 0) return on_face(p, x_is_a, i, s, {w, s, axis.vertex}, c, options);
    const Closest near = beside_face(p, x_is_a, axis, side);
    const double distance = std::sqrt(near.squared);
    const double rounding = 8 * std::numeric_limits<double>::epsilon() * p.scale();
    if (c.count == 0 || c.kept[0].b > distance + rounding) return nearest_contact(p, near, options);
    return on_face(p, x_is_a, i, distance, c.kept[0], c, options);
  }
  if (c.count == 0) {
    const Clipped over = deepest_over_face(x, i, y);
    return on_face(p, x_is_a, i, s, over.b < std::numeric_limits<double>::infinity() ? over : c.deep, c, options);
  }
  const bool deep_kept =
      std::any_of(c.kept.begin(), c.kept.begin() + c.count, [&](const Clipped& k) { return k.id == c.deep.id; });
  return on_face(p, x_is_a, i, s, deep_kept ? c.deep : c.kept[0], c, options);
}

Contact nearest_contact(const CorePair& p, const Closest& c, const ContactOptions& options) {
  const double distance = std::sqrt(c.squared);
  // A vertex over an edge: that edge is the reference face (a segment's, the side facing the vertex).
  const auto over_edge = [&](bool x_is_a, int edge, const Vec2& on_x, const Vec2& on_y, int vertex) {
    const Core &x = x_is_a ? p.a : p.b, &y = x_is_a ? p.b : p.a;
    const int face = x.count == 2 && x.n[edge].dot(on_y - on_x) < 0 ? 1 - edge : edge;
    return on_face(p, x_is_a, face, distance, Clipped{on_y, distance, vertex}, clip_face(x, face, y), options);
  };
  if (c.a_edge >= 0) return over_edge(true, c.a_edge, c.on_a, c.on_b, c.b_vertex);
  if (c.b_edge >= 0) return over_edge(false, c.b_edge, c.on_b, c.on_a, c.a_vertex);
  const LengthAndDirection d = length_and_direction(Vec2(c.on_b - c.on_a));
  return Writer{p}.one(true, c.on_a, c.on_b, d.direction, d.length - radii(p),
                       feature_id(FeatureKind::corner_corner, c.a_vertex, c.b_vertex));
}

// A segment's end axis at the best: the segment x and a point or a parallel segment y in line.
Contact end_contact(const CorePair& p, bool x_is_a, const Axis& axis) {
  const Core &x = x_is_a ? p.a : p.b, &y = x_is_a ? p.b : p.a;
  return Writer{p}.one(x_is_a, x.v[axis.end], y.v[axis.vertex], plane_of(x, axis).normal, axis.s - radii(p),
                       feature_id(FeatureKind::corner_corner, axis.end, axis.vertex));
}

// The contact on the axis of greatest separation; where the two cores' best faces tie to 1e-9 of
// the sum of their reaches, the manifold is A's (as contact_rect_rect keeps it, so that ids hold).
Contact contact_of(const CorePair& p, const Axes& axes, const ContactOptions& options) {
  const bool b_best = axes.b_best();
  const Axis& best = axes.best();
  if (best.face < 0) {
    if (best.s > 0) return nearest_contact(p, nearest_features(p), options);
    return end_contact(p, !b_best, best);
  }
  Contact out = face_contact(p, !b_best, best, options);
  const bool tie =
      b_best && axes.of_a.face >= 0 && axes.of_b.s - axes.of_a.s <= 1e-9 * (p.a.discs.reach + p.b.discs.reach);
  if (!tie || feature_kind(out.manifold[0].id) == FeatureKind::corner_corner) return out;
  const Contact kept = face_contact(p, true, axes.of_a, options);
  if (feature_kind(kept.manifold[0].id) == FeatureKind::corner_corner) return out;
  out.manifold = kept.manifold;
  out.manifold_size = kept.manifold_size;
  return out;
}

// A point of two overlapping segments: where their lines cross, or, in line, the middle of their
// common part.
Vec2 segments_common_point(const Core& x, const Core& y) {
  const Vec2 ex = x.v[1] - x.v[0], ey = y.v[1] - y.v[0];
  const double turn = cross(ey, ex);
  if (turn != 0.0) return y.v[0] + (cross(x.v[0] - y.v[0], ex) / turn) * ey;
  const double length = ex.squaredNorm();
  if (length == 0.0) return x.v[0];  // collapsed by rounding, far from the origin
  const auto at = [&](const Vec2& q) { return std::clamp((q - x.v[0]).dot(ex) / length, 0.0, 1.0); };
  return x.v[0] + ((at(y.v[0]) + at(y.v[1])) / 2) * ex;
}

// Whether p lies in the (sharp) core c, which has faces all round (3 vertices or more).
bool in_core(const Core& c, const Vec2& p) {
  for (int i = 0; i < c.count; ++i) {
    if (c.n[i].dot(p - c.v[i]) > 0.0) return false;
  }
  return true;
}

// A point of both overlapping cores, x the one of more vertices. The mean of the vertices of each
// that lie in the other, a point of both by convexity; where none does (the cores cross), the mean
// of y's core clipped to x's faces (Sutherland–Hodgman), whose points are edges' crossings (left
// for last: two nearly parallel edges cross at a point that rounding slides along them); a point
// core is its own witness. None where rounding clips all of y away (the cores touch).
std::optional<Vec2> common_point(const Core& x, const Core& y) {
  if (y.count == 1) return y.v[0];
  if (x.count == 2) return segments_common_point(x, y);
  Vec2 sum = Vec2::Zero();
  int inside = 0;
  for (int k = 0; k < y.count; ++k) {
    if (in_core(x, y.v[k])) sum += y.v[k], ++inside;
  }
  for (int k = 0; y.count >= 3 && k < x.count; ++k) {
    if (in_core(y, x.v[k])) sum += x.v[k], ++inside;
  }
  if (inside > 0) return sum / inside;
  std::array<Vec2, 2 * kMaxPolygonVertices> poly{}, next{};
  int size = y.count;
  std::copy(y.v.begin(), y.v.begin() + size, poly.begin());
  for (int i = 0; i < x.faces() && size > 0; ++i) {
    int out = 0;
    for (int k = 0; k < size; ++k) {
      const Vec2 &p = poly[k], &q = poly[(k + 1) % size];
      const double dp = x.n[i].dot(p - x.v[i]), dq = x.n[i].dot(q - x.v[i]);
      if (dp <= 0.0) next[out++] = p;
      if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) next[out++] = p + (dp / (dp - dq)) * (q - p);
    }
    if (y.count == 2) out = std::min(out, 2);  // a segment, closed as a polygon, is cut twice at one point
    size = out, poly = next;
  }
  if (size == 0) return std::nullopt;
  for (int k = 0; k < size; ++k) sum += poly[k];
  return sum / size;
}

// A point of both cores where they touch to rounding: midway between y's deepest point over the
// best face and its foot on the face, or between a segment's end and y's vertex beyond it.
Vec2 touching_point(const CorePair& p, const Axes& axes) {
  const Axis& best = axes.best();
  const Core &x = axes.b_best() ? p.b : p.a, &y = axes.b_best() ? p.a : p.b;
  if (best.face < 0) return (x.v[best.end] + y.v[best.vertex]) / 2;
  const FaceClip c = clip_face(x, best.face, y);
  const Clipped& k = c.count > 0 ? c.kept[0] : c.deep;
  return k.on_y - (k.b / 2) * x.n[best.face];
}

}  // namespace

void set_axes(Core& c) {
  const int faces = c.faces(), axes = c.axes();
  // Every slot in one loop of fixed length, the slots of no face set apart by a select.
  for (int i = 0; i < kMaxPolygonVertices; ++i) {
    const bool face = i < faces;
    const double nx = c.n[i].x(), ny = c.n[i].y();
    c.ax[i] = face ? nx : 0.0, c.ay[i] = face ? ny : 0.0;
    c.ad[i] = face ? nx * c.x[i] + ny * c.y[i] : kInf;  // n.v, as plane_of's
  }
  for (int i = faces; i < axes; ++i) {
    const Plane plane = plane_of(c, Axis{-kInf, -1, i - faces});
    c.ax[i] = plane.normal.x(), c.ay[i] = plane.normal.y(), c.ad[i] = plane.normal.dot(plane.origin);
  }
}

Core core_of(const Rect& r, const Placement& at) {
  const double hx = r.half_extents.x(), hy = r.half_extents.y();
  const Vec2 v[] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  const Vec2 n[] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  return make(4, v, n, 0.0, discs_of(r), at);
}

Core core_of(const ConvexPolygon& p, const Placement& at) {
  const PolygonOutline& o = *p.outline;
  return make(o.count, o.vertices, o.normals, o.radius, discs_of(p), at);
}

Core core_of(const Capsule& c, const Placement& at) {
  const std::array<Vec2, 2> faces = segment_normals();
  const Vec2 n[] = {faces[0], faces[1], {1, 0}, {-1, 0}};
  return make(2, segment_of(c), n, c.radius, discs_of(c), at);
}

// A segment's core is a capsule's of radius 0 from its frame's origin.
Core core_of(const Segment& s, const Placement& at) {
  return make(2, segment_of(s), segment_normals(s), 0.0, discs_of(s), at);
}

Core core_of(const Circle& c, const Placement& at) {
  const Vec2 v[] = {{0, 0}};
  return make(1, v, {}, c.radius, discs_of(c), at);
}

double CorePair::scale() const {
  // Every slot (those past the count repeat a vertex), slot by slot and then as a tree.
  std::array<double, kMaxPolygonVertices> reach;
  for (int i = 0; i < kMaxPolygonVertices; ++i) {
    reach[i] = std::max(std::max(std::abs(a.x[i]), std::abs(a.y[i])), std::max(std::abs(b.x[i]), std::abs(b.y[i])));
  }
  return 2 * tree_fold(reach, [](double l, double r) { return std::max(l, r); }) + a.radius + b.radius;
}

namespace {

// Whether the solids overlap, from the cores' axes and, where those leave it open, their gap (into
// `c`): the one verdict of the overlap test and the distance, so that they agree to the bit.
bool overlapping(const CorePair& p, const Axes& axes, Closest& c) {
  const double s = axes.s();
  if (s <= 0.0) return true;
  if (s > radii(p)) return false;
  c = gap(p, axes);
  return c.squared <= radii(p) * radii(p);
}

}  // namespace

bool core_overlap(const CorePair& p) {
  Closest c;
  return overlapping(p, axes_of(p, radii(p)), c);
}

DistanceResult core_distance(const CorePair& p) {
  const Axes axes = axes_of(p);
  Closest c;
  if (overlapping(p, axes, c)) {
    if (axes.s() <= 0.0) {
      const std::optional<Vec2> w = p.a.count >= p.b.count ? common_point(p.a, p.b) : common_point(p.b, p.a);
      return DistanceResult::touching(p.world_point(w ? *w : touching_point(p, axes)));
    }
    const double t = radii(p) > 0.0 ? p.a.radius / radii(p) : 0.5;
    return DistanceResult::touching(p.world_point(Vec2(c.on_a + t * (c.on_b - c.on_a))));
  }
  if (c.squared == kInf) c = gap(p, axes);
  const LengthAndDirection d = length_and_direction(Vec2(c.on_b - c.on_a));
  return DistanceResult::apart(d.length - radii(p), p.world_point(Vec2(c.on_a + p.a.radius * d.direction)),
                               p.world_point(Vec2(c.on_b - p.b.radius * d.direction)));
}

Contact core_face_contact(const CorePair& p, int i, const ContactOptions& options) {
  const Clipped over = deepest_over_face(p.a, i, p.b);
  if (!(over.b < kInf)) return Contact::beyond(kInf);
  if (over.b - radii(p) > options.max_separation) return Contact::beyond(over.b - radii(p));
  return on_face(p, true, i, over.b, over, clip_face(p.a, i, p.b), options);
}

// With a limit, the axes stop at the first that shows the pair beyond it.
Contact core_contact(const CorePair& p, const ContactOptions& options) {
  if (has_limit(options)) {
    if (const auto gap = discs_beyond(p.b.center, p.a.discs.reach + p.b.discs.reach, options)) {
      return Contact::beyond(*gap);
    }
  }
  const double stop = has_limit(options) ? separation_limit(p.scale(), options) + radii(p) : kInf;
  const Axes axes = axes_of(p, stop);
  // The cores' separation along an axis is at most their distance.
  if (axes.s() > stop) return Contact::beyond(axes.s() - radii(p));
  return limited(options, [&] { return contact_of(p, axes, options); });
}

}  // namespace collide2d::detail
