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

// The shape's separation from the line through q of unit normal u (a circle's without the square
// root its support point takes).
template <class B>
double separation_along(const B& shape, const Orientation& o, const Vec2& u, const Vec2& q) {
  if constexpr (std::is_same_v<B, Circle>) {
    return u.dot(shape.center - q) - shape.radius;
  } else {
    return u.dot(detail::support(shape, Rot::of(o), Vec2(-u)) - q);
  }
}

// Whether no convex neighbour's line lies farther from the shape than the segment's, beyond the
// rounding of the separations. They are measured in the world, from points a segment and its
// neighbour each round on their own, so the slack is of the coordinates' size: with less, where a
// chain's points in line carry their rounding (turns of 1e-14 rad at 1000 from the origin), both
// segments at a vertex could give the body to the other.
template <class B>
bool owns(const Faces& f, const B& shape, const Orientation& o, const Vec2& r) {
  if (!f.convex1 && !f.convex2) return true;
  const double own = separation_along(shape, o, f.n, f.p1);
  const double scale = f.p1.cwiseAbs().maxCoeff() + r.cwiseAbs().maxCoeff() + detail::reach(shape) + f.length;
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
  if (!owns(f, b, bo, r)) return Contact::beyond(kInf);
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

// A circle whose centre, c in the segment's frame, lies in front. On the segment's front face the
// centre lies over the segment, in front of it. A convex neighbour's normal is the segment's turned
// by the vertex's angle t away from the segment, so the centre's height along it is cos t times its
// height over the segment less sin t times its distance from the vertex along the segment: never
// more, and the neighbour leaves it to the segment (owns()); the normal is the segment's
// (admitted()). One named result, built in the caller's slot.
Contact circle_in_front(const ChainSegment& a, const Orientation& ao, const Vec2& c, const Circle& b,
                        const Orientation& bo, const ContactOptions& options) {
  Contact result = detail::core_circle_at(a.segment, detail::SegmentView(a.segment).view(), ao, c, b, options);
  if (!result.empty() && result.manifold[0].id != feature_id(FeatureKind::face_of_a, 0, 0)) {
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
