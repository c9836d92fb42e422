// Two capsules, or a capsule and a segment: the two segments' features found directly, each
// segment's ends in the other's frame (A's segment along x from (-h, 0) to (h, 0); B's from its
// first end along its direction u, its face 0 to the right of u).
// - Apart, the nearest of four candidates: each end of one segment against the other segment (over
//   it, its height; beyond it, the other's nearer end). Two disjoint segments have a nearest pair
//   of points with an end among them, so the nearest candidate names the features.
// - Where the segments meet, the deepest way out lies along a normal of a face of their Minkowski
//   difference, a parallelogram: one of the segments' face normals. The four faces and four ends
//   are the convex cores' separating axes (convex_core.h), taken in the cores' order.
// The manifold is Box2D's (E. Catto, b2ClipPolygons): the incident segment clipped to the reference
// face's side planes, in the face's own coordinates, deeper point first. Where features tie (two
// faces to 1e-9 of the reaches: the segments parallel; an end within the cores' rounding of a
// face's end; an end's axis at the best: the segments in line) or rounding empties the clip, the
// cores' contact decides, with its rules for ties (A's face, the deeper face's normal).
#include "narrowphase/contact/capsule_segment.h"

#include <collide2d/kernels.h>

#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/cores/core_pair.h"
#include "narrowphase/shared/frames/unit_vector.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace collide2d {
namespace detail {
namespace {

// B's segment in A's frame: its first end, its unit direction, its second end, its length; its
// radius and reach (Discs).
struct Placed {
  Vec2 q0, u, q1;
  double length, radius, reach;
};

Placed placed(const Capsule& b, const Placement& at) {
  const Vec2 u(at.rot.c, at.rot.s), half = b.half_length * u;
  return {at.offset - half, u, at.offset + half, 2 * b.half_length, b.radius, discs_of(b).reach};
}

Placed placed(const Segment& b, const Placement& at) {
  const double length = b.end.norm();
  return {at.offset, at.direction(Vec2(b.end / length)), at.point(b.end), length, 0.0, discs_of(b).reach};
}

// One segment's two ends in the other's frame: `along` it (A's from its centre, B's from its first
// end) and the height over it (A's up, B's to the left of u).
struct Ends {
  std::array<double, 2> along, height;
};

// The pair: A's pose, half length and radius; B placed; each one's ends in the other's frame; and
// whether the caller gave B first, so that the contact is written B's way round.
struct Pair {
  Rotation<double> rot;
  Vec2 center;
  double h, ra, reach;
  Placed b;
  Ends b_in_a, a_in_b;
  bool swapped;

  double radii() const { return ra + b.radius; }
  Vec2 world_point(const Vec2& p) const { return center + rot.apply(p); }
  Vec2 world_direction(const Vec2& d) const { return rot.apply(d); }
  Vec2 a_end(int k) const { return Vec2(k == 0 ? -h : h, 0.0); }
  Vec2 b_end(int j) const { return j == 0 ? b.q0 : b.q1; }
};

Pair pair_of(const Rotation<double>& rot, const Vec2& center, double h, double ra, double reach, const Placed& b,
             bool swapped) {
  const Vec2 n(b.u.y(), -b.u.x());  // B's face 0's normal, to the right of u
  const double along0 = b.u.dot(b.q0), height0 = n.dot(b.q0);
  const double ax = h * b.u.x(), ay = h * n.x();
  return {rot,
          center,
          h,
          ra,
          reach,
          b,
          {{b.q0.x(), b.q1.x()}, {b.q0.y(), b.q1.y()}},
          {{-ax - along0, ax - along0}, {ay + height0, height0 - ay}},
          swapped};
}

// A reference face in the world: its first vertex, its unit direction and outward normal; its
// length; and the incident segment's ends in the face's coordinates (along it from the first
// vertex, the height over its line), in the order of the cores' clip: from the end of the incident
// face most opposed to the reference, the second end first where u.x leans along the face.
struct Face {
  Vec2 origin, t, n;
  double length;
  std::array<double, 2> a, b;
  std::array<int, 2> id;
};

// The incident ends' coordinates, in the clip's order.
template <class Along, class Height>
void set_ends(Face& f, bool second_first, Along along, Height height) {
  const int first = second_first ? 1 : 0;
  f.a = {along(first), along(1 - first)};
  f.b = {height(first), height(1 - first)};
  f.id = {first, 1 - first};
}

// Face i of A: face 0 faces right of A's direction (-y in its frame) from its first end, face 1
// left from its second.
Face face_of_a(const Pair& p, int i) {
  const double sign = i == 0 ? 1.0 : -1.0;
  const Vec2 axis(p.rot.c, p.rot.s);  // A's direction in the world
  Face f{p.center - sign * p.h * axis, sign * axis, sign * Vec2(axis.y(), -axis.x()), 2 * p.h, {}, {}, {}};
  set_ends(
      f, sign * p.b.u.x() > 0.0, [&](int j) { return p.h + sign * p.b_in_a.along[j]; },
      [&](int j) { return -sign * p.b_in_a.height[j]; });
  return f;
}

// Face i of B: face 0 faces right of u from its first end, face 1 left from its second.
Face face_of_b(const Pair& p, int i) {
  const double sign = i == 0 ? 1.0 : -1.0;
  const Vec2 u = p.world_direction(p.b.u);
  Face f{p.world_point(p.b_end(i)), sign * u, sign * Vec2(u.y(), -u.x()), p.b.length, {}, {}, {}};
  set_ends(
      f, sign * p.b.u.x() > 0.0, [&](int k) { return i == 0 ? p.a_in_b.along[k] : p.b.length - p.a_in_b.along[k]; },
      [&](int k) { return -sign * p.a_in_b.height[k]; });
  return f;
}

// A point of the incident segment in the face's coordinates, and its feature number (an end's
// index, or a cut by a side plane).
struct Point {
  double a, b;
  int id;
};

// The incident segment clipped to the face's side planes, deeper first; count 0 where it lies
// wholly beyond one plane. Both ends are clipped with selects: which end lies beyond is a coin toss.
struct Clip {
  std::array<Point, 2> kept;
  int count;
};
Clip clip(const Face& f) {
  std::array<Point, 2> kept;
  for (int e = 0; e < 2; ++e) {
    const double a = f.a[e], limit = std::clamp(a, 0.0, f.length);
    const double cut = height_at(limit, a, f.b[e], f.a[1 - e], f.b[1 - e]);
    kept[e] = limit == a ? Point{a, f.b[e], f.id[e]} : Point{limit, cut, a < 0.0 ? kCutAtStart : kCutAtEnd};
  }
  const bool beyond = (f.a[0] < 0.0 && f.a[1] < 0.0) || (f.a[0] > f.length && f.a[1] > f.length);
  const bool swap = kept[1].b < kept[0].b;
  return {{swap ? kept[1] : kept[0], swap ? kept[0] : kept[1]}, beyond ? 0 : 2};
}

// The contact on face i of x (A's if XIsA, else B's), the segments' separation s along its
// normal: `main` its main point, the clip its manifold; written the caller's way round, x the
// caller's A or B.
template <bool XIsA>
Contact on_face(const Pair& p, const Face& f, int i, double s, const Point& main, const Clip& c,
                const ContactOptions& options) {
  const double rx = XIsA ? p.ra : p.b.radius, ry = XIsA ? p.b.radius : p.ra, radii = rx + ry;
  const bool x_first = XIsA != p.swapped;
  const FeatureKind kind = x_first ? FeatureKind::face_of_a : FeatureKind::face_of_b;
  const auto point = [&](const Point& q) {
    const Vec2 foot = f.origin + q.a * f.t;
    const Vec2 on_x = foot + rx * f.n, on_y = foot + (q.b - ry) * f.n;
    return ContactPoint{x_first ? on_x : on_y, x_first ? on_y : on_x, q.b - radii, feature_id(kind, i, q.id)};
  };
  const ContactPoint first = point(main);
  const Point& deep = c.kept[0];
  Contact out = Contact::of(s - radii, x_first ? f.n : Vec2(-f.n), first.point_a, first.point_b, first.id);
  out.manifold[0] = deep.id == main.id && deep.a == main.a && deep.b == main.b ? first : point(deep);
  const double keep = std::max(out.separation, 0.0) + options.margin;
  if (c.kept[1].b - radii <= keep) {
    out.manifold[1] = point(c.kept[1]);
    out.manifold_size = 2;
  }
  return out;
}

// A contact this kernel leaves to the cores' (its manifold size -1).
Contact undecided() {
  Contact c;
  c.manifold_size = -1;
  return c;
}

// The ends k of A and j of B, nearest, written the caller's way round.
Contact corner(const Pair& p, int k, int j) {
  const Vec2 on_a = p.a_end(k), on_b = p.b_end(j);
  const LengthAndDirection u = length_and_direction(Vec2(on_b - on_a));
  const Vec2 a = p.world_point(Vec2(on_a + p.ra * u.direction)),
             b = p.world_point(Vec2(on_b - p.b.radius * u.direction));
  const Vec2 normal = p.world_direction(u.direction);
  const double separation = u.length - p.radii();
  if (p.swapped) return Contact::of(separation, -normal, b, a, feature_id(FeatureKind::corner_corner, j, k));
  return Contact::of(separation, normal, a, b, feature_id(FeatureKind::corner_corner, k, j));
}

double square(double x) { return x * x; }

// The rounding the cores allow for on the pair's scale (face_rounding()).
double rounding_of(const Pair& p) {
  const double extent =
      std::max({p.h, std::abs(p.b.q0.x()), std::abs(p.b.q0.y()), std::abs(p.b.q1.x()), std::abs(p.b.q1.y())});
  return face_rounding(pair_scale(extent, p.radii()));
}

// An end's squared distance from the other segment, its ends' `along` coordinates lo and hi.
double squared_from(double along, double height, double lo, double hi) {
  return square(along - std::clamp(along, lo, hi)) + square(height);
}

// The contact of an end over the other segment's face: B's end `end` over A's face (OnA), or A's
// over B's.
template <bool OnA>
Contact over(const Pair& p, int end, const ContactOptions& options) {
  const int i = (OnA ? p.b_in_a : p.a_in_b).height[end] < 0.0 ? 0 : 1;
  const Face f = OnA ? face_of_a(p, i) : face_of_b(p, i);
  const int e = f.id[0] == end ? 0 : 1;
  return on_face<OnA>(p, f, i, f.b[e], {f.a[e], f.b[e], end}, clip(f), options);
}

// The four candidates apart: B's ends against A's segment, then A's ends against B's; each one's
// squared distance, and whether its end lies over the other's face.
struct Candidates {
  std::array<double, 4> squared;
  std::array<bool, 4> over;

  // Whether candidate e's end lies over a face as near as `distance`, to the tie of the reaches.
  bool as_near(int e, double distance, double reach) const {
    const double tie = distance + 1e-9 * reach;
    return over[e] && squared[e] <= tie * tie;
  }
};
Candidates candidates_of(const Pair& p) {
  const Ends &b = p.b_in_a, &a = p.a_in_b;
  const auto inside = [&p](double along) { return along > 0.0 && along < p.b.length; };
  return {
      {squared_from(b.along[0], b.height[0], -p.h, p.h), squared_from(b.along[1], b.height[1], -p.h, p.h),
       squared_from(a.along[0], a.height[0], 0.0, p.b.length), squared_from(a.along[1], a.height[1], 0.0, p.b.length)},
      {std::abs(b.along[0]) <= p.h, std::abs(b.along[1]) <= p.h, inside(a.along[0]), inside(a.along[1])}};
}

// The greatest separation along a segment's two faces of the other's ends.
double best_face(const Ends& other) {
  return std::max(-std::max(other.height[0], other.height[1]), std::min(other.height[0], other.height[1]));
}

// Candidate `best`, an end over the other segment's face, at `distance`; undecided where the other
// segment's face comes as near, to the tie (the segments parallel): the cores' rules for ties keep
// the deeper face's normal and A's manifold.
Contact end_over_face(const Pair& p, const Candidates& c, int best, double distance, const ContactOptions& options) {
  if (best_face(best < 2 ? p.a_in_b : p.b_in_a) >= distance - 1e-9 * p.reach) return undecided();
  if (best < 2) return over<true>(p, best, options);
  const bool b_end_as_near = c.as_near(0, distance, p.reach) || c.as_near(1, distance, p.reach);
  return b_end_as_near ? undecided() : over<false>(p, best - 2, options);
}

// Candidate `best`, two ends, at `distance`; undecided where a face comes as near, to the tie, or
// where an end lies within the cores' rounding of over a face (beyond a face's end by d, it has a
// point of its segment over the face a further d^2 / 2s away at the least, s the separation), as the
// cores then keep the face.
Contact two_ends(const Pair& p, const Candidates& c, int best, double distance) {
  const Ends &b = p.b_in_a, &a = p.a_in_b;
  const int k = best < 2 ? (b.along[best] > 0.0 ? 1 : 0) : best - 2;
  const int j = best < 2 ? best : (a.along[k] > 0.0 ? 1 : 0);
  const double room = 8 * rounding_of(p) * distance;
  const auto close = [room](double d) { return d <= 0.0 || d * d <= room; };
  for (int e = 0; e < 4; ++e) {
    if (c.as_near(e, distance, p.reach)) return undecided();
  }
  if (close(std::abs(b.along[j]) - p.h) || close(j == 1 ? a.along[k] - p.b.length : -a.along[k])) return undecided();
  return corner(p, k, j);
}

// The segments apart: the nearest candidate's contact.
Contact apart(const Pair& p, const ContactOptions& options) {
  const Candidates c = candidates_of(p);
  int best = 0;
  for (int e = 1; e < 4; ++e) best = c.squared[e] < c.squared[best] ? e : best;
  const double distance = std::sqrt(c.squared[best]);
  if (distance - p.radii() > options.max_separation) return Contact::beyond(distance - p.radii());
  return c.over[best] ? end_over_face(p, c, best, distance, options) : two_ends(p, c, best, distance);
}

// The first greatest of four separations, as the cores' axes pick it.
int first_greatest(const std::array<double, 4>& s) {
  int k = 0;
  for (int i = 1; i < 4; ++i) k = s[i] > s[k] ? i : k;
  return k;
}

// The segments meet: the contact on the best face; undecided where an end's axis is the best.
Contact crossing(const Pair& p, const ContactOptions& options) {
  const Ends &b = p.b_in_a, &a = p.a_in_b;
  const auto least = [](const std::array<double, 2>& v) { return std::min(v[0], v[1]); };
  const auto most = [](const std::array<double, 2>& v) { return std::max(v[0], v[1]); };
  const std::array<double, 4> of_a{-most(b.height), least(b.height), -most(b.along) - p.h, least(b.along) - p.h};
  const std::array<double, 4> of_b{-most(a.height), least(a.height), -most(a.along), least(a.along) - p.b.length};
  const int ia = first_greatest(of_a), ib = first_greatest(of_b);
  const bool b_best = of_b[ib] > of_a[ia];
  const int i = b_best ? ib : ia;
  const double s = b_best ? of_b[ib] : of_a[ia];
  if (i >= 2 || s > 0.0) return undecided();
  // B's face deeper by less than the tie: the cores keep its normal and A's manifold.
  if (b_best && ia < 2 && of_b[ib] - of_a[ia] <= 1e-9 * p.reach) return undecided();
  const Face f = b_best ? face_of_b(p, i) : face_of_a(p, i);
  const Clip c = clip(f);
  if (c.count == 0) return undecided();
  if (s - p.radii() > options.max_separation) return Contact::beyond(s - p.radii());
  return b_best ? on_face<false>(p, f, i, s, c.kept[0], c, options) : on_face<true>(p, f, i, s, c.kept[0], c, options);
}

// Whether the segments meet: each one's ends not both strictly on one side of the other's line.
bool meet(const Pair& p) {
  const auto straddle = [](const std::array<double, 2>& h) {
    return !(h[0] > 0.0 && h[1] > 0.0) && !(h[0] < 0.0 && h[1] < 0.0);
  };
  return straddle(p.b_in_a.height) && straddle(p.a_in_b.height);
}

}  // namespace

template <class B>
Contact capsule_segment_direct(const Capsule& a, const Orientation& ao, const B& b, const Orientation& bo,
                               const ContactOptions& options, bool swapped) {
  const Rotation<double> frame = Rotation<double>::of(ao);
  const Vec2 offset = Placement::offset_of(b.center, a.center, frame);
  const double reach = discs_of(a).reach + discs_of(b).reach;
  if (has_limit(options)) {
    if (const auto gap = discs_beyond(offset, reach, options)) return Contact::beyond(*gap);
  }
  const Placement at{Rotation<double>::of(bo).relative_to(frame), offset};
  const Pair p = pair_of(frame, a.center, a.half_length, a.radius, reach, placed(b, at), swapped);
  return meet(p) ? crossing(p, options) : apart(p, options);
}

template <class B>
Contact capsule_segment_contact(const Capsule& a, const Orientation& ao, const B& b, const Orientation& bo,
                                const ContactOptions& options, bool swapped) {
  // One named result, so that the kernel writes it in the caller's slot.
  Contact out = capsule_segment_direct(a, ao, b, bo, options, swapped);
  if (out.manifold_size < 0) out = core_contact(a, ao, b, bo, options, swapped);
  return out;
}

template Contact capsule_segment_direct(const Capsule&, const Orientation&, const Capsule&, const Orientation&,
                                        const ContactOptions&, bool);
template Contact capsule_segment_direct(const Capsule&, const Orientation&, const Segment&, const Orientation&,
                                        const ContactOptions&, bool);
template Contact capsule_segment_contact(const Capsule&, const Orientation&, const Capsule&, const Orientation&,
                                         const ContactOptions&, bool);
template Contact capsule_segment_contact(const Capsule&, const Orientation&, const Segment&, const Orientation&,
                                         const ContactOptions&, bool);

}  // namespace detail

Contact contact_capsule_capsule(const Capsule& a, const Orientation& a_orientation, const Capsule& b,
                                const Orientation& b_orientation, const ContactOptions& options) {
  return detail::capsule_segment_contact(a, a_orientation, b, b_orientation, options, false);
}

Contact contact_capsule_capsule(const Capsule& a, const Capsule& b, const ContactOptions& options) {
  return contact_capsule_capsule(a, Orientation::of(a.angle), b, Orientation::of(b.angle), options);
}

}  // namespace collide2d
