#include "narrowphase/shared/cores/convex_core.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace collide2d::detail {
namespace {

// An eight-slot core from every slot of a shape's vertices and normals, placed in SIMD lanes.
Core core_in_slots(int count, const std::array<Vec2, kMaxPolygonVertices>& vertices,
                   const std::array<Vec2, kMaxPolygonVertices>& normals, int normal_count, double radius,
                   const Discs& discs, const Placement& at) {
  Core c;
  c.count = count;
  c.radius = radius;
  c.discs = discs;
  c.center = at.offset;
  place_slots(vertices, normals, normal_count, c.faces(), at, c);
  if (count == 2) set_end_axes(c);
  return c;
}

// A segment's core in two slots: its two ends and its two faces' normals placed by `at`, and its
// axes one at a time.
SegmentCore segment_core(const std::array<Vec2, 2>& ends, const Vec2& right, const Vec2& left, double radius,
                         const Discs& discs, const Placement& at) {
  SegmentCore c;
  c.radius = radius;
  c.discs = discs;
  c.center = at.offset;
  const bool moves = at.moves();
  for (std::size_t i = 0; i < 2; ++i) {
    const Vec2 v = moves ? at.point(ends[i]) : ends[i];
    c.v[i] = v, c.x[i] = v.x(), c.y[i] = v.y();
    c.largest = std::max(c.largest, std::max(std::abs(v.x()), std::abs(v.y())));
  }
  c.n = {moves ? at.direction(right) : right, moves ? at.direction(left) : left};
  for (std::size_t i = 0; i < 2; ++i) {
    const double nx = c.n[i].x(), ny = c.n[i].y();
    c.ax[i] = nx, c.ay[i] = ny, c.ad[i] = nx * c.x[i] + ny * c.y[i];  // n.v, as plane_of's
  }
  set_end_axes(c);
  return c;
}

// An eight-slot core from the shape's first slots: the slots not given repeat the first vertex,
// and the normals not given are zero, so that the lanes read every slot.
Core core_in_first_slots(int count, std::span<const Vec2> vertices, std::span<const Vec2> normals, double radius,
                         const Discs& discs, const Placement& at) {
  std::array<Vec2, kMaxPolygonVertices> v, n;
  std::copy(vertices.begin(), vertices.end(), v.begin());
  std::fill(v.begin() + static_cast<std::ptrdiff_t>(vertices.size()), v.end(), vertices[0]);
  std::copy(normals.begin(), normals.end(), n.begin());
  std::fill(n.begin() + static_cast<std::ptrdiff_t>(normals.size()), n.end(), Vec2::Zero());
  return core_in_slots(count, v, n, static_cast<int>(normals.size()), radius, discs, at);
}

}  // namespace

Core core_of(const Rect& r, const Placement& at) {
  const double hx = r.half_extents.x(), hy = r.half_extents.y();
  const Vec2 v[] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  const Vec2 n[] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  return core_in_first_slots(4, v, n, 0.0, discs_of(r), at);
}

Core core_of(const ConvexPolygon& p, const Placement& at) {
  const PolygonOutline& o = *p.outline;
  return core_in_slots(o.count, o.vertices, o.normals, kMaxPolygonVertices, o.radius, discs_of(p), at);
}

template <class C>
C core_of(const Capsule& c, const Placement& at) {
  const std::array<Vec2, 2> faces = segment_normals();
  if constexpr (std::is_same_v<C, SegmentCore>) {
    return segment_core(segment_of(c), faces[0], faces[1], c.radius, discs_of(c), at);
  } else {
    const Vec2 n[] = {faces[0], faces[1], {1, 0}, {-1, 0}};
    return core_in_first_slots(2, segment_of(c), n, c.radius, discs_of(c), at);
  }
}
template Core core_of(const Capsule&, const Placement&);
template SegmentCore core_of(const Capsule&, const Placement&);

// A segment's core is a capsule's of radius 0 from its frame's origin.
template <class C>
C core_of(const Segment& s, const Placement& at) {
  const std::array<Vec2, 4> n = segment_normals(s);
  if constexpr (std::is_same_v<C, SegmentCore>) {
    return segment_core(segment_of(s), n[0], n[1], 0.0, discs_of(s), at);
  } else {
    return core_in_first_slots(2, segment_of(s), n, 0.0, discs_of(s), at);
  }
}
template Core core_of(const Segment&, const Placement&);
template SegmentCore core_of(const Segment&, const Placement&);

Core core_of(const Circle& c, const Placement& at) {
  const Vec2 v[] = {{0, 0}};
  return core_in_first_slots(1, v, {}, c.radius, discs_of(c), at);
}

}  // namespace collide2d::detail
