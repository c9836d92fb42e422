#include "narrowphase/shared/cores/core_pair.h"

#include "narrowphase/shared/lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace collide2d::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

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

// The best axis, or the first beyond `stop`: past it, the caller needs no other (the overlap test,
// whose pair is apart).
Axis best_axis_of(const Core& x, const Core& y, double stop) {
  if (x.axes() == 0) return {};  // a point core has no axis
  const BestAxis best = best_axis(x, y, stop);
  const int faces = x.faces();
  return best.axis < faces ? Axis{best.s, best.axis, 0, best.vertex} : Axis{best.s, -1, best.axis - faces, best.vertex};
}

// Every edge of a core once: a segment's one edge, a point's none.
int edges(const Core& c) { return c.count == 2 ? 1 : c.faces(); }

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

// A point core's one vertex is farthest along every direction.
bool farthest_at(const Core& x, int k, const Vec2& d) {
  return detail::farthest_at(x.v[x.prev(k)], x.v[k], x.v[x.next(k)], d);
}

}  // namespace

Closest nearest_features(const CorePair& p) {
  Closest best;
  vertex_edge(p.a, p.b, true, best);
  vertex_edge(p.b, p.a, false, best);
  if (p.a.count == 1 && p.b.count == 1) best = {(p.b.v[0] - p.a.v[0]).squaredNorm(), p.a.v[0], p.b.v[0], -1, -1, 0, 0};
  return best;
}

Axes axes_of(const CorePair& p, double stop) {
  const Axis of_a = best_axis_of(p.a, p.b, stop);
  return {of_a, of_a.s > stop ? Axis{} : best_axis_of(p.b, p.a, stop)};
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

void set_axes(Core& c) {
  const int faces = c.faces(), axes = c.axes();
  // Every slot in one loop of fixed length, the slots of no face set apart by a select.
  for (int i = 0; i < kMaxPolygonVertices; ++i) {
    const bool face = i < faces;
    const double nx = c.n[i].x(), ny = c.n[i].y();
    c.ax[i] = face ? nx : 0.0, c.ay[i] = face ? ny : 0.0;
    c.ad[i] = face ? nx * c.x[i] + ny * c.y[i] : kInf;  // n.v, as plane_of's
  }
  if (axes == faces) return;
  // A segment's two ends, as plane_of() gives them: slot 2 the first end, facing back along the
  // segment, slot 3 the second, facing on; their offsets written out rather than through a Plane,
  // which the compiler builds in memory.
  const Vec2 e = perp(c.n[0]);
  c.ax[2] = -e.x(), c.ay[2] = -e.y(), c.ad[2] = -e.x() * c.x[0] + -e.y() * c.y[0];
  c.ax[3] = e.x(), c.ay[3] = e.y(), c.ad[3] = e.x() * c.x[1] + e.y() * c.y[1];
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

}  // namespace collide2d::detail
