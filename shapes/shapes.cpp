// The geometry of any shape (Shape), by its kind's own functions (shapes/<word>.cpp), and what all
// kinds share: boxes, validation messages, orientations.
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

void validate(const Shape& s) {
  std::visit([](const auto& shape) { validate(shape); }, s);
}

Vec2 center_of(const Shape& s) {
  return std::visit([](const auto& x) { return x.center; }, s);
}

Shape moved_to(const Shape& s, const Vec2& center) {
  return std::visit(
      [&center](auto x) -> Shape {
        x.center = center;
        return x;
      },
      s);
}

double angle_of(const Shape& s) {
  return std::visit(
      [](const auto& x) {
        if constexpr (requires { x.angle; }) {
          return x.angle;
        } else {
          return 0.0;
        }
      },
      s);
}

double reach_of(const Shape& s) {
  return std::visit([](const auto& x) { return detail::reach(x); }, s);
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

Aabb aabb(const Shape& s) {
  return std::visit([](const auto& x) { return aabb(x); }, s);
}
Aabb aabb(const Shape& s, const Orientation& o) {
  return std::visit([&o](const auto& x) { return detail::oriented_box(x, o); }, s);
}

Vec2 support(const Shape& s, const Orientation& o, const Vec2& d) {
  return std::visit([&](const auto& shape) { return detail::support(shape, Rot::of(o), d); }, s);
}

Vec2 support(const Shape& s, const Vec2& d) {
  return std::visit([&d](const auto& shape) { return support(shape, d); }, s);
}

bool contains(const Shape& s, const Vec2& p) {
  return std::visit([&p](const auto& shape) { return contains(shape, p); }, s);
}

}  // namespace collide2d
