#include "narrowphase/area/boundary.h"

#include "narrowphase/area/clip.h"
#include "narrowphase/shared/frames/unit_vector.h"

#include <variant>

namespace collide2d::detail::areas {
namespace {

template <class Real>
ArcOf<Real> ellipse_arc(const V2<Real>& c, double a, double b, const Rotation<Real>& r) {
  ArcOf<Real> arc;
  arc.c = c;
  arc.m << a * r.c, -b * r.s, a * r.s, b * r.c;
  arc.inverse << r.c / a, r.s / a, -r.s / b, r.c / b;
  if constexpr (std::is_same_v<Real, double>)
    arc.det = a * b;
  else
    arc.det = two_product(a, b);
  arc.u0 = arc.u1 = V2<Real>::UnitX();
  arc.full = false;
  arc.circular = a == b;
  return arc;
}

// The whole curve as one piece, from and to the end of its first axis.
template <class Real>
BoundaryOf<Real> closed_curve(const ArcOf<Real>& curve) {
  BoundaryOf<Real> b;
  b.polygonal = false;
  b.count = 1;
  PieceOf<Real>& piece = b.pieces[0];
  piece.curved = true;
  piece.arc = curve;
  piece.arc.full = true;
  piece.start = piece.end = EndOf<Real>{curve.point(V2<Real>::UnitX()), V2<Real>::UnitX()};
  return b;
}

// The convex polygon of `count` vertices (a capsule's core has 2), each edge moved out by `radius`
// along its normal and each corner rounded by an arc about its vertex.
template <class Real>
BoundaryOf<Real> rounded_polygon(const V2<Real>* vertices, const V2<Real>* normals, int count, double radius) {
  BoundaryOf<Real> b;
  b.polygonal = radius == 0;
  for (int i = 0; i < count; ++i) {
    const int next = (i + 1) % count;
    const V2<Real> offset = Real(radius) * normals[i];
    PieceOf<Real>& edge = b.pieces[b.count++];
    edge.start = EndOf<Real>{vertices[i] + offset, V2<Real>::UnitX()};
    edge.end = EndOf<Real>{vertices[next] + offset, V2<Real>::UnitX()};
    edge.curved = false;
    if (radius == 0) continue;
    PieceOf<Real>& corner = b.pieces[b.count++];
    corner.curved = true;
    corner.arc = ellipse_arc(vertices[next], radius, radius, Rotation<Real>{});
    corner.arc.u0 = normals[i];
    corner.arc.u1 = normals[next];
    corner.start = {edge.end.p, normals[i]};
    corner.end = {V2<Real>(vertices[next] + Real(radius) * normals[next]), normals[next]};
  }
  return b;
}

template <class Real>
V2<Real> rotated(const Rotation<Real>& r, const Vec2& v) {
  return r.apply(widened<Real>(v));
}

template <class Real>
BoundaryOf<Real> boundary(const Circle& c, const Vec2& origin) {
  return closed_curve(ellipse_arc(offset<Real>(c.center, origin), c.radius, c.radius, Rotation<Real>{}));
}

template <class Real>
BoundaryOf<Real> boundary(const Ellipse& e, const Vec2& origin) {
  return closed_curve(ellipse_arc(offset<Real>(e.center, origin), e.a, e.b, Rotation<Real>::of(e.angle)));
}

template <class Real>
BoundaryOf<Real> boundary(const Rect& r, const Vec2& origin) {
  const auto rot = Rotation<Real>::of(r.angle);
  const std::array<V2<Real>, 4> normals{rotated(rot, Vec2(0, -1)), rotated(rot, Vec2(1, 0)), rotated(rot, Vec2(0, 1)),
                                        rotated(rot, Vec2(-1, 0))};
  return rounded_polygon(corners_of<Real>(r, origin).v.data(), normals.data(), 4, 0);
}

template <class Real>
BoundaryOf<Real> boundary(const Capsule& c, const Vec2& origin) {
  const auto rot = Rotation<Real>::of(c.angle);
  const V2<Real> along = rotated(rot, Vec2(c.half_length, 0)), across = rotated(rot, Vec2(0, 1));
  const V2<Real> center = offset<Real>(c.center, origin);
  const std::array<V2<Real>, 2> ends{center - along, center + along};
  const std::array<V2<Real>, 2> normals{-across, across};
  return rounded_polygon(ends.data(), normals.data(), 2, c.radius);
}

// In double the outline's normals turned; in double-double each edge's unit normal from its
// corners, as the outline's rounded normals would leave the edges off their offset by a few eps.
template <class Real>
BoundaryOf<Real> boundary(const ConvexPolygon& p, const Vec2& origin) {
  const auto rot = Rotation<Real>::of(p.angle);
  const PolygonOutline& o = *p.outline;
  const Corners<Real> corners = corners_of<Real>(p, origin);
  std::array<V2<Real>, kMaxPolygonVertices> normals;
  for (int i = 0; i < o.count; ++i) {
    if constexpr (std::is_same_v<Real, double>) {
      normals[i] = rotated(rot, o.normals[i]);
    } else {
      const V2<Real> e = corners.v[(i + 1) % o.count] - corners.v[i];
      normals[i] = V2<Real>(e.y(), -e.x()) / sqrt(e.squaredNorm());
    }
  }
  return rounded_polygon(corners.v.data(), normals.data(), o.count, o.radius);
}

template <class Real>
BoundaryOf<Real> boundary(const Segment&, const Vec2&) {
  throw InvalidShape("a segment has no area");
}

}  // namespace

template <>
Vec2 Arc::unit(const Vec2& p) const {
  return length_and_direction(inverse * (p - c)).direction;
}

template <>
V2<DoubleDouble> ArcOf<DoubleDouble>::unit(const V2<DoubleDouble>& p) const {
  const V2<DoubleDouble> v = inverse * (p - c);
  return v / sqrt(v.squaredNorm());
}

template <class Real>
BoundaryOf<Real> boundary_of(const Shape& s, const Vec2& origin) {
  return std::visit([&](const auto& shape) { return boundary<Real>(shape, origin); }, s);
}

template Boundary boundary_of<double>(const Shape&, const Vec2&);
template BoundaryOf<DoubleDouble> boundary_of<DoubleDouble>(const Shape&, const Vec2&);

double turn_key(const Vec2& u0, const Vec2& u) {
  const double x = u0.dot(u), y = u0.x() * u.y() - u0.y() * u.x();
  if (y >= 0) return x >= 0 ? y / (x + y) : 1 - x / (y - x);
  return x < 0 ? 2 - y / (-x - y) : 3 + x / (x - y);
}

}  // namespace collide2d::detail::areas
