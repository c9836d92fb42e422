#include "bench/box2d_v3/report.h"

#include "bench/box2d_v3/manifold.h"

#include <vector>

namespace collide2d::box2d_v3 {
namespace {

// The report's shapes are 0.05 to 1 across, aspect up to 10; v3 is tuned for 0.1 to 10 m (its hull
// welds points within 2 cm and drops points within 1 cm of a line, so a thin ellipse's polygon
// loses vertices or collapses). Posed at kScale times their size, a power of two that leaves the
// float shapes' relative rounding unchanged, v3's errors are its polygons' alone.
constexpr double kScale = 16.0;

Rect scaled(const Rect& r) { return {kScale * r.center, kScale * r.half_extents, r.angle}; }
Circle scaled(const Circle& c) { return {kScale * c.center, kScale * c.radius}; }
Ellipse scaled(const Ellipse& e) { return {kScale * e.center, kScale * e.a, kScale * e.b, e.angle}; }
Capsule scaled(const Capsule& c) { return {kScale * c.center, kScale * c.half_length, kScale * c.radius, c.angle}; }
Segment scaled(const Segment& s) { return {kScale * s.center, kScale * s.end, s.angle}; }
ConvexPolygon scaled(const ConvexPolygon& p) {
  std::vector<Vec2> vertices;
  for (const Vec2& v : p.vertices()) vertices.push_back(kScale * v);
  return ConvexPolygon::of(vertices, kScale * p.radius()).at(kScale * p.center, p.angle);
}

template <class S>
std::vector<S> scaled(const std::vector<S>& shapes) {
  std::vector<S> out;
  for (const S& s : shapes) out.push_back(scaled(s));
  return out;
}

Vec2 to_double(b2Vec2 v) { return Vec2(v.x, v.y) / kScale; }

}  // namespace

template <class A>
Manifolds manifolds(const std::vector<A>& a, const std::vector<Ellipse>& b, int sides) {
  return [pa = posed_shapes(scaled(a), sides),
          pb = posed_shapes(scaled(b), sides)](std::size_t k) -> std::optional<Deepest> {
    const WorldManifold m = manifold(pa[k], pb[k]);
    if (m.count == 0) return std::nullopt;
    const int deepest = m.count == 2 && m.separations[1] < m.separations[0];
    return Deepest{m.separations[deepest] / kScale, Vec2(m.normal.x, m.normal.y), to_double(m.points[deepest])};
  };
}

template Manifolds manifolds(const std::vector<Rect>&, const std::vector<Ellipse>&, int);
template Manifolds manifolds(const std::vector<Circle>&, const std::vector<Ellipse>&, int);
template Manifolds manifolds(const std::vector<Ellipse>&, const std::vector<Ellipse>&, int);
template Manifolds manifolds(const std::vector<ConvexPolygon>&, const std::vector<Ellipse>&, int);
template Manifolds manifolds(const std::vector<Capsule>&, const std::vector<Ellipse>&, int);
template Manifolds manifolds(const std::vector<Segment>&, const std::vector<Ellipse>&, int);

}  // namespace collide2d::box2d_v3
