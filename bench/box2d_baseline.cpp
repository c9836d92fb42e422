#include "bench/box2d_baseline.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <type_traits>

namespace collide2d::baseline {
namespace {

b2Vec2 to_float(const Vec2& p) { return {static_cast<float>(p.x()), static_cast<float>(p.y())}; }

Vec2 rotate(double angle, const Vec2& v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

Polygon ellipse_polygon(const Ellipse& e, int sides, Fit fit, const Vec2& origin) {
  if (sides < 3) throw std::invalid_argument("a polygon needs at least 3 sides");
  // Circumscribed: the regular N-gon around the unit circle has its vertices at radius 1/cos(pi/N),
  // half a step off the tangent points; the ellipse's affine map keeps it around the ellipse.
  const double step = 2 * std::numbers::pi / sides;
  const double scale = fit == Fit::circumscribed ? 1.0 / std::cos(step / 2) : 1.0;
  const double shift = fit == Fit::circumscribed ? step / 2 : 0.0;
  Polygon p;
  for (int k = 0; k < sides; ++k) {
    const double t = k * step + shift;
    const Vec2 local(scale * e.a * std::cos(t), scale * e.b * std::sin(t));
    p.vertices.push_back(to_float(e.center - origin + rotate(e.angle, local)));
  }
  return p;
}

// Box2D 2.4.1 has no capsule. Its nearest equivalent is a rounded box (b2PolygonShape's m_radius):
// half extents (h + w, w) rounded by r - w, whose support function passes the capsule's by at most
// w (|cos| + |sin| - 1) <= 0.42 w. w = 0.003, just wider than the 0.0025 within which Box2D welds
// two vertices into one.
Polygon capsule_polygon(const Capsule& c, const Vec2& origin) {
  constexpr double w = kCapsuleBoxHalfWidth;
  if (!(c.radius > w)) throw std::invalid_argument("a capsule of radius below 0.003 has no Box2D 2.4.1 equivalent");
  Polygon p;
  for (const Vec2& corner : {Vec2(1, 1), Vec2(-1, 1), Vec2(-1, -1), Vec2(1, -1)}) {
    const Vec2 local = corner.cwiseProduct(Vec2(c.half_length + w, w));
    p.vertices.push_back(to_float(c.center - origin + rotate(c.angle, local)));
  }
  p.radius = static_cast<float>(c.radius - w);
  return p;
}

}  // namespace

b2AABB to_box2d(const Aabb& box) {
  b2AABB out;
  out.lowerBound.Set(static_cast<float>(box.min.x()), static_cast<float>(box.min.y()));
  out.upperBound.Set(static_cast<float>(box.max.x()), static_cast<float>(box.max.y()));
  return out;
}

Polygon to_box2d(const Shape& shape, int sides, Fit fit, const Vec2& origin) {
  if (const auto* e = std::get_if<Ellipse>(&shape)) return ellipse_polygon(*e, sides, fit, origin);
  if (const auto* c = std::get_if<Circle>(&shape))
    return {{to_float(c->center - origin)}, static_cast<float>(c->radius)};
  if (const auto* c = std::get_if<Capsule>(&shape)) return capsule_polygon(*c, origin);
  if (const auto* g = std::get_if<Segment>(&shape)) {
    return {{to_float(g->point1() - origin), to_float(g->point2() - origin)}, 0.0f};
  }
  if (const auto* q = std::get_if<ConvexPolygon>(&shape)) {
    if (q->radius() != 0.0) throw std::invalid_argument("Box2D 2.4.1 has no rounded polygons");
    Polygon p;
    for (const Vec2& v : q->vertices()) p.vertices.push_back(to_float(q->center - origin + rotate(q->angle, v)));
    return p;
  }
  const auto& r = std::get<Rect>(shape);
  Polygon p;
  for (const Vec2& corner : {Vec2(1, 1), Vec2(-1, 1), Vec2(-1, -1), Vec2(1, -1)}) {
    p.vertices.push_back(to_float(r.center - origin + rotate(r.angle, Vec2(corner.cwiseProduct(r.half_extents)))));
  }
  return p;
}

double box2d_distance(const Polygon& a, const Polygon& b) {
  b2DistanceInput input;
  input.proxyA.Set(a.vertices.data(), static_cast<int32>(a.vertices.size()), a.radius);
  input.proxyB.Set(b.vertices.data(), static_cast<int32>(b.vertices.size()), b.radius);
  input.transformA.SetIdentity();
  input.transformB.SetIdentity();
  input.useRadii = true;
  b2SimplexCache cache;
  cache.count = 0;
  b2DistanceOutput output;
  b2Distance(&output, &cache, &input);
  return output.distance;
}

Box2dShape to_box2d_shape(const Polygon& p) {
  Box2dShape out;
  out.round = p.vertices.size() == 1;
  out.is_edge = p.vertices.size() == 2;
  if (out.is_edge) {
    out.edge.SetTwoSided(p.vertices[0], p.vertices[1]);
    out.edge.m_radius = p.radius;  // no skin, as the polygons
  } else if (out.round) {
    out.circle.m_p = p.vertices[0];
    out.circle.m_radius = p.radius;
  } else {
    out.polygon.Set(p.vertices.data(), static_cast<int32>(p.vertices.size()));
    out.polygon.m_radius = p.radius;
  }
  return out;
}

std::vector<Box2dShape> to_box2d_chain(std::span<const Vec2> points, const Vec2& origin) {
  std::vector<b2Vec2> v;
  for (const Vec2& p : points) v.push_back(to_float(p - origin));
  b2ChainShape chain;
  chain.CreateChain(v.data() + 1, static_cast<int32>(v.size() - 2), v.front(), v.back());
  std::vector<Box2dShape> out(v.size() - 3);
  for (std::size_t k = 0; k < out.size(); ++k) {
    out[k].is_edge = true;
    chain.GetChildEdge(&out[k].edge, static_cast<int32>(k));
    out[k].edge.m_radius = 0.0f;  // no skin, as the polygons
  }
  return out;
}

ShapePair to_box2d_shapes(const Polygon& a, const Polygon& b) { return {{to_box2d_shape(a), to_box2d_shape(b)}}; }

bool box2d_overlap(const ShapePair& pair) {
  b2Transform identity;
  identity.SetIdentity();
  return b2TestOverlap(pair.shape(0), 0, pair.shape(1), 0, identity, identity);
}

void box2d_overlaps(std::span<const ShapePair> pairs, std::span<std::uint8_t> overlapping) {
  b2Transform identity;
  identity.SetIdentity();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    overlapping[k] = b2TestOverlap(pairs[k].shape(0), 0, pairs[k].shape(1), 0, identity, identity) ? 1 : 0;
  }
}

void box2d_manifolds(std::span<const ShapePair> pairs, std::span<b2Manifold> manifolds) {
  for (std::size_t k = 0; k < pairs.size(); ++k) box2d_manifold(pairs[k], &manifolds[k]);
}

void box2d_manifold(const ShapePair& pair, b2Manifold* manifold) {
  b2Transform identity;
  identity.SetIdentity();
  const Box2dShape& a = pair.side[0];
  const Box2dShape& b = pair.side[1];
  if (a.is_edge || b.is_edge) {
    const Box2dShape &edge = a.is_edge ? a : b, &other = a.is_edge ? b : a;
    if (other.round) {
      b2CollideEdgeAndCircle(manifold, &edge.edge, identity, &other.circle, identity);
    } else {
      b2CollideEdgeAndPolygon(manifold, &edge.edge, identity, &other.polygon, identity);
    }
  } else if (a.round && b.round) {
    b2CollideCircles(manifold, &a.circle, identity, &b.circle, identity);
  } else if (b.round) {
    b2CollidePolygonAndCircle(manifold, &a.polygon, identity, &b.circle, identity);
  } else if (a.round) {
    b2CollidePolygonAndCircle(manifold, &b.polygon, identity, &a.circle, identity);
  } else {
    b2CollidePolygons(manifold, &a.polygon, identity, &b.polygon, identity);
  }
}

std::optional<Box2dContact> box2d_contact(const ShapePair& pair) {
  b2Manifold manifold;
  box2d_manifold(pair, &manifold);
  if (manifold.pointCount == 0) return std::nullopt;
  const bool swapped = pair.side[1].is_edge ? !pair.side[0].is_edge : pair.side[0].round && !pair.side[1].round;
  const int first = swapped ? 1 : 0;
  b2Transform identity;
  identity.SetIdentity();
  b2WorldManifold world;
  world.Initialize(&manifold, identity, pair.shape(first)->m_radius, identity, pair.shape(1 - first)->m_radius);
  int deepest = 0;
  for (int i = 1; i < manifold.pointCount; ++i)
    deepest = world.separations[i] < world.separations[deepest] ? i : deepest;
  const Vec2 normal(world.normal.x, world.normal.y);
  return Box2dContact{world.separations[deepest], swapped ? Vec2(-normal) : normal,
                      Vec2(world.points[deepest].x, world.points[deepest].y)};
}

namespace {

b2Sweep sweep_of(const Shape& s, const Motion& m, const Vec2& origin) {
  b2Sweep sweep;
  sweep.localCenter.SetZero();
  sweep.c0 = to_float(center_of(s) - origin);
  sweep.c = to_float(center_of(s) + m.velocity - origin);
  sweep.a0 = static_cast<float>(angle_of(s));
  sweep.a = static_cast<float>(angle_of(s) + m.angular_velocity);
  sweep.alpha0 = 0.0f;
  return sweep;
}

// The shape in its own frame: centred at the origin, angle 0.
Shape at_rest(Shape s) {
  std::visit(
      [](auto& x) {
        x.center = Vec2::Zero();
        if constexpr (!std::is_same_v<std::decay_t<decltype(x)>, Circle>) x.angle = 0.0;
      },
      s);
  return s;
}

}  // namespace

ToiPair to_box2d_toi(const Shape& a, const Motion& ma, const Shape& b, const Motion& mb, int sides, Fit fit) {
  const Vec2 origin = center_of(a);
  return {to_box2d(at_rest(a), sides, fit, Vec2::Zero()), to_box2d(at_rest(b), sides, fit, Vec2::Zero()),
          sweep_of(a, ma, origin), sweep_of(b, mb, origin)};
}

void box2d_time_of_impact(const ToiPair& pair, b2TOIOutput* out) {
  b2TOIInput input;
  input.proxyA.Set(pair.a.vertices.data(), static_cast<int32>(pair.a.vertices.size()), pair.a.radius);
  input.proxyB.Set(pair.b.vertices.data(), static_cast<int32>(pair.b.vertices.size()), pair.b.radius);
  input.sweepA = pair.sweep_a;
  input.sweepB = pair.sweep_b;
  input.tMax = 1.0f;
  b2TimeOfImpact(out, &input);
}

std::vector<std::uint32_t> Box2dBroadPhase::insert_batch(const std::vector<Aabb>& boxes) {
  std::vector<std::uint32_t> ids;
  for (const Aabb& box : boxes) {
    ids.push_back(static_cast<std::uint32_t>(proxy_.size()));
    const b2AABB b = to_box2d(box);
    proxy_.push_back(tree_.CreateProxy(b, reinterpret_cast<void*>(static_cast<std::uintptr_t>(ids.back()))));
    centre_.push_back(b.GetCenter());
  }
  return ids;
}

void Box2dBroadPhase::move(std::uint32_t id, const b2AABB& box) {
  const b2Vec2 centre = box.GetCenter();
  tree_.MoveProxy(proxy_[id], box, centre - centre_[id]);
  centre_[id] = centre;
}

void Box2dBroadPhase::update() {
  tree_.UpdatePairs(this);
  std::erase_if(pairs_,
                [this](std::uint64_t key) { return !tree_.TestOverlap(proxy_[key >> 32], proxy_[key & 0xffffffffu]); });
}

void Box2dBroadPhase::AddPair(void* a, void* b) {
  const auto p = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(a));
  const auto q = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(b));
  pairs_.insert(p < q ? p << 32 | q : q << 32 | p);
}

}  // namespace collide2d::baseline
