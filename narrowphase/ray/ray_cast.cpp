#include <collide2d/ray_cast.h>

#include <collide2d/chain.h>

#include "narrowphase/shared/cores/convex_core.h"
#include "shapes/internal.h"

#include <cmath>
#include <limits>

namespace collide2d {
namespace {

using Rot = detail::Rotation<double>;
using detail::cross;

std::optional<RayShapeHit> hit_at(double t, const Vec2& origin, const Vec2& direction, const Vec2& normal,
                                  double max_distance) {
  if (!(t <= max_distance)) return std::nullopt;
  return RayShapeHit{t, origin + t * direction, normal};
}

// In the ellipse frame the ray o + t d (|d| = 1) meets the curve where b^2 (o.x + t d.x)^2 + a^2 (o.y +
// t d.y)^2 = a^2 b^2: A t^2 + 2 B t + C = 0 with A = b^2 d.x^2 + a^2 d.y^2, B = b^2 o.x d.x + a^2 o.y d.y
// and C = b^2 o.x^2 + a^2 o.y^2 - a^2 b^2. Its discriminant B^2 - A C equals a^2 b^2 (A - (o x d)^2):
// the line meets the ellipse when its distance from the centre, |o x d|, is within the ellipse's
// half-width across it, sqrt(A). The discriminant is computed in that form because B^2 - A C cancels
// to rounding noise for a needle seen from afar (a = 1e-20, b = 3.7, 12 away: both terms near 1e81,
// their difference 1e39). The entering root is taken as C / (-B + a b sqrt(A - (o x d)^2)), which does
// not cancel (B < 0 for a ray that approaches). The normal comes from the hit measured from the
// line's closest point to the centre, m = (o x d) (d.y, -d.x), not from o + t d: for an ellipse far
// smaller than its distance, o + t d rounds to the centre itself and has no direction.
std::optional<RayShapeHit> cast(const Ellipse& e, const Vec2& origin, const Vec2& direction, double max_distance) {
  const Rot rot = Rot::of(e.angle);
  const Vec2 o = rot.apply_inverse(Vec2(origin - e.center));
  const Vec2 d = rot.apply_inverse(direction);
  const double a2 = e.a * e.a, b2 = e.b * e.b;
  const double a_coef = b2 * d.x() * d.x() + a2 * d.y() * d.y();
  const double b_coef = b2 * o.x() * d.x() + a2 * o.y() * d.y();
  const double cross = o.x() * d.y() - o.y() * d.x();
  const double gap = a_coef - cross * cross;
  if (b_coef >= 0.0 || gap < 0.0) return std::nullopt;
  const double root = e.a * e.b * std::sqrt(gap);
  const double c_coef = b2 * o.x() * o.x() + a2 * o.y() * o.y() - a2 * b2;
  const double t = std::max(c_coef / (-b_coef + root), 0.0);
  const Vec2 m = cross * Vec2(d.y(), -d.x());
  const double m_coef = b2 * m.x() * d.x() + a2 * m.y() * d.y();
  const Vec2 local = m - ((m_coef + root) / a_coef) * d;
  const Vec2 normal = rot.apply(Vec2(local.x() / e.a / e.a, local.y() / e.b / e.b)).stableNormalized();
  return hit_at(t, origin, direction, normal, max_distance);
}

std::optional<RayShapeHit> cast(const Circle& c, const Vec2& origin, const Vec2& direction, double max_distance) {
  return cast(Ellipse{c.center, c.radius, c.radius, 0.0}, origin, direction, max_distance);
}

// Slabs in the rectangle frame: the ray enters at the largest of the per-axis entry parameters. The
// origin is outside (ray_cast tests that first), so one slab has an entry and gives the normal.
std::optional<RayShapeHit> cast(const Rect& r, const Vec2& origin, const Vec2& direction, double max_distance) {
  const Rot rot = Rot::of(r.angle);
  const Vec2 o = rot.apply_inverse(Vec2(origin - r.center));
  const Vec2 d = rot.apply_inverse(direction);
  double enter = -std::numeric_limits<double>::infinity();
  double leave = std::numeric_limits<double>::infinity();
  Vec2 normal = Vec2::Zero();
  for (int k = 0; k < 2; ++k) {
    const double h = r.half_extents[k];
    if (d[k] == 0.0) {
      if (std::abs(o[k]) > h) return std::nullopt;
      continue;
    }
    const double t0 = (-h - o[k]) / d[k];
    const double t1 = (h - o[k]) / d[k];
    const double near = std::min(t0, t1);
    if (near > enter) {
      enter = near;
      normal = Vec2::Zero();
      normal[k] = d[k] > 0 ? -1.0 : 1.0;
    }
    leave = std::min(leave, std::max(t0, t1));
  }
  if (enter > leave || leave < 0.0) return std::nullopt;
  return hit_at(std::max(enter, 0.0), origin, direction, rot.apply(normal), max_distance);
}

// A polygon's or capsule's core in its own frame, the ray brought there. Sharp, the faces clip the
// ray (Cyrus–Beck): it enters at the largest entry parameter of the faces it crosses inwards, whose
// normal it takes. Rounded, the solid is the union of the core, the rectangles the radius lays along
// its faces and the discs at its vertices, and a ray from outside enters the union where it first
// enters one of them: its first crossing of an offset face inwards (within the face) or of a
// vertex's circle, whichever comes first, whose normal it takes.
std::optional<RayShapeHit> cast_core(const detail::Core& c, const Rot& rot, const Vec2& center, const Vec2& origin,
                                     const Vec2& direction, double max_distance) {
  const Vec2 o = rot.apply_inverse(Vec2(origin - center));
  const Vec2 d = rot.apply_inverse(direction);
  double enter = -std::numeric_limits<double>::infinity(), leave = std::numeric_limits<double>::infinity();
  double first = std::numeric_limits<double>::infinity();
  Vec2 normal = Vec2::Zero();
  for (int i = 0; i < c.faces(); ++i) {
    const Vec2& n = c.n[i];
    const double toward = n.dot(d), gap = n.dot(o - c.v[i]) - c.radius;  // the ray's height over the offset face
    if (c.radius == 0.0) {
      if (toward == 0.0) {
        if (gap > 0.0) return std::nullopt;
        continue;
      }
      const double t = -gap / toward;
      if (toward < 0.0 && t > enter) enter = t, normal = n;
      if (toward > 0.0) leave = std::min(leave, t);
      continue;
    }
    if (!(toward < 0.0) || gap < 0.0) continue;
    const double t = -gap / toward;
    const Vec2 along(-n.y(), n.x());
    const double at = along.dot(o + t * d - c.v[i]);
    if (at >= 0.0 && at <= along.dot(c.v[c.next(i)] - c.v[i]) && t < first) first = t, normal = n;
  }
  if (c.radius == 0.0) {
    if (enter > leave || leave < 0.0) return std::nullopt;
    return hit_at(std::max(enter, 0.0), origin, direction, rot.apply(normal), max_distance);
  }
  for (int k = 0; k < c.count; ++k) {
    const std::optional<RayShapeHit> disc = cast(Ellipse{c.v[k], c.radius, c.radius, 0.0}, o, d, first);
    if (disc && disc->distance < first) first = disc->distance, normal = disc->normal;
  }
  if (!(first <= max_distance)) return std::nullopt;
  return hit_at(first, origin, direction, rot.apply(normal), max_distance);
}

std::optional<RayShapeHit> cast(const Capsule& s, const Vec2& origin, const Vec2& direction, double max_distance) {
  return cast_core(detail::core_of(s, {}), Rot::of(s.angle), s.center, origin, direction, max_distance);
}

std::optional<RayShapeHit> cast(const ConvexPolygon& s, const Vec2& origin, const Vec2& direction,
                                double max_distance) {
  return cast_core(detail::core_of(s, {}), Rot::of(s.angle), s.center, origin, direction, max_distance);
}

// In the segment's frame the ray o + t d meets the line of its points s e (s in [0, 1]) where
// t = (o x e) / D and s = (o x d) / D, D = e x d; the segment's sides are its two faces, and the ray
// takes the normal of the one it crosses. A ray along the segment's line (D = 0) has no crossing, as
// Box2D's b2RayCastSegment: it meets the segment, which has no area, in no single point of entry.
std::optional<RayShapeHit> cast(const Segment& s, const Vec2& origin, const Vec2& direction, double max_distance) {
  const Rot rot = Rot::of(s.angle);
  const Vec2 o = rot.apply_inverse(Vec2(origin - s.center));
  const Vec2 d = rot.apply_inverse(direction);
  const Vec2& e = s.end;
  const double sign = cross(e, d) < 0.0 ? -1.0 : 1.0;
  const double denominator = sign * cross(e, d), along = sign * cross(o, d), t = sign * cross(o, e);
  if (!(denominator > 0.0) || along < 0.0 || along > denominator || t < 0.0) return std::nullopt;
  const Vec2 right = detail::segment_normals(s)[0];
  const Vec2 normal = right.dot(d) > 0.0 ? Vec2(-right) : right;
  return hit_at(t / denominator, origin, direction, rot.apply(normal), max_distance);
}

}  // namespace

std::optional<RayShapeHit> ray_cast(const Shape& shape, const Vec2& origin, const Vec2& direction,
                                    double max_distance) {
  // Inside is decided by contains() alone, so a caller that skips the shapes holding the origin and
  // a zero normal agree to the last bit.
  if (contains(shape, origin)) return hit_at(0.0, origin, direction, Vec2::Zero(), max_distance);
  return std::visit([&](const auto& s) { return cast(s, origin, direction, max_distance); }, shape);
}

// A ray from behind the chain segment's line (the side away from its front, its direction turned
// clockwise: chain.h) passes through it.
std::optional<RayShapeHit> ray_cast(const ChainSegment& s, const Vec2& origin, const Vec2& direction,
                                    double max_distance) {
  const Vec2 d = Rot::of(s.segment.angle).apply(s.segment.end);
  const Vec2 front(d.y(), -d.x());
  if (front.dot(Vec2(origin - s.segment.center)) < 0.0) return std::nullopt;
  return ray_cast(Shape(s.segment), origin, direction, max_distance);
}

}  // namespace collide2d
