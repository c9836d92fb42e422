#include <collide2d/shapes.h>

#include "shapes/internal.h"
#include "shapes/kinds.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

namespace collide2d {
namespace {

using Rot = detail::Rotation<double>;
using detail::reject;

using detail::require_coordinate;
using detail::require_finite;
using detail::require_size;

Aabb around(const Vec2& center, const Vec2& half) { return detail::around(center, half, half, half); }

}  // namespace

Aabb detail::around(const Vec2& center, const Vec2& below, const Vec2& above, const Vec2& reach) {
  const Vec2 slack = 8 * std::numeric_limits<double>::epsilon() * (center.cwiseAbs() + reach);
  return {center - below - slack, center + above + slack};
}

void detail::reject(const char* what, const char* field, double value, const char* rule) {
  throw InvalidShape(std::string(what) + ' ' + field + ' ' + rule + " (got " + shortest(value) + ')');
}

// The fewest significant digits that read back to the value, as %g writes them: std::to_chars for
// doubles is missing from some standard libraries (Emscripten's libc++, which builds the testbed).
std::string detail::shortest(double value) {
  char digits[32];
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(digits, sizeof digits, "%.*g", precision, value);
    if (std::strtod(digits, nullptr) == value) break;
  }
  return digits;
}

Orientation Orientation::of(double angle) {
  const Rot r = Rot::of(angle);
  return {r.c, r.s};
}

void validate_point(const Vec2& p, const char* what) {
  require_coordinate(what, "x", p.x());
  require_coordinate(what, "y", p.y());
}

void validate(const Aabb& box) {
  validate_point(box.min, "box min");
  validate_point(box.max, "box max");
  if (box.min.x() > box.max.x()) reject("box", "min x", box.min.x(), "must not exceed box max x");
  if (box.min.y() > box.max.y()) reject("box", "min y", box.min.y(), "must not exceed box max y");
}

void validate(const Circle& c) {
  require_coordinate("circle", "cx", c.center.x());
  require_coordinate("circle", "cy", c.center.y());
  require_size("circle", "radius", c.radius);
}

void validate(const Ellipse& e) {
  require_coordinate("ellipse", "cx", e.center.x());
  require_coordinate("ellipse", "cy", e.center.y());
  require_size("ellipse", "a", e.a);
  require_size("ellipse", "b", e.b);
  require_finite("ellipse", "angle", e.angle);
}

void validate(const Rect& r) {
  require_coordinate("rect", "cx", r.center.x());
  require_coordinate("rect", "cy", r.center.y());
  require_size("rect", "hx", r.half_extents.x());
  require_size("rect", "hy", r.half_extents.y());
  require_finite("rect", "angle", r.angle);
}

void validate(const Capsule& c) {
  require_coordinate("capsule", "cx", c.center.x());
  require_coordinate("capsule", "cy", c.center.y());
  if (c.half_length == 0.0)
    reject("capsule", "half_length", c.half_length,
           "must be positive (a capsule of no length is a circle: use circle)");
  require_size("capsule", "half_length", c.half_length);
  require_size("capsule", "radius", c.radius);
  require_finite("capsule", "angle", c.angle);
}

void validate(const Segment& s) {
  require_coordinate("segment", "x1", s.center.x());
  require_coordinate("segment", "y1", s.center.y());
  require_coordinate("segment", "end x", s.end.x());
  require_coordinate("segment", "end y", s.end.y());
  require_finite("segment", "angle", s.angle);
  const double length = s.end.norm();
  if (length == 0.0) reject("segment", "length", length, "must be positive (its two points are one)");
  if (length < kMinSize || length > kMaxMagnitude)
    reject("segment", "length", length, "is outside the supported range 1e-50 to 1e50");
}

Vec2 Segment::point2() const { return center + Rot::of(angle).apply(end); }

void validate(const Shape& s) {
  std::visit([](const auto& shape) { validate(shape); }, s);
}

Vec2 center_of(const Shape& s) {
  return std::visit([](const auto& x) { return x.center; }, s);
}

double angle_of(const Shape& s) {
  return std::visit(
      [](const auto& x) {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, Circle>) {
          return 0.0;
        } else {
          return x.angle;
        }
      },
      s);
}

double reach_of(const Shape& s) {
  if (const auto* c = std::get_if<Circle>(&s)) return c->radius;
  if (const auto* e = std::get_if<Ellipse>(&s)) return std::max(e->a, e->b);
  if (const auto* c = std::get_if<Capsule>(&s)) return c->half_length + c->radius;
  if (const auto* p = std::get_if<ConvexPolygon>(&s)) return p->outline->reach;
  if (const auto* g = std::get_if<Segment>(&s)) return g->end.norm();
  return std::get<Rect>(s).half_extents.norm();
}

bool intersects(const Aabb& p, const Aabb& q) {
  return (p.min.array() <= q.max.array()).all() && (q.min.array() <= p.max.array()).all();
}

bool encloses(const Aabb& outer, const Aabb& inner) {
  return (outer.min.array() <= inner.min.array()).all() && (inner.max.array() <= outer.max.array()).all();
}

const char* shape_name(const Shape& s) {
  return detail::with_kind(s, [](const auto&, auto kind) { return decltype(kind)::word.data(); });
}

Aabb aabb(const Circle& c) { return around(c.center, Vec2::Constant(c.radius)); }

namespace {

Aabb oriented_box(const Circle& c, const Orientation&) { return aabb(c); }

// The extreme x of the rotated ellipse is the support half-width sqrt((a c)^2 + (b s)^2).
Aabb oriented_box(const Ellipse& e, const Orientation& o) {
  return around(e.center, Vec2(std::hypot(e.a * o.c, e.b * o.s), std::hypot(e.a * o.s, e.b * o.c)));
}

Aabb oriented_box(const Rect& r, const Orientation& o) {
  const double c = std::abs(o.c), s = std::abs(o.s);
  const Vec2& h = r.half_extents;
  return around(r.center, Vec2(h.x() * c + h.y() * s, h.x() * s + h.y() * c));
}

Aabb oriented_box(const Capsule& c, const Orientation& o) {
  return around(c.center, Vec2(c.half_length * std::abs(o.c) + c.radius, c.half_length * std::abs(o.s) + c.radius));
}

Aabb oriented_box(const ConvexPolygon& p, const Orientation& o) { return detail::polygon_box(p, o); }

Aabb oriented_box(const Segment& s, const Orientation& o) {
  const Vec2 to = Rot::of(o).apply(s.end);
  return detail::around(s.center, to.cwiseMin(0.0).cwiseAbs(), to.cwiseMax(0.0), to.cwiseAbs());
}

}  // namespace

Aabb aabb(const Capsule& c) { return oriented_box(c, Orientation::of(c.angle)); }
Aabb aabb(const Segment& s) { return oriented_box(s, Orientation::of(s.angle)); }
Aabb aabb(const Ellipse& e) { return oriented_box(e, Orientation::of(e.angle)); }
Aabb aabb(const Rect& r) { return oriented_box(r, Orientation::of(r.angle)); }
Aabb aabb(const Shape& s) {
  return std::visit([](const auto& x) { return aabb(x); }, s);
}
Aabb aabb(const Shape& s, const Orientation& o) {
  return std::visit([&o](const auto& x) { return oriented_box(x, o); }, s);
}

Vec2 support(const Circle& c, const Vec2& d) {
  const double n = d.norm();
  return n > 0.0 ? Vec2(c.center + (c.radius / n) * d) : c.center;
}

namespace {

Vec2 support(const Circle& c, const Rot&, const Vec2& d) { return support(c, d); }

Vec2 support(const Ellipse& e, const Rot& r, const Vec2& d) {
  // Support of {K + V diag(a,b) u : |u| <= 1} in direction d is K + V diag(a,b)^2 w / |diag(a,b) w|
  // with w = V^T d; d is scaled by its largest component first so that squares cannot overflow.
  const double m = d.cwiseAbs().maxCoeff();
  if (!(m > 0.0)) return e.center;
  const Vec2 w = r.apply_inverse(Vec2(d / m));
  const Vec2 scaled(e.a * w.x(), e.b * w.y());
  const Vec2 local(e.a * scaled.x(), e.b * scaled.y());
  return e.center + r.apply(Vec2(local / scaled.norm()));
}

Vec2 support(const Rect& r, const Rot& rot, const Vec2& d) {
  const Vec2 w = rot.apply_inverse(d);
  const Vec2 corner(w.x() >= 0.0 ? r.half_extents.x() : -r.half_extents.x(),
                    w.y() >= 0.0 ? r.half_extents.y() : -r.half_extents.y());
  return r.center + rot.apply(corner);
}

Vec2 support(const Capsule& c, const Rot& rot, const Vec2& d) {
  const Vec2 axis(rot.c, rot.s);
  const double n = d.norm();
  const Vec2 end = c.center + (d.dot(axis) >= 0.0 ? c.half_length : -c.half_length) * axis;
  return n > 0.0 ? Vec2(end + (c.radius / n) * d) : end;
}

Vec2 support(const Segment& s, const Rot& rot, const Vec2& d) {
  const Vec2 to = rot.apply(s.end);
  return d.dot(to) >= 0.0 ? Vec2(s.center + to) : s.center;
}

Vec2 support(const ConvexPolygon& p, const Rot& rot, const Vec2& d) { return detail::support_turned(p, rot, d); }

}  // namespace

Vec2 support(const Ellipse& e, const Vec2& d) { return support(e, Rot::of(e.angle), d); }
Vec2 support(const Rect& r, const Vec2& d) { return support(r, Rot::of(r.angle), d); }
Vec2 support(const Capsule& c, const Vec2& d) { return support(c, Rot::of(c.angle), d); }
Vec2 support(const Segment& s, const Vec2& d) { return support(s, Rot::of(s.angle), d); }

Vec2 support(const Shape& s, const Orientation& o, const Vec2& d) {
  return std::visit([&](const auto& shape) { return support(shape, Rot::of(o), d); }, s);
}

Vec2 support(const Shape& s, const Vec2& d) {
  return std::visit([&d](const auto& shape) { return support(shape, d); }, s);
}

bool contains(const Circle& c, const Vec2& p) { return (p - c.center).squaredNorm() <= c.radius * c.radius; }

bool contains(const Ellipse& e, const Vec2& p) {
  const Vec2 q = Rot::of(e.angle).apply_inverse(Vec2(p - e.center));
  const double u = q.x() / e.a;
  const double v = q.y() / e.b;
  return u * u + v * v <= 1.0;
}

bool contains(const Rect& r, const Vec2& p) {
  const Vec2 q = Rot::of(r.angle).apply_inverse(Vec2(p - r.center));
  return std::abs(q.x()) <= r.half_extents.x() && std::abs(q.y()) <= r.half_extents.y();
}

bool contains(const Capsule& c, const Vec2& p) {
  const Vec2 q = Rot::of(c.angle).apply_inverse(Vec2(p - c.center));
  const double along = q.x() - std::clamp(q.x(), -c.half_length, c.half_length);
  return along * along + q.y() * q.y() <= c.radius * c.radius;
}

// On the segment: on its line (the orientation test's sign exactly 0) and between its points.
bool contains(const Segment& s, const Vec2& p) {
  const Vec2 q = Rot::of(s.angle).apply_inverse(Vec2(p - s.center));
  const double along = q.dot(s.end);
  return q.x() * s.end.y() == q.y() * s.end.x() && along >= 0.0 && along <= s.end.squaredNorm();
}

bool contains(const Shape& s, const Vec2& p) {
  return std::visit([&p](const auto& shape) { return contains(shape, p); }, s);
}

}  // namespace collide2d
