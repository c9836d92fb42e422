// Any two convex cores (narrowphase/shared/cores/convex_core.h), where the pair has no kernel of its
// own: the axis of greatest separation and Box2D's manifold on it (E. Catto, b2ClipPolygons), the
// incident face clipped to the reference face's side planes; apart beside the best face, the
// nearest features.
#include "narrowphase/shared/cores/core_pair.h"

#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/frames/unit_vector.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide2d::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The deepest point of core y over face i of core x (between its side planes): a vertex of y there,
// or where an edge of y crosses a side plane; b infinite where y has none. Where the incident face
// lies wholly beyond a side plane, as one of two faces of y nearly in line may, it stands in for
// its deeper end, which lies off the face.
template <class X, class Y>
Clipped deepest_over_face(const X& x, int i, const Y& y) {
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

// Builds contacts in the world from points in A's frame, in the caller's order (CorePairOf::swapped).
template <class P>
struct Writer {
  const P& p;

  // Whether x, core A if x_is_a, is the caller's first shape.
  bool callers_a(bool x_is_a) const { return x_is_a != p.swapped; }
  // A point of y's core and its foot on x's, the normal from x to y.
  ContactPoint point(bool x_is_a, const Vec2& on_x, const Vec2& on_y, const Vec2& normal, double separation,
                     std::uint32_t id) const {
    const double rx = x_is_a ? p.a.radius : p.b.radius, ry = x_is_a ? p.b.radius : p.a.radius;
    const Vec2 x = p.world_point(Vec2(on_x + rx * normal)), y = p.world_point(Vec2(on_y - ry * normal));
    return callers_a(x_is_a) ? ContactPoint{x, y, separation, id} : ContactPoint{y, x, separation, swapped_feature(id)};
  }
  Contact one(bool x_is_a, const Vec2& on_x, const Vec2& on_y, const Vec2& normal, double separation,
              std::uint32_t id) const {
    const ContactPoint c = point(x_is_a, on_x, on_y, normal, separation, id);
    return Contact::of(separation, world_normal(x_is_a, normal), c.point_a, c.point_b, c.id);
  }
  // The normal from x to y in the world, turned where x is not the caller's A.
  Vec2 world_normal(bool x_is_a, const Vec2& normal) const {
    const Vec2 world = p.world_direction(normal);
    return callers_a(x_is_a) ? world : Vec2(-world);
  }
};

// Apart, nearest at two vertices, or at a vertex over an edge found by the vertex–edge search.
template <class P>
Contact nearest_contact(const P& p, const Closest& c, const ContactOptions& options);

// The contact on face i of x (A's if x_is_a): the cores' separation s, its main point `main` (a
// point of y's core and its height over the face), and the manifold from the face's clip `c`.
template <class P>
Contact on_face(const P& p, bool x_is_a, int i, double s, const Clipped& main, const FaceClip& c,
                const ContactOptions& options) {
  const Vec2& n = x_is_a ? p.a.n[i] : p.b.n[i];
  const auto point = [&](const Clipped& k) {
    // As if x were A: Writer renames the features for B.
    return Writer<P>{p}.point(x_is_a, Vec2(k.on_y - k.b * n), k.on_y, n, k.b - radii(p),
                              feature_id(FeatureKind::face_of_a, i, k.id));
  };
  const ContactPoint first = point(main);
  Contact out = Contact::of(s - radii(p), Writer<P>{p}.world_normal(x_is_a, n), first.point_a, first.point_b, first.id);
  out.manifold[0] = first;
  const double keep = std::max(out.separation, 0.0) + options.margin;
  int size = 0;
  for (int k = 0; k < c.count; ++k) {
    const Clipped& q = c.kept[k];
    // The main point is most often a kept one: written once.
    const bool is_main = q.id == main.id && q.b == main.b && q.on_y == main.on_y;
    if (q.b - radii(p) <= keep) out.manifold[size++] = is_main ? first : point(q);
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
template <class P, class X, class Y>
Contact face_contact(const P& p, const X& x, const Y& y, bool x_is_a, const Axis& axis, const ContactOptions& options) {
  const int i = axis.face;
  const double s = axis.s;
  const FaceClip c = clip_face(x, i, y);
  if (s > 0) {
    const Vec2& w = y.v[axis.vertex];
    const int side = side_of(x, i, w);
    if (side == 0) return on_face(p, x_is_a, i, s, {w, s, axis.vertex}, c, options);
    const Closest near = beside_face(p, x_is_a, axis, side);
    const double distance = std::sqrt(near.squared);
    if (c.count == 0 || c.kept[0].b > distance + face_rounding(p.scale())) return nearest_contact(p, near, options);
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

template <class P>
Contact face_contact(const P& p, bool x_is_a, const Axis& axis, const ContactOptions& options) {
  return x_is_a ? face_contact(p, p.a, p.b, true, axis, options) : face_contact(p, p.b, p.a, false, axis, options);
}

template <class P>
Contact nearest_contact(const P& p, const Closest& c, const ContactOptions& options) {
  const double distance = std::sqrt(c.squared);
  // A vertex over an edge: that edge is the reference face (a segment's, the side facing the vertex).
  const auto over = [&](const auto& x, const auto& y, bool x_is_a, int edge, const Vec2& on_x, const Vec2& on_y,
                        int vertex) {
    const int face = x.count == 2 && x.n[edge].dot(on_y - on_x) < 0 ? 1 - edge : edge;
    return on_face(p, x_is_a, face, distance, Clipped{on_y, distance, vertex}, clip_face(x, face, y), options);
  };
  if (c.a_edge >= 0) return over(p.a, p.b, true, c.a_edge, c.on_a, c.on_b, c.b_vertex);
  if (c.b_edge >= 0) return over(p.b, p.a, false, c.b_edge, c.on_b, c.on_a, c.a_vertex);
  const LengthAndDirection d = length_and_direction(Vec2(c.on_b - c.on_a));
  return Writer<P>{p}.one(true, c.on_a, c.on_b, d.direction, d.length - radii(p),
                          feature_id(FeatureKind::corner_corner, c.a_vertex, c.b_vertex));
}

// A segment's end axis at the best: the segment x and a point or a parallel segment y in line.
template <class P>
Contact end_contact(const P& p, bool x_is_a, const Axis& axis) {
  const auto on = [&](const auto& x, const auto& y) {
    return Writer<P>{p}.one(x_is_a, x.v[axis.end], y.v[axis.vertex], plane_of(x, axis).normal, axis.s - radii(p),
                            feature_id(FeatureKind::corner_corner, axis.end, axis.vertex));
  };
  return x_is_a ? on(p.a, p.b) : on(p.b, p.a);
}

// The contact on the best face; where the two cores' best faces tie to 1e-9 of the sum of their
// reaches, the manifold is A's (as contact_rect_rect keeps it, so that ids hold). Every return is
// the one named contact, so that it is built in the caller's slot rather than moved there.
template <class P>
Contact best_face_contact(const P& p, const Axes& axes, const ContactOptions& options) {
  const bool b_best = axes.b_best();
  Contact out = face_contact(p, !b_best, axes.best(), options);
  const bool tie =
      b_best && axes.of_a.face >= 0 && axes.of_b.s - axes.of_a.s <= 1e-9 * (p.a.discs.reach + p.b.discs.reach);
  if (!tie || feature_kind(out.manifold[0].id) == FeatureKind::corner_corner) return out;
  const Contact kept = face_contact(p, true, axes.of_a, options);
  if (feature_kind(kept.manifold[0].id) == FeatureKind::corner_corner) return out;
  out.manifold = kept.manifold;
  out.manifold_size = kept.manifold_size;
  return out;
}

// The contact on the axis of greatest separation.
template <class P>
Contact contact_of(const P& p, const Axes& axes, const ContactOptions& options) {
  const Axis& best = axes.best();
  if (best.face >= 0) return best_face_contact(p, axes, options);
  if (best.s > 0) return nearest_contact(p, nearest_features(p), options);
  return end_contact(p, !axes.b_best(), best);
}

}  // namespace

template <class X, class Y>
Contact core_face_contact(const CorePairOf<X, Y>& p, int i, const ContactOptions& options) {
  const Clipped over = deepest_over_face(p.a, i, p.b);
  if (!(over.b < kInf)) return Contact::beyond(kInf);
  if (over.b - radii(p) > options.max_separation) return Contact::beyond(over.b - radii(p));
  return on_face(p, true, i, over.b, over, clip_face(p.a, i, p.b), options);
}

// With a limit, the axes stop at the first that shows the pair beyond it.
template <class X, class Y>
Contact core_contact(const CorePairOf<X, Y>& p, const ContactOptions& options) {
  const double stop = has_limit(options) ? separation_limit(p.scale(), options) + radii(p) : kInf;
  const Axes axes = axes_of(p, stop);
  // The cores' separation along an axis is at most their distance.
  if (axes.s() > stop) return Contact::beyond(axes.s() - radii(p));
  return limited(options, [&] { return contact_of(p, axes, options); });
}

template Contact core_contact(const CorePairOf<Core, Core>&, const ContactOptions&);
template Contact core_contact(const CorePairOf<Core, SegmentCore>&, const ContactOptions&);
template Contact core_contact(const CorePairOf<SegmentCore, Core>&, const ContactOptions&);
template Contact core_contact(const CorePairOf<SegmentCore, SegmentCore>&, const ContactOptions&);
template Contact core_contact(const CorePairOf<OwnFrameCore<Rect>, SegmentCore>&, const ContactOptions&);
template Contact core_contact(const CorePairOf<OwnFrameCore<Rect>, Core>&, const ContactOptions&);
template Contact core_contact(const CorePairOf<OwnFrameCore<ConvexPolygon>, SegmentCore>&, const ContactOptions&);
template Contact core_contact(const CorePairOf<OwnFrameCore<ConvexPolygon>, Core>&, const ContactOptions&);
template Contact core_face_contact(const CorePairOf<SegmentCore, Core>&, int, const ContactOptions&);
template Contact core_face_contact(const CorePairOf<SegmentCore, SegmentCore>&, int, const ContactOptions&);

}  // namespace collide2d::detail
