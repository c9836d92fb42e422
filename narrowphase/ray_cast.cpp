#include "narrowphase/ray_cast.h"

#include "shapes/rotation.h"

#include <cmath>
#include <limits>

namespace collide2d {
namespace {

using Rot = detail::Rotation<double>;

std::optional<RayShapeHit> hit_at(double t, const Vec2& origin, const Vec2& direction, const Vec2& normal,
                                  double max_distance) {
  if (!(t <= max_distance)) return std::nullopt;
  return RayShapeHit{t, origin + t * direction, normal};
}

// In the ellipse frame scaled to the unit disc the ray is p + t q; |p + t q|^2 = 1 is
// A t^2 + 2 B t + C = 0 with A = q.q, B = p.q, C = p.p - 1. The entering root is taken in the form
// C / (-B + sqrt(B^2 - A C)), which does not cancel (B < 0 for a ray that approaches).
std::optional<RayShapeHit> cast(const Ellipse& e, const Vec2& origin, const Vec2& direction, double max_distance) {
  const Rot rot = Rot::of(e.angle);
  const Vec2 o = rot.apply_inverse(Vec2(origin - e.center));
  const Vec2 d = rot.apply_inverse(direction);
  const Vec2 p(o.x() / e.a, o.y() / e.b);
  const Vec2 q(d.x() / e.a, d.y() / e.b);
  const double c = p.squaredNorm() - 1.0;
  if (c <= 0.0) return hit_at(0.0, origin, direction, Vec2::Zero(), max_distance);
  const double b = p.dot(q);
  const double disc = b * b - q.squaredNorm() * c;
  if (b >= 0.0 || disc < 0.0) return std::nullopt;
  const double t = c / (-b + std::sqrt(disc));
  const Vec2 local = o + t * d;
  const Vec2 normal = rot.apply(Vec2(local.x() / (e.a * e.a), local.y() / (e.b * e.b))).normalized();
  return hit_at(t, origin, direction, normal, max_distance);
}

std::optional<RayShapeHit> cast(const Circle& c, const Vec2& origin, const Vec2& direction, double max_distance) {
  return cast(Ellipse{c.center, c.radius, c.radius, 0.0}, origin, direction, max_distance);
}

// Slabs in the rectangle frame: the ray enters at the largest of the per-axis entry parameters.
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
  if (enter <= 0.0) return hit_at(0.0, origin, direction, Vec2::Zero(), max_distance);
  return hit_at(enter, origin, direction, rot.apply(normal), max_distance);
}

}  // namespace

std::optional<RayShapeHit> ray_cast(const Shape& shape, const Vec2& origin, const Vec2& direction,
                                    double max_distance) {
  return std::visit([&](const auto& s) { return cast(s, origin, direction, max_distance); }, shape);
}

}  // namespace collide2d
