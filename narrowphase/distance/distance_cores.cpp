// Any two convex cores (narrowphase/shared/cores/convex_core.h), where the pair has no kernel of its
// own: apart, the cores' nearest features (core_pair.h) less the radii; overlapping, a point of both.
#include "narrowphase/shared/cores/core_pair.h"

#include "narrowphase/shared/frames/unit_vector.h"

#include <algorithm>
#include <array>
#include <limits>
#include <optional>

namespace collide2d::detail {
namespace {

// A point of two overlapping segments: where their lines cross, or, in line, the middle of their
// common part.
template <class X, class Y>
Vec2 segments_common_point(const X& x, const Y& y) {
  const Vec2 ex = x.v[1] - x.v[0], ey = y.v[1] - y.v[0];
  const double turn = cross(ey, ex);
  if (turn != 0.0) return y.v[0] + (cross(x.v[0] - y.v[0], ex) / turn) * ey;
  const double length = ex.squaredNorm();
  if (length == 0.0) return x.v[0];  // collapsed by rounding, far from the origin
  const auto at = [&](const Vec2& q) { return std::clamp((q - x.v[0]).dot(ex) / length, 0.0, 1.0); };
  return x.v[0] + ((at(y.v[0]) + at(y.v[1])) / 2) * ex;
}

// Whether p lies in the (sharp) core c, which has faces all round (3 vertices or more).
template <class C>
bool in_core(const C& c, const Vec2& p) {
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
template <class X, class Y>
std::optional<Vec2> common_point(const X& x, const Y& y) {
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
template <class P>
Vec2 touching_point(const P& p, const Axes& axes) {
  const Axis& best = axes.best();
  const auto on = [&](const auto& x, const auto& y) -> Vec2 {
    if (best.face < 0) return (x.v[best.end] + y.v[best.vertex]) / 2;
    const FaceClip c = clip_face(x, best.face, y);
    const Clipped& k = c.count > 0 ? c.kept[0] : c.deep;
    return k.on_y - (k.b / 2) * x.n[best.face];
  };
  return axes.b_best() ? on(p.b, p.a) : on(p.a, p.b);
}

}  // namespace

template <class X, class Y>
DistanceResult core_distance(const CorePairOf<X, Y>& p) {
  const Axes axes = axes_of(p);
  CoreVerdict v = verdict(p, axes);
  Closest& c = v.gap;
  if (v.overlapping) {
    if (axes.s() <= 0.0) {
      const std::optional<Vec2> w = p.a.count >= p.b.count ? common_point(p.a, p.b) : common_point(p.b, p.a);
      return DistanceResult::touching(p.world_point(w ? *w : touching_point(p, axes)));
    }
    const double t = radii(p) > 0.0 ? p.a.radius / radii(p) : 0.5;
    return DistanceResult::touching(p.world_point(Vec2(c.on_a + t * (c.on_b - c.on_a))));
  }
  if (c.squared == std::numeric_limits<double>::infinity()) c = gap(p, axes);
  const LengthAndDirection d = length_and_direction(Vec2(c.on_b - c.on_a));
  return DistanceResult::apart(d.length - radii(p), p.world_point(Vec2(c.on_a + p.a.radius * d.direction)),
                               p.world_point(Vec2(c.on_b - p.b.radius * d.direction)));
}

template DistanceResult core_distance(const CorePairOf<Core, Core>&);
template DistanceResult core_distance(const CorePairOf<Core, SegmentCore>&);
template DistanceResult core_distance(const CorePairOf<SegmentCore, Core>&);
template DistanceResult core_distance(const CorePairOf<SegmentCore, SegmentCore>&);
template DistanceResult core_distance(const CorePairOf<OwnFrameCore<Rect>, SegmentCore>&);
template DistanceResult core_distance(const CorePairOf<OwnFrameCore<Rect>, Core>&);
template DistanceResult core_distance(const CorePairOf<OwnFrameCore<ConvexPolygon>, SegmentCore>&);
template DistanceResult core_distance(const CorePairOf<OwnFrameCore<ConvexPolygon>, Core>&);

}  // namespace collide2d::detail
