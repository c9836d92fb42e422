#include "narrowphase/shared/cores/convex_core.h"

#include <algorithm>
#include <span>

namespace collide2d::detail {
namespace {

// The core of `count` vertices from the shape's slots: a polygon's outline gives all of them (those
// past the count repeating the first), so that the loops run a fixed length; the slots not given
// repeat the first vertex, and the normals not given are zero. A two-slot core keeps a segment's
// two faces' normals alone.
template <class C>
C make(int count, std::span<const Vec2> vertices, std::span<const Vec2> normals, double radius, const Discs& discs,
       const Placement& at) {
  C c;
  if constexpr (C::kSlots != 2) c.count = count;
  c.radius = radius;
  c.discs = discs;
  c.center = at.offset;
  normals = normals.first(std::min(normals.size(), c.n.size()));
  const bool moves = at.moves();
  // The lanes read all the slots. The coordinates apart are written from the vertex as
  // computed, not read back from the vertex's slot, which would stall on the store.
  const auto put = [&c](std::size_t i, const Vec2& v) { c.v[i] = v, c.x[i] = v.x(), c.y[i] = v.y(); };
  const Vec2 first = moves ? at.point(vertices[0]) : vertices[0];
  put(0, first);
  for (std::size_t i = 1; i < vertices.size(); ++i) put(i, moves ? at.point(vertices[i]) : vertices[i]);
  for (std::size_t i = vertices.size(); i < c.v.size(); ++i) put(i, first);
  for (std::size_t i = 0; i < normals.size(); ++i) c.n[i] = moves ? at.direction(normals[i]) : normals[i];
  std::fill(c.n.begin() + static_cast<std::ptrdiff_t>(normals.size()), c.n.end(), Vec2::Zero());
  return c;
}

}  // namespace

Core core_of(const Rect& r, const Placement& at) {
  const double hx = r.half_extents.x(), hy = r.half_extents.y();
  const Vec2 v[] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  const Vec2 n[] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  return make<Core>(4, v, n, 0.0, discs_of(r), at);
}

Core core_of(const ConvexPolygon& p, const Placement& at) {
  const PolygonOutline& o = *p.outline;
  return make<Core>(o.count, o.vertices, o.normals, o.radius, discs_of(p), at);
}

template <class C>
C core_of(const Capsule& c, const Placement& at) {
  const std::array<Vec2, 2> faces = segment_normals();
  const Vec2 n[] = {faces[0], faces[1], {1, 0}, {-1, 0}};
  return make<C>(2, segment_of(c), n, c.radius, discs_of(c), at);
}
template Core core_of(const Capsule&, const Placement&);
template SegmentCore core_of(const Capsule&, const Placement&);

// A segment's core is a capsule's of radius 0 from its frame's origin.
template <class C>
C core_of(const Segment& s, const Placement& at) {
  return make<C>(2, segment_of(s), segment_normals(s), 0.0, discs_of(s), at);
}
template Core core_of(const Segment&, const Placement&);
template SegmentCore core_of(const Segment&, const Placement&);

Core core_of(const Circle& c, const Placement& at) {
  const Vec2 v[] = {{0, 0}};
  return make<Core>(1, v, {}, c.radius, discs_of(c), at);
}

}  // namespace collide2d::detail
