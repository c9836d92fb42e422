// Convex polygons: their outlines made and checked once, and the public geometry of a posed polygon
// (its traits are inline in shapes/polygon.h).
#include <collide2d/shapes.h>

#include "shapes/polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace collide2d {
namespace {

using Rot = detail::Rotation<double>;
using detail::cross;

// The sign of the turn a -> b -> c: +1 left, -1 right, 0 where the determinant lies within the
// bound of its rounding (J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
// Robust Geometric Predicates", the bound of orient2d's first stage), so that a nonzero sign is
// the exact one.
int turn(const Vec2& a, const Vec2& b, const Vec2& c) {
  constexpr double u = std::numeric_limits<double>::epsilon() / 2;
  const double left = (a.x() - c.x()) * (b.y() - c.y());
  const double right = (a.y() - c.y()) * (b.x() - c.x());
  const double det = left - right;
  const double bound = (3 + 16 * u) * u * (std::abs(left) + std::abs(right));
  return det > bound ? 1 : det < -bound ? -1 : 0;
}

[[noreturn]] void refuse(const std::string& why) { throw InvalidShape("polygon " + why); }

void require_point(const char* what, std::size_t k, const Vec2& p) {
  const std::string name = std::string(what) + ' ' + std::to_string(k);
  detail::require_coordinate("polygon", (name + " x").c_str(), p.x());
  detail::require_coordinate("polygon", (name + " y").c_str(), p.y());
}

void require_radius(double radius) {
  detail::require_finite("polygon", "radius", radius);
  if (radius < 0.0) detail::reject("polygon", "radius", radius, "must be 0 or positive");
  if (radius != 0.0) detail::require_size("polygon", "radius", radius);
}

// The larger side of the points' bounding box.
double extent(std::span<const Vec2> points) {
  Vec2 lo = points[0], hi = points[0];
  for (const Vec2& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).maxCoeff();
}

// Each vertex strictly left of every edge it is not on: the vertices run counter-clockwise around a
// strictly convex polygon (a star whose turns are all left has a vertex right of some edge). Each
// edge, and each vertex's height over every other edge, is a size: at least 1e-50, which also keeps
// the orientation test's products clear of underflow, where its error bound would not hold.
void require_convex(std::span<const Vec2> v) {
  const std::size_t n = v.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t next = (i + 1) % n;
    const double length = (v[next] - v[i]).norm();
    if (!(length >= kMinSize)) {
      refuse("edge from vertex " + std::to_string(i) + " to " + std::to_string(next) + " is shorter than 1e-50");
    }
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i || j == next) continue;
      const int side = turn(v[i], v[next], v[j]);
      if (side > 0 && cross(v[next] - v[i], v[j] - v[i]) / length < kMinSize) {
        refuse("vertex " + std::to_string(j) + " lies within 1e-50 of the line of the edge from vertex " +
               std::to_string(i) + " to " + std::to_string(next) + ": thinner than the supported range");
      }
      if (side > 0) continue;
      const std::string where = "vertex " + std::to_string(j) + " lies " + (side < 0 ? "right of" : "on the line of") +
                                " the edge from vertex " + std::to_string(i) + " to " + std::to_string(next);
      refuse(side < 0 ? where + ": the vertices must run counter-clockwise around a convex polygon"
                      : where + " (to rounding): the polygon must be strictly convex");
    }
  }
}

// The centroid and area of the core polygon, the strips that the radius lays along its edges, and
// the circular sectors at its vertices (which make a whole disc together).
void set_mass(PolygonOutline& o) {
  const auto& v = o.vertices;
  const auto& n = o.normals;
  const double r = o.radius;
  const int count = o.count;
  double area = 0.0;
  Vec2 moment = Vec2::Zero();
  const auto add = [&](double a, const Vec2& c) { area += a, moment += a * c; };
  for (int i = 1; i + 1 < count; ++i) {
    const Vec2 p = v[i] - v[0], q = v[i + 1] - v[0];
    add(cross(p, q) / 2, v[0] + (p + q) / 3);
  }
  for (int i = 0; r > 0.0 && i < count; ++i) {
    const Vec2& next = v[(i + 1) % count];
    add((next - v[i]).norm() * r, (v[i] + next) / 2 + (r / 2) * n[i]);
    const Vec2& before = n[(i + count - 1) % count];
    const double half = detail::arc_tangent(cross(before, n[i]), before.dot(n[i])) / 2;
    add(r * r * half, v[i] + (2 * r * detail::cos_sin(half).s / (3 * half)) * (before + n[i]).normalized());
  }
  o.area = area;
  o.centroid = moment / area;
}

std::shared_ptr<const PolygonOutline> outline_of(std::span<const Vec2> vertices, double radius) {
  if (vertices.size() < 3 || vertices.size() > kMaxPolygonVertices)
    refuse("must have 3 to 8 vertices (got " + std::to_string(vertices.size()) + ")");
  for (std::size_t k = 0; k < vertices.size(); ++k) require_point("vertex", k, vertices[k]);
  require_radius(radius);
  if (!(extent(vertices) >= kMinSize)) refuse("is smaller than 1e-50 across");
  require_convex(vertices);
  auto o = std::make_shared<PolygonOutline>();
  o->count = static_cast<int>(vertices.size());
  o->radius = radius;
  for (int i = 0; i < o->count; ++i) {
    o->vertices[i] = vertices[i];
    const Vec2 edge = vertices[(i + 1) % o->count] - vertices[i];
    o->normals[i] = Vec2(edge.y(), -edge.x()) / edge.norm();
    o->reach = std::max(o->reach, vertices[i].norm());
  }
  std::fill(o->vertices.begin() + o->count, o->vertices.end(), vertices[0]);
  std::fill(o->normals.begin() + o->count, o->normals.end(), o->normals[0]);
  for (int i = 0; i < kMaxPolygonVertices; ++i) o->offsets[i] = o->normals[i].dot(o->vertices[i]);
  double nearest_face = std::numeric_limits<double>::infinity();
  for (int i = 0; i < o->count; ++i) nearest_face = std::min(nearest_face, o->offsets[i]);
  o->inner = nearest_face >= 0.0 ? nearest_face + radius : -1.0;
  o->reach += radius;
  set_mass(*o);
  return o;
}

// Andrew's monotone chain ("Another efficient algorithm for convex hulls in two dimensions"), each
// turn that is not certainly left dropped: the hull counter-clockwise from the lowest point in x.
std::vector<Vec2> monotone_hull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](const Vec2& p, const Vec2& q) { return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y()); });
  std::vector<Vec2> hull;
  const auto chain = [&](auto first, auto last, std::size_t floor) {
    for (auto it = first; it != last; ++it) {
      while (hull.size() > floor && turn(hull[hull.size() - 2], hull.back(), *it) <= 0) hull.pop_back();
      hull.push_back(*it);
    }
  };
  chain(points.begin(), points.end(), 1);
  chain(points.rbegin() + 1, points.rend(), hull.size());
  hull.pop_back();  // the first point, reached again
  return hull;
}

// Drops, one at a time, a vertex within `tolerance` of the next one or of the line of its two
// neighbours, until none is (or fewer than 3 remain).
void weld_hull(std::vector<Vec2>& hull, double tolerance) {
  for (bool dropped = true; dropped && hull.size() >= 3;) {
    dropped = false;
    for (std::size_t i = 0; i < hull.size() && !dropped; ++i) {
      const Vec2& before = hull[(i + hull.size() - 1) % hull.size()];
      const Vec2& next = hull[(i + 1) % hull.size()];
      const Vec2 chord = next - before;
      const bool near_next = (next - hull[i]).norm() <= tolerance;
      const bool near_line = std::abs(cross(chord, hull[i] - before)) <= tolerance * chord.norm();
      if (near_next || near_line) {
        hull.erase(hull.begin() + static_cast<std::ptrdiff_t>(i));
        dropped = true;
      }
    }
  }
}

}  // namespace

ConvexPolygon ConvexPolygon::of(std::span<const Vec2> vertices, double radius) {
  return {Vec2::Zero(), 0.0, outline_of(vertices, radius)};
}

ConvexPolygon ConvexPolygon::hull(std::span<const Vec2> points, double radius, double weld) {
  for (std::size_t k = 0; k < points.size(); ++k) require_point("point", k, points[k]);
  detail::require_finite("polygon", "weld", weld);
  if (weld < 0.0) detail::reject("polygon", "weld", weld, "must not be negative");
  if (points.size() < 3) refuse("needs at least 3 points (got " + std::to_string(points.size()) + ")");
  std::vector<Vec2> kept = monotone_hull({points.begin(), points.end()});
  weld_hull(kept, weld * extent(points));
  if (kept.size() < 3) refuse("points lie on one line, to the weld: they make no polygon");
  if (kept.size() > kMaxPolygonVertices)
    refuse("hull has " + std::to_string(kept.size()) + " vertices, more than the 8 supported");
  return of(kept, radius);
}

ConvexPolygon ConvexPolygon::box(double hx, double hy, double radius) {
  detail::require_size("polygon", "hx", hx);
  detail::require_size("polygon", "hy", hy);
  const Vec2 corners[] = {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}};
  return of(corners, radius);
}

ConvexPolygon ConvexPolygon::regular(int count, double circumradius, double radius) {
  if (count < 3 || count > kMaxPolygonVertices) refuse("must have 3 to 8 vertices (got " + std::to_string(count) + ")");
  detail::require_size("polygon", "circumradius", circumradius);
  std::array<Vec2, kMaxPolygonVertices> v;
  for (int k = 0; k < count; ++k) {
    const double t = 2 * std::numbers::pi * k / count;
    const detail::CosSin turn = detail::cos_sin(t);
    v[k] = circumradius * Vec2(turn.c, turn.s);
  }
  return of(std::span<const Vec2>(v.data(), static_cast<std::size_t>(count)), radius);
}

std::shared_ptr<const PolygonOutline> ConvexPolygon::square() {
  static const std::shared_ptr<const PolygonOutline> unit = box(1.0, 1.0).outline;
  return unit;
}

Vec2 ConvexPolygon::centroid() const { return center + Rot::of(angle).apply(outline->centroid); }

void validate(const ConvexPolygon& p) {
  detail::require_coordinate("polygon", "cx", p.center.x());
  detail::require_coordinate("polygon", "cy", p.center.y());
  detail::require_finite("polygon", "angle", p.angle);
  if (p.outline == nullptr) refuse("has no outline: make it with ConvexPolygon::of, hull, box or regular");
}

Aabb aabb(const ConvexPolygon& p) { return detail::oriented_box(p, Orientation::of(p.angle)); }

Vec2 support(const ConvexPolygon& p, const Vec2& d) { return detail::support(p, Rot::of(p.angle), d); }

bool contains(const ConvexPolygon& poly, const Vec2& p) {
  const Vec2 q = Rot::of(poly.angle).apply_inverse(Vec2(p - poly.center));
  const PolygonOutline& o = *poly.outline;
  bool inside = true;
  double nearest = std::numeric_limits<double>::infinity();  // squared distance to the core's boundary
  for (int i = 0; i < o.count; ++i) {
    const Vec2& a = o.vertices[i];
    const Vec2 edge = o.vertices[(i + 1) % o.count] - a;
    inside = inside && o.normals[i].dot(q - a) <= 0.0;
    const double t = std::clamp((q - a).dot(edge) / edge.squaredNorm(), 0.0, 1.0);
    nearest = std::min(nearest, (q - a - t * edge).squaredNorm());
  }
  return inside || nearest <= o.radius * o.radius;
}

}  // namespace collide2d
