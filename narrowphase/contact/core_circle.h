// Private: a convex core of one to eight faces against a circle, the contact that the polygon,
// capsule, segment and chain segment pairs with a circle share (contact_polygon_circle.cpp,
// contact_capsule_circle.cpp, contact_segment_circle.cpp, contact_chain.cpp), each instantiating it
// for its core.
#pragma once

#include <collide2d/kernels.h>

#include "narrowphase/contact/contact_limit.h"
#include "narrowphase/shared/cores/convex_core.h"
#include "narrowphase/shared/frames/unit_vector.h"

#include <algorithm>
#include <array>

namespace collide2d::detail {

// The core as the kernel reads it: Slots faces, those past the count copies of the first.
template <int Slots>
struct CoreView {
  const Vec2* vertices;
  const Vec2* normals;
  const double* offsets;
  int count;
  double radius;
  double reach;
};

// A segment's core: from its frame's origin to its end, its faces' lines through the origin.
struct SegmentView {
  std::array<Vec2, 2> ends;
  std::array<Vec2, 4> normals;  // the faces' two first
  double reach;
  static constexpr std::array<double, 2> kOffsets{};

  explicit SegmentView(const Segment& s) : ends(segment_of(s)), normals(segment_normals(s)), reach(discs_of(s).reach) {}
  CoreView<2> view() const { return {ends.data(), normals.data(), kOffsets.data(), 2, 0.0, reach}; }
};

// The face of greatest separation s of point c (the first of equals), as a tree of selects
// (tree_fold): which face leads is a coin toss.
struct Lead {
  double s;
  int face;
};

// Inlined into each kernel, which the compiler stops doing once two kinds share it: the call out of
// line then weighs on the capsule's and segment's contacts (bench_contact's circle rows).
template <int Slots>
[[gnu::always_inline]] inline Lead leading_face(const Vec2* normals, const double* offsets, const Vec2& c) {
  std::array<Lead, Slots> lead;
  for (int i = 0; i < Slots; ++i) lead[i] = {normals[i].dot(c) - offsets[i], i};  // as the cores' axes
  return tree_fold(lead, [](const Lead& l, const Lead& r) {
    return Lead{std::max(l.s, r.s), r.s > l.s ? r.face : l.face};
  });
}

// Out of line: the cores take a large frame that the common paths do without.
template <class A>
[[gnu::noinline]] Contact contact_on_cores(const A& a, const Orientation& a_orientation, const Circle& b,
                                           const ContactOptions& options) {
  return core_contact(a, a_orientation, b, Orientation{}, options);
}

// In the shape's frame, with c the circle's centre there: the face of greatest separation s, then, as
// Box2D's b2CollidePolygonAndCircle, the face where c lies over it or within a polygon (s <= 0),
// else the face's end beyond which c lies (the core's separation from a point falls away on either
// side of its greatest face, so the nearest point of the core lies on that face). Where rounding
// leaves that end not the core's farthest point towards c, the convex cores' contact decides
// (narrowphase/shared/cores/convex_core.h), as it does for every other core pair.
//
// Local to each kernel's file, its one caller, so that the compiler inlines it there as a function
// called once; shared across files it stays out of line, or inlined against its will it spills
// the centre in halves that are then read whole (a stalled load), and either weighs on these short
// kernels.
namespace {

template <class A, int Slots>
Contact core_circle_at(const A& a, const CoreView<Slots>& o, const Orientation& a_orientation, const Vec2& c,
                       const Circle& b, const ContactOptions& options) {
  const Rotation<double> rot = Rotation<double>::of(a_orientation);
  if (has_limit(options)) {  // as the cores' contact
    if (const auto gap = discs_beyond(c, o.reach + b.radius, options)) return Contact::beyond(*gap);
  }
  const auto [s, face] = leading_face<Slots>(o.normals, o.offsets, c);
  const double radii = o.radius + b.radius;
  const double scale = 2 * std::max(o.reach, c.cwiseAbs().maxCoeff()) + radii;
  if (beyond_limit(s - radii, scale, options)) return Contact::beyond(s - radii);
  const auto one = [&](const Vec2& on_a, const Vec2& normal, double separation, std::uint32_t id) {
    const Vec2 point_a = a.center + rot.apply(Vec2(on_a + o.radius * normal));
    const Vec2 point_b = a.center + rot.apply(Vec2(c - b.radius * normal));
    return limited(options, [&] { return Contact::of(separation, rot.apply(normal), point_a, point_b, id); });
  };
  const Vec2& n = o.normals[face];
  const int next = face + 1 == o.count ? 0 : face + 1;
  // A segment's two faces hold no point: s = 0 says only that c lies on its line.
  const int side = Slots != 2 && s <= 0.0 ? 0 : along_face(n, o.vertices[face], o.vertices[next], c);
  if (side == 0) return one(Vec2(c - s * n), n, s - radii, feature_id(FeatureKind::face_of_a, face, 0));
  const int end = side < 0 ? face : next;
  const Vec2 d = c - o.vertices[end];
  const Vec2& before = o.vertices[end == 0 ? o.count - 1 : end - 1];
  if (!farthest_at(before, o.vertices[end], o.vertices[end + 1 == o.count ? 0 : end + 1], d)) {
    return contact_on_cores(a, a_orientation, b, options);
  }
  const LengthAndDirection u = length_and_direction(d);
  return one(o.vertices[end], u.direction, u.length - radii, feature_id(FeatureKind::corner_corner, end, 0));
}

// The same, c computed from the circle's centre in the world.
template <class A, int Slots>
Contact core_circle(const A& a, const CoreView<Slots>& o, const Orientation& a_orientation, const Circle& b,
                    const ContactOptions& options) {
  const Vec2 c = Rotation<double>::of(a_orientation).apply_inverse(Vec2(b.center - a.center));
  return core_circle_at(a, o, a_orientation, c, b, options);
}

}  // namespace

}  // namespace collide2d::detail
