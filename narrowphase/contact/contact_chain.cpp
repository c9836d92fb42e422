// A chain segment against any shape: the segment's exact contact, under the one-sided, shared-vertex
// and smooth rules of include/collide2d/chain.h. The rules follow E. Catto's ghost-collision
// treatment in Box2D v3 ("Ghost Collisions", box2d.org, 2020): the shape's centre decides the side,
// separating axes decide which of two segments owns the space around a convex vertex, and a normal
// outside the vertex cones gives way to the segment's own.
#include <collide2d/chain.h>

#include <collide2d/kernels.h>
#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/contact/core_circle.h"
#include "narrowphase/pairs.h"
#include "narrowphase/shared/cores/convex_core.h"
#include "shapes/internal.h"
#include "shapes/kinds.h"

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <variant>

namespace collide2d {
namespace {

using detail::cross;
using Rot = detail::Rotation<double>;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
// How far past a cone's edge a normal may lie and still be in it: the rounding of unit normals.
constexpr double kTurn = 64 * kEpsilon;

Vec2 right_of(const Vec2& d) { return {d.y(), -d.x()}; }

// The chain segment in the world: its points, its unit normal n (its direction turned clockwise,
// towards the side it collides from) and direction e, and at each end whether the vertex is convex
// and the neighbour's unit normal there (read only at a convex vertex).
struct Faces {
  Vec2 p1, p2, n, n0, n2, e;
  bool convex1 = false, convex2 = false;
  double length = 0.0;
};

Faces faces_of(const ChainSegment& s, const Orientation& o) {
  const Vec2& end = s.segment.end;
  const Vec2 in = -s.ghost1, out = s.ghost2 - end;  // the neighbours' directions, in the segment's frame
  Faces f;
  f.p1 = s.segment.center;
  const Rot rot = Rot::of(o);
  const Vec2 d = rot.apply(end);
  f.p2 = f.p1 + d;
  f.length = end.norm();
  f.n = right_of(d) / f.length;
  f.e = Vec2(-f.n.y(), f.n.x());
  f.convex1 = cross(in, end) > 0.0;
  f.convex2 = cross(end, out) > 0.0;
  if (f.convex1) f.n0 = right_of(rot.apply(in)).normalized();
  if (f.convex2) f.n2 = right_of(rot.apply(out)).normalized();
  return f;
}

// The point whose side decides: a shape's centre, a polygon's centroid (its centre may lie outside).
template <class B>
Vec2 reference_point(const B& shape, const Orientation& o) {
  if constexpr (std::is_same_v<B, ConvexPolygon>) {
    return shape.center + Rot::of(o).apply(shape.outline->centroid);
  } else {
    return shape.center;
  }
}

// Whether the point r, given in the segment's frame from its first point, lies in front of the
// segment or of a convex neighbour's line: read in the segment's own frame, where the neighbours'
// directions are given, so that no rotation precedes the test that turns half the pairs away.
bool in_front(const ChainSegment& s, const Vec2& r) {
  const Vec2& end = s.segment.end;
  const Vec2 in = -s.ghost1, out = s.ghost2 - end;
  return right_of(end).dot(r) >= 0.0 || (cross(in, end) > 0.0 && right_of(in).dot(r) >= 0.0) ||
         (cross(end, out) > 0.0 && right_of(out).dot(Vec2(r - end)) >= 0.0);
}

// The same for a point r in the world, the segment posed by o.
bool in_front(const ChainSegment& s, const Orientation& o, const Vec2& r) {
  return in_front(s, Rot::of(o).apply_inverse(Vec2(r - s.segment.center)));
}

// The shape's separation from the line through q of unit normal u: its centre's height less its
// support function along -u.
template <class B>
double separation_along(const B& shape, const Orientation& o, const Vec2& u, const Vec2& q) {
  return u.dot(shape.center - q) - detail::support_along(shape, Rot::of(o).apply_inverse(Vec2(-u)));
}

// The scale of the separations that decide which segment, of length `length`, owns a shape of
// reference point r (in the world) and reach `reach`: a segment and its neighbour each round their
// points on their own, so it is of the world coordinates' size. With less, where a chain's points in
// line carry their rounding (turns of 1e-14 rad at 1000 from the origin), both segments at a vertex
// could give the body to the other.
double owning_scale(const ChainSegment& s, const Vec2& r, double reach, double length) {
  return s.segment.center.cwiseAbs().maxCoeff() + r.cwiseAbs().maxCoeff() + reach + length;
}

// Whether no convex neighbour's line lies farther from the shape than the segment's, beyond the
// rounding of the separations at `scale` (owning_scale()).
template <class B>
bool owns(const Faces& f, const B& shape, const Orientation& o, double scale) {
  if (!f.convex1 && !f.convex2) return true;
  const double own = separation_along(shape, o, f.n, f.p1);
  const double slack = 64 * kEpsilon * scale;
  return !(f.convex1 && separation_along(shape, o, f.n0, f.p1) > own + slack) &&
         !(f.convex2 && separation_along(shape, o, f.n2, f.p2) > own + slack);
}

// Whether n lies in the closed cone from `from` counter-clockwise to `to`.
bool within(const Vec2& from, const Vec2& n, const Vec2& to) {
  return cross(from, n) >= -kTurn && cross(n, to) >= -kTurn;
}

// Whether n is the segment's normal or lies in the cone of the convex vertex it leans towards (a
// cone of a sharp vertex spans more than a quarter turn, past the segment's direction).
bool admitted(const Faces& f, const Vec2& n) {
  const bool front = n.dot(f.n) > 0.0;
  if (n.dot(f.e) >= 0.0) return f.convex2 ? within(f.n, n, f.n2) : front && cross(f.n, n) <= kTurn;
  return f.convex1 ? within(f.n0, n, f.n) : front && cross(n, f.n) <= kTurn;
}

// A curved shape's contact along the segment's normal: its support point q along -n, where it lies
// over the segment.
Contact held_at(const Faces& f, const Vec2& q, const ContactOptions& options) {
  const Vec2 from1 = q - f.p1;
  const double along = f.e.dot(from1);
  if (!(along >= 0.0 && along <= f.length)) return Contact::beyond(kInf);
  const double s = f.n.dot(from1);
  return detail::limited(options, [&] { return Contact::of(s, f.n, Vec2(q - s * f.n), q); });
}

// The contact with the segment's normal held: the shape's deepest points over the segment.
template <class B>
Contact held(const ChainSegment& a, const Orientation& ao, const Faces& f, const B& b, const Orientation& bo,
             const ContactOptions& options) {
  if constexpr (std::is_same_v<B, Circle> || std::is_same_v<B, Ellipse>) {
    return held_at(f, detail::support(b, Rot::of(bo), Vec2(-f.n)), options);
  } else {
    return detail::core_face_contact(detail::core_pair(a.segment, ao, b, bo), 0, options);
  }
}

// The contact c of the segment, which is not empty and not on the segment's front face, under the
// rules at its vertices; r is the shape's reference point.
template <class B>
Contact at_a_vertex(const ChainSegment& a, const Orientation& ao, const B& b, const Orientation& bo, const Vec2& r,
                    const Contact& c, const ContactOptions& options) {
  const Faces f = faces_of(a, ao);
  if (!owns(f, b, bo, owning_scale(a, r, detail::reach(b), f.length))) return Contact::beyond(kInf);
  if (admitted(f, c.normal)) return c;
  const Contact h = held(a, ao, f, b, bo, options);
  // Apart, a shape's points over the segment lie in front of it, or all behind it where the shape
  // comes round from the back (a sliver whose centre is in front beyond the segment's end): none.
  if (c.separation > 0 && !(h.separation >= 0)) return Contact::beyond(kInf);
  return h;
}

template <class B>
Contact contact_of_kind(const ChainSegment& a, const Orientation& ao, const B& b, const Orientation& bo,
                        const ContactOptions& options) {
  const Vec2 r = reference_point(b, bo);
  if (!in_front(a, ao, r)) return Contact::beyond(kInf);
  // The segment's contact first: with a limit it ends soonest for the pairs apart.
  const Contact c = detail::contact_of_kinds<detail::Kinds>(a.segment, ao, b, bo, options);
  if (c.empty()) return c;
  return at_a_vertex(a, ao, b, bo, r, c, options);
}

// The rules at an end of the segment for a circle whose centre c (in the segment's frame, from its
// first point) lies beyond that end (1 or 2) in front of the segment's line, at height h over it:
// its contact is at that end, along d, c's offset from it. owns() and admitted() as a circle reads
// them in the segment's frame, where it needs no turning, squared where they divide by a length:
// no convex neighbour's line, of direction w, lies farther from c than the segment's, (right of w)
// . x / |w| <= h + slack; at a convex end the normal lies in the vertex's cone, d not past the
// neighbour's direction away from the end (w . d <= kTurn |w| |d|); at a concave end it is the
// segment's normal. A normal not admitted leaves none: the circle's deepest point over the segment
// lies beyond the same end. Out of line: inlined, it weighs on the pairs that never come to it.
[[gnu::noinline]] bool circle_kept_at(const ChainSegment& a, const detail::SegmentView& view, const Vec2& c,
                                      const Circle& b, int end) {
  const Vec2& p2 = a.segment.end;
  const double h = view.normals[0].dot(c);
  const Vec2 in = -a.ghost1, out = a.ghost2 - p2;
  const bool convex1 = cross(in, p2) > 0.0, convex2 = cross(p2, out) > 0.0;
  const double bound = h + 64 * kEpsilon * owning_scale(a, b.center, b.radius, view.reach);
  const auto nearer = [&](const Vec2& w, const Vec2& x) {
    const double s = right_of(w).dot(x);
    return !(s > 0.0 && s * s > bound * bound * w.squaredNorm());
  };
  if ((convex1 && !nearer(in, c)) || (convex2 && !nearer(out, Vec2(c - p2)))) return false;
  const Vec2 d = end == 1 ? c : Vec2(c - p2);
  const double turn = kTurn * kTurn * d.squaredNorm();
  if (end == 1 ? convex1 : convex2) {
    const Vec2& w = end == 1 ? a.ghost1 : out;
    const double t = w.dot(d);
    return !(t > 0.0 && t * t > turn * w.squaredNorm());
  }
  const double along = view.normals[2].dot(d);
  return h > 0.0 && along * along <= turn;
}

// The end (1 or 2) that a circle's centre c (in the segment's frame, from its first point) lies
// beyond, in front of the segment's line, where the circle's contact at that end lies within the
// limit; else 0. Read without the unit normal that core_circle_at() divides out, so by a margin of
// the rounding between the two readings and of the world's coordinates (at_a_vertex() reads the
// centre's place along the segment there): where core_circle_at() too finds c past that end (its
// front face leading, then along_face()), and no rounding could put it over the segment.
int end_ruled(const ChainSegment& a, const Vec2& c, const Circle& b, const ContactOptions& options) {
  const Vec2& p2 = a.segment.end;
  const double at = p2.dot(c), height = right_of(p2).dot(c), last = p2.squaredNorm();
  const int end = !(height > 0.0) ? 0 : at < 0.0 ? 1 : at > last ? 2 : 0;
  if (end == 0 || detail::may_pass_limit(end == 1 ? c : Vec2(c - p2), b.radius, options)) return 0;
  const Vec2 size = p2.cwiseAbs();
  const double world = a.segment.center.cwiseAbs().maxCoeff() + b.center.cwiseAbs().maxCoeff();
  const double margin = 8 * kEpsilon * size.sum() * (c.cwiseAbs().sum() + size.sum() + world);
  return height > margin && (end == 1 ? at < -margin : at > last + margin) ? end : 0;
}

// A circle whose centre, c in the segment's frame, lies in front. On the segment's front face the
// centre lies over the segment, in front of it. A convex neighbour's normal is the segment's turned
// by the vertex's angle t away from the segment, so the centre's height along it is cos t times its
// height over the segment less sin t times its distance from the vertex along the segment: never
// more, and the neighbour leaves it to the segment (owns()); the normal is the segment's
// (admitted()). Beyond an end (end_ruled()), the rules decide before the contact is made, which
// they spare for most such pairs; elsewhere the limit turns most pairs away first, and the rules
// follow a contact found. One named result, built in the caller's slot.
Contact circle_in_front(const ChainSegment& a, const Orientation& ao, const Vec2& c, const Circle& b,
                        const Orientation& bo, const ContactOptions& options) {
  const int end = end_ruled(a, c, b, options);
  const detail::SegmentView view(a.segment);
  Contact result = end != 0 && !circle_kept_at(a, view, c, b, end)
                       ? Contact::beyond(kInf)
                       : detail::core_circle_at(a.segment, view.view(), ao, c, b, options);
  if (!result.empty() && end == 0 && result.manifold[0].id != feature_id(FeatureKind::face_of_a, 0, 0)) {
    result = at_a_vertex(a, ao, b, bo, b.center, result, options);
  }
  return result;
}

// A circle: its centre placed in the segment's frame once, for the side and for the segment's kernel.
Contact contact_of_kind(const ChainSegment& a, const Orientation& ao, const Circle& b, const Orientation& bo,
                        const ContactOptions& options) {
  const Vec2 c = Rot::of(ao).apply_inverse(Vec2(b.center - a.segment.center));
  return in_front(a, c) ? circle_in_front(a, ao, c, b, bo, options) : Contact::beyond(kInf);
}

}  // namespace

bool in_front(const ChainSegment& s, const Shape& shape) {
  const Vec2 r = std::visit([](const auto& x) { return reference_point(x, detail::orientation_of(x)); }, shape);
  return in_front(s, Orientation::of(s.segment.angle), r);
}

Contact contact(const ChainSegment& a, const Orientation& ao, const Shape& b, const Orientation& bo,
                const ContactOptions& options) {
  return std::visit([&](const auto& x) { return contact_of_kind(a, ao, x, bo, options); }, b);
}

Contact contact(const ChainSegment& a, const Shape& b, const ContactOptions& options) {
  validate(a);
  validate(b);
  detail::validate(options);
  if (detail::is_level_geometry(b)) {
    throw UnsupportedPair(std::string("a chain segment does not pair with a ") + shape_name(b) +
                          ": both are level geometry");
  }
  return contact(a, Orientation::of(a.segment.angle), b, Orientation::of(angle_of(b)), options);
}

}  // namespace collide2d
