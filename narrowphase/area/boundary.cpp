#include "narrowphase/area/boundary.h"

#include "narrowphase/area/clip.h"
#include "narrowphase/shared/frames/unit_vector.h"
#include "shapes/internal.h"

#include <variant>

namespace collide2d::detail::areas {
namespace {

using Rot = Rotation<double>;

Arc ellipse_arc(const Vec2& c, double a, double b, const Rot& r) {
  Arc arc;
  arc.c = c;
  arc.m << a * r.c, -b * r.s, a * r.s, b * r.c;
  arc.inverse << r.c / a, r.s / a, -r.s / b, r.c / b;
  arc.det = a * b;
  arc.u0 = arc.u1 = Vec2::UnitX();
  arc.full = false;
  arc.circular = a == b;
  return arc;
}

// The whole curve as one piece, from and to the end of its first axis.
Boundary closed_curve(const Arc& curve) {
  Boundary b;
  b.polygonal = false;
  b.count = 1;
  Piece& piece = b.pieces[0];
  piece.curved = true;
  piece.arc = curve;
  piece.arc.full = true;
  piece.start = piece.end = End{curve.point(Vec2::UnitX()), Vec2::UnitX()};
  return b;
}

// The convex polygon of `count` vertices (a capsule's core has 2), each edge moved out by `radius`
// along its normal and each corner rounded by an arc about its vertex.
Boundary rounded_polygon(const Vec2* vertices, const Vec2* normals, int count, double radius) {
  Boundary b;
  b.polygonal = radius == 0;
  for (int i = 0; i < count; ++i) {
    const int next = (i + 1) % count;
    const Vec2 offset = radius * normals[i];
    Piece& edge = b.pieces[b.count++];
    edge.start = End{vertices[i] + offset, Vec2::UnitX()};
    edge.end = End{vertices[next] + offset, Vec2::UnitX()};
    edge.curved = false;
    if (radius == 0) continue;
    Piece& corner = b.pieces[b.count++];
    corner.curved = true;
    corner.arc = ellipse_arc(vertices[next], radius, radius, Rot{});
    corner.arc.u0 = normals[i];
    corner.arc.u1 = normals[next];
    corner.start = {edge.end.p, normals[i]};
    corner.end = {vertices[next] + radius * normals[next], normals[next]};
  }
  return b;
}

Boundary boundary(const Circle& c, const Vec2& origin) {
  return closed_curve(ellipse_arc(c.center - origin, c.radius, c.radius, Rot{}));
}

Boundary boundary(const Ellipse& e, const Vec2& origin) {
  return closed_curve(ellipse_arc(e.center - origin, e.a, e.b, Rot::of(e.angle)));
}

Boundary boundary(const Rect& r, const Vec2& origin) {
  const Rot rot = Rot::of(r.angle);
  const std::array<Vec2, 4> normals{rot.apply(Vec2(0, -1)), rot.apply(Vec2(1, 0)), rot.apply(Vec2(0, 1)),
                                    rot.apply(Vec2(-1, 0))};
  return rounded_polygon(corners_of<double>(r, origin).v.data(), normals.data(), 4, 0);
}

Boundary boundary(const Capsule& c, const Vec2& origin) {
  const Rot rot = Rot::of(c.angle);
  const Vec2 along = rot.apply(Vec2(c.half_length, 0)), across = rot.apply(Vec2(0, 1));
  const std::array<Vec2, 2> ends{c.center - origin - along, c.center - origin + along};
  const std::array<Vec2, 2> normals{-across, across};
  return rounded_polygon(ends.data(), normals.data(), 2, c.radius);
}

Boundary boundary(const ConvexPolygon& p, const Vec2& origin) {
  const Rot rot = Rot::of(p.angle);
  const PolygonOutline& o = *p.outline;
  std::array<Vec2, kMaxPolygonVertices> normals;
  for (int i = 0; i < o.count; ++i) normals[i] = rot.apply(o.normals[i]);
  return rounded_polygon(corners_of<double>(p, origin).v.data(), normals.data(), o.count, o.radius);
}

Boundary boundary(const Segment&, const Vec2&) { throw InvalidShape("a segment has no area"); }

}  // namespace

Vec2 Arc::unit(const Vec2& p) const { return length_and_direction(inverse * (p - c)).direction; }

Boundary boundary_of(const Shape& s, const Vec2& origin) {
  return std::visit([&](const auto& shape) { return boundary(shape, origin); }, s);
}

double turn_key(const Vec2& u0, const Vec2& u) {
  const double x = u0.dot(u), y = u0.x() * u.y() - u0.y() * u.x();
  if (y >= 0) return x >= 0 ? y / (x + y) : 1 - x / (y - x);
  return x < 0 ? 2 - y / (-x - y) : 3 + x / (x - y);
}

}  // namespace collide2d::detail::areas
