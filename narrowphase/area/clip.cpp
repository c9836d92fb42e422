#include "narrowphase/area/clip.h"

#include <variant>

namespace collide2d::detail::areas {
namespace {

// The corners c + R(angle) v of `count` local corners v, c the centre's offset from the origin.
template <class Real>
Corners<Real> placed(const Vec2& center, double angle, const Vec2* local, int count, const Vec2& origin) {
  const auto rot = Rotation<Real>::of(angle);
  const V2<Real> c = offset<Real>(center, origin);
  Corners<Real> out;
  out.count = count;
  for (int i = 0; i < count; ++i) out.v[i] = c + rot.apply(widened<Real>(local[i]));
  return out;
}

}  // namespace

template <class Real>
Corners<Real> corners_of(const Rect& r, const Vec2& origin) {
  const Vec2 h = r.half_extents;
  const std::array<Vec2, 4> local{Vec2(-h.x(), -h.y()), Vec2(h.x(), -h.y()), h, Vec2(-h.x(), h.y())};
  return placed<Real>(r.center, r.angle, local.data(), 4, origin);
}

template <class Real>
Corners<Real> corners_of(const ConvexPolygon& p, const Vec2& origin) {
  return placed<Real>(p.center, p.angle, p.outline->vertices.data(), p.outline->count, origin);
}

template <class Real>
Corners<Real> corners_of(const Shape& s, const Vec2& origin) {
  if (const auto* r = std::get_if<Rect>(&s)) return corners_of<Real>(*r, origin);
  return corners_of<Real>(std::get<ConvexPolygon>(s), origin);
}

template <class Real>
Corners<Real> clipped(const Corners<Real>& subject, const Corners<Real>& clipper) {
  Corners<Real> poly = subject, next;
  for (int j = 0; j < clipper.count && poly.count > 0; ++j) {
    const V2<Real> q = clipper.v[j], e = clipper.v[(j + 1) % clipper.count] - q;
    next.count = 0;
    for (int i = 0; i < poly.count; ++i) {
      const V2<Real>&p0 = poly.v[i], &p1 = poly.v[(i + 1) % poly.count];
      const Real s0 = cross(e, V2<Real>(p0 - q)), s1 = cross(e, V2<Real>(p1 - q));
      if (s0 >= 0) next.v[next.count++] = p0;
      if ((s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0)) next.v[next.count++] = p0 + (s0 / (s0 - s1)) * (p1 - p0);
    }
    poly = next;
  }
  return poly;
}

template <class Real>
Moments<Real> moments_of(const Corners<Real>& p) {
  if (p.count < 3) return {};
  Fan<Real> fan;
  for (int i = 1; i + 1 < p.count; ++i) fan.add(p.v[i] - p.v[0], p.v[i + 1] - p.v[0]);
  const Real area = fan.twice_area / 2;
  return {area, fan.moment6 / 6 + area * p.v[0]};
}

template Corners<double> corners_of(const Rect&, const Vec2&);
template Corners<double> corners_of(const ConvexPolygon&, const Vec2&);
template Corners<double> corners_of(const Shape&, const Vec2&);
template Corners<DoubleDouble> corners_of(const Rect&, const Vec2&);
template Corners<DoubleDouble> corners_of(const ConvexPolygon&, const Vec2&);
template Corners<DoubleDouble> corners_of(const Shape&, const Vec2&);
template Corners<double> clipped(const Corners<double>&, const Corners<double>&);
template Corners<DoubleDouble> clipped(const Corners<DoubleDouble>&, const Corners<DoubleDouble>&);
template Moments<double> moments_of(const Corners<double>&);
template Moments<DoubleDouble> moments_of(const Corners<DoubleDouble>&);

}  // namespace collide2d::detail::areas
