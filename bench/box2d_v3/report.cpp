#include "bench/box2d_v3/report.h"

#include "bench/box2d_v3/manifold.h"

namespace collide2d::box2d_v3 {
namespace {

Vec2 to_double(b2Vec2 v) { return {v.x, v.y}; }

}  // namespace

template <class A>
Manifolds manifolds(const std::vector<A>& a, const std::vector<Ellipse>& b, int sides) {
  return [pa = posed_shapes(a, sides), pb = posed_shapes(b, sides)](std::size_t k) -> std::optional<Deepest> {
    const WorldManifold m = manifold(pa[k], pb[k]);
    if (m.count == 0) return std::nullopt;
    const int deepest = m.count == 2 && m.separations[1] < m.separations[0];
    return Deepest{m.separations[deepest], to_double(m.normal), to_double(m.points[deepest])};
  };
}

template Manifolds manifolds(const std::vector<Rect>&, const std::vector<Ellipse>&, int);
template Manifolds manifolds(const std::vector<Circle>&, const std::vector<Ellipse>&, int);
template Manifolds manifolds(const std::vector<Ellipse>&, const std::vector<Ellipse>&, int);
template Manifolds manifolds(const std::vector<ConvexPolygon>&, const std::vector<Ellipse>&, int);
template Manifolds manifolds(const std::vector<Capsule>&, const std::vector<Ellipse>&, int);
template Manifolds manifolds(const std::vector<Segment>&, const std::vector<Ellipse>&, int);

}  // namespace collide2d::box2d_v3
