// Distance between two solid oriented rectangles, with closest points.
// Separated: a closest pair of two disjoint convex polygons always has a vertex of one of them, so
// the distance is the least of the eight vertex-to-box distances (each a clamp in the box's frame).
// Overlapping (overlap_rect_rect): distance 0 and the centroid of the vertices of B clipped to A
// (Sutherland–Hodgman) as witness. Computed in A's frame after subtracting centres; accurate to a
// few ulps of the pair's scale.

#include <collide2d/kernels.h>

#include "narrowphase/shared/frames/box_local.h"
#include "narrowphase/shared/frames/rect_pair_frame.h"

#include <array>
#include <limits>
#include <vector>

namespace collide2d {
namespace {

using detail::clamp_to_box;

std::array<Vec2, 4> box_corners(const Vec2& h) {
  return {Vec2(-h.x(), -h.y()), Vec2(h.x(), -h.y()), Vec2(h.x(), h.y()), Vec2(-h.x(), h.y())};
}

struct LocalPair {
  double distance = std::numeric_limits<double>::infinity();
  Vec2 on_a = Vec2::Zero();
  Vec2 on_b = Vec2::Zero();
};

// Nearest vertex-to-box pair, in A's frame.
LocalPair nearest_vertex_pair(const detail::RectPairFrame& f, const Rect& a, const Rect& b) {
  LocalPair best;
  const auto consider = [&best](const Vec2& on_a, const Vec2& on_b) {
    const double d = (on_b - on_a).norm();
    if (d < best.distance) best = {d, on_a, on_b};
  };
  for (const Vec2& corner : box_corners(b.half_extents)) {
    const Vec2 p = f.b_center + f.b_rel.apply(corner);
    consider(clamp_to_box(p, a.half_extents), p);
  }
  for (const Vec2& p : box_corners(a.half_extents)) {
    const Vec2 in_b = f.b_rel.apply_inverse(Vec2(p - f.b_center));
    consider(p, f.b_center + f.b_rel.apply(clamp_to_box(in_b, b.half_extents)));
  }
  return best;
}

// Keeps the part of the convex polygon with sign * p[axis] <= limit.
std::vector<Vec2> clip(const std::vector<Vec2>& poly, int axis, double sign, double limit) {
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Vec2& p = poly[k];
    const Vec2& q = poly[(k + 1) % poly.size()];
    const double dp = sign * p[axis] - limit;
    const double dq = sign * q[axis] - limit;
    if (dp <= 0.0) out.push_back(p);
    if ((dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0)) out.push_back(p + (dp / (dp - dq)) * (q - p));
  }
  return out;
}

// B clipped to A (Sutherland–Hodgman), in A's frame: the intersection polygon.
std::vector<Vec2> clipped_b(const detail::RectPairFrame& f, const Rect& a, const Rect& b) {
  std::vector<Vec2> poly;
  for (const Vec2& corner : box_corners(b.half_extents)) poly.push_back(f.b_center + f.b_rel.apply(corner));
  for (int axis = 0; axis < 2; ++axis) {
    for (const double sign : {-1.0, 1.0}) poly = clip(poly, axis, sign, a.half_extents[axis]);
  }
  return poly;
}

}  // namespace

DistanceResult distance_rect_rect(const Rect& a, const Rect& b) {
  const detail::RectPairFrame f(a, b);
  const auto to_world = [&](const Vec2& p) -> Vec2 { return a.center + f.a_rot.apply(p); };
  const LocalPair best = nearest_vertex_pair(f, a, b);
  if (!overlap_rect_rect(a, b)) {
    return DistanceResult::apart(best.distance, to_world(best.on_a), to_world(best.on_b));
  }
  const std::vector<Vec2> poly = clipped_b(f, a, b);
  // An empty clip means the boxes only touch, within rounding: the nearest pair's midpoint serves.
  Vec2 witness = 0.5 * (best.on_a + best.on_b);
  if (!poly.empty()) {
    witness = Vec2::Zero();
    for (const Vec2& p : poly) witness += p;
    witness /= static_cast<double>(poly.size());
  }
  return DistanceResult::touching(to_world(witness));
}

}  // namespace collide2d
