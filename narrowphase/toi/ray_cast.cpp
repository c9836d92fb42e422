#include <collide2d/ray_cast.h>

#include "shapes/internal.h"

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

// In the ellipse frame the ray o + t d meets the curve where b^2 (o.x + t d.x)^2 + a^2 (o.y + t d.y)^2
// = a^2 b^2: A t^2 + 2 B t + C = 0 with A = b^2 d.x^2 + a^2 d.y^2, B = b^2 o.x d.x + a^2 o.y d.y and
// C = b^2 o.x^2 + a^2 o.y^2 - a^2 b^2. Its discriminant B^2 - A C equals a^2 b^2 (A - (o x d)^2): the
// line meets the ellipse when its distance from the centre, |o x d| / |d|, is within the ellipse's
// half-width across it, sqrt(A) / |d|. The discriminant is computed in that form: B^2 - A C itself
// cancels to rounding noise for a needle seen from afar (a = 1e-20, b = 3.7, 12 away: both terms
// near 1e81, their difference 1e39), which the World fuzzer caught as a hit 15 beyond the needle's
// end. The entering root is taken as C / (-B + a b sqrt(A - (o x d)^2)), which does not cancel
// (B < 0 for a ray that approaches).
std::optional<RayShapeHit> cast(const Ellipse& e, const Vec2& origin, const Vec2& direction, double max_distance) {
  const Rot rot = Rot::of(e.angle);
  const Vec2 o = rot.apply_inverse(Vec2(origin - e.center));
  const Vec2 d = rot.apply_inverse(direction);
  const double a2 = e.a * e.a, b2 = e.b * e.b;
  if ((o.x() / e.a) * (o.x() / e.a) + (o.y() / e.b) * (o.y() / e.b) <= 1.0) {
    return hit_at(0.0, origin, direction, Vec2::Zero(), max_distance);
  }
  const double a_coef = b2 * d.x() * d.x() + a2 * d.y() * d.y();
  const double b_coef = b2 * o.x() * d.x() + a2 * o.y() * d.y();
  const double cross = o.x() * d.y() - o.y() * d.x();
  const double gap = a_coef - cross * cross;
  if (b_coef >= 0.0 || gap < 0.0) return std::nullopt;
  const double c_coef = b2 * o.x() * o.x() + a2 * o.y() * o.y() - a2 * b2;
  const double t = c_coef / (-b_coef + e.a * e.b * std::sqrt(gap));
  const Vec2 local = o + t * d;
  const Vec2 normal = rot.apply(Vec2(local.x() / a2, local.y() / b2)).normalized();
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
