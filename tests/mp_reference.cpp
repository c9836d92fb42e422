#include "mp_reference.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

namespace collide2d::reference {
namespace {

using boost::multiprecision::abs;
using boost::multiprecision::sqrt;

struct Frame {
  Point center;
  Real c;
  Real s;
};

Frame frame_of(const Vec2& center, double angle) {
  const Real t(angle);
  return {to_mp(center), boost::multiprecision::cos(t), boost::multiprecision::sin(t)};
}

Point to_local(const Frame& f, const Point& p) {
  const Real dx = p.x - f.center.x;
  const Real dy = p.y - f.center.y;
  return {f.c * dx + f.s * dy, -f.s * dx + f.c * dy};
}

Point to_world(const Frame& f, const Point& p) {
  return {f.center.x + f.c * p.x - f.s * p.y, f.center.y + f.s * p.x + f.c * p.y};
}

Real norm(const Real& x, const Real& y) { return sqrt(x * x + y * y); }

Real point_ellipse(const Ellipse& e, const Point& world) {
  const Point p = to_local(frame_of(e.center, e.angle), world);
  const Real a(e.a), b(e.b);
  const Real y0 = abs(p.x), y1 = abs(p.y);
  const Real q = (y0 / a) * (y0 / a) + (y1 / b) * (y1 / b);
  if (q <= 1) return Real(0);
  // F(t) = (a y0 / (t + a^2))^2 + (b y1 / (t + b^2))^2 - 1 is convex and decreasing for t > -b^2,
  // positive at t = 0 for an outside point: Newton from t = 0 climbs monotonically to the root.
  const Real a2 = a * a, b2 = b * b;
  Real t = 0;
  for (int k = 0; k < 400; ++k) {
    const Real r0 = a * y0 / (t + a2), r1 = b * y1 / (t + b2);
    const Real f = r0 * r0 + r1 * r1 - 1;
    const Real df = -2 * (r0 * r0 / (t + a2) + r1 * r1 / (t + b2));
    const Real next = t - f / df;
    if (!(next > t)) break;
    t = next;
  }
  const Real x0 = a2 * y0 / (t + a2), x1 = b2 * y1 / (t + b2);
  return norm(x0 - y0, x1 - y1);
}

std::array<Point, 4> rect_corners(const Rect& r) {
  const Frame f = frame_of(r.center, r.angle);
  const Real hx(r.half_extents.x()), hy(r.half_extents.y());
  return {to_world(f, {-hx, -hy}), to_world(f, {hx, -hy}), to_world(f, {hx, hy}), to_world(f, {-hx, hy})};
}

Real point_rect(const Rect& r, const Point& world) {
  const Point p = to_local(frame_of(r.center, r.angle), world);
  const Real dx = std::max(Real(0), abs(p.x) - Real(r.half_extents.x()));
  const Real dy = std::max(Real(0), abs(p.y) - Real(r.half_extents.y()));
  return norm(dx, dy);
}

Real point_circle(const Circle& c, const Point& world) {
  const Point o = to_mp(c.center);
  return std::max(Real(0), norm(world.x - o.x, world.y - o.y) - Real(c.radius));
}

Point lerp(const Point& p, const Point& q, const Real& t) { return {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)}; }

// Least value of a convex function on [0, 1] by golden-section search, endpoints included.
template <class F>
Real convex_minimum(F f) {
  const Real g = (sqrt(Real(5)) - 1) / 2;
  Real lo = 0, hi = 1;
  Real x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  Real f1 = f(x1), f2 = f(x2);
  for (int k = 0; k < 90; ++k) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = f(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = f(x2);
    }
  }
  return std::min({f1, f2, f(Real(0)), f(Real(1))});
}

Real point_segment(const Point& p, const Point& a, const Point& b) {
  const Real dx = b.x - a.x, dy = b.y - a.y;
  Real t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
  t = std::clamp(t, Real(0), Real(1));
  return norm(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// Least ellipse quadratic Q = (u0/a)^2 + (u1/b)^2 over the segment p -> q (world points).
Real least_quadratic(const Ellipse& e, const Point& p, const Point& q) {
  const Frame f = frame_of(e.center, e.angle);
  const Point lp = to_local(f, p), lq = to_local(f, q);
  const Real a(e.a), b(e.b);
  const Real w0 = lp.x / a, w1 = lp.y / b;
  const Real d0 = lq.x / a - w0, d1 = lq.y / b - w1;
  const Real t = std::clamp(-(w0 * d0 + w1 * d1) / (d0 * d0 + d1 * d1), Real(0), Real(1));
  const Real x = w0 + t * d0, y = w1 + t * d1;
  return x * x + y * y;
}

bool rect_ellipse_overlap(const Rect& r, const Ellipse& e) {
  if (point_rect(r, to_mp(e.center)) == 0) return true;
  const auto c = rect_corners(r);
  for (int k = 0; k < 4; ++k) {
    if (least_quadratic(e, c[k], c[(k + 1) % 4]) <= 1) return true;
  }
  return false;
}

Real rect_ellipse_distance(const Rect& r, const Ellipse& e) {
  if (rect_ellipse_overlap(r, e)) return Real(0);
  const auto c = rect_corners(r);
  Real best = -1;
  for (int k = 0; k < 4; ++k) {
    const Point p = c[k], q = c[(k + 1) % 4];
    const Real d = convex_minimum([&](const Real& t) { return point_ellipse(e, lerp(p, q, t)); });
    if (best < 0 || d < best) best = d;
  }
  return best;
}

// Projection interval of the rectangle's corners on axis (ux, uy).
std::pair<Real, Real> project(const std::array<Point, 4>& c, const Real& ux, const Real& uy) {
  Real lo = c[0].x * ux + c[0].y * uy, hi = lo;
  for (const Point& p : c) {
    const Real v = p.x * ux + p.y * uy;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return {lo, hi};
}

bool rect_rect_overlap(const Rect& a, const Rect& b) {
  const auto ca = rect_corners(a), cb = rect_corners(b);
  for (const auto* c : {&ca, &cb}) {
    for (int k = 0; k < 2; ++k) {
      const Real ux = (*c)[k + 1].x - (*c)[k].x, uy = (*c)[k + 1].y - (*c)[k].y;
      const auto [alo, ahi] = project(ca, ux, uy);
      const auto [blo, bhi] = project(cb, ux, uy);
      if (ahi < blo || bhi < alo) return false;
    }
  }
  return true;
}

Real rect_rect_distance(const Rect& a, const Rect& b) {
  if (rect_rect_overlap(a, b)) return Real(0);
  const auto ca = rect_corners(a), cb = rect_corners(b);
  Real best = -1;
  for (const auto& [from, to] : {std::pair{&ca, &cb}, std::pair{&cb, &ca}}) {
    for (const Point& p : *from) {
      for (int k = 0; k < 4; ++k) {
        const Real d = point_segment(p, (*to)[k], (*to)[(k + 1) % 4]);
        if (best < 0 || d < best) best = d;
      }
    }
  }
  return best;
}

// Distance between a circle and any other solid: the other's distance to the centre, less r.
Real circle_distance(const Circle& c, const Shape& other) {
  return std::max(Real(0), distance_to(other, to_mp(c.center)) - Real(c.radius));
}

}  // namespace

Point to_mp(const Vec2& p) { return {Real(p.x()), Real(p.y())}; }

Real distance_to(const Shape& s, const Point& p) {
  if (const auto* c = std::get_if<Circle>(&s)) return point_circle(*c, p);
  if (const auto* e = std::get_if<Ellipse>(&s)) return point_ellipse(*e, p);
  return point_rect(std::get<Rect>(s), p);
}

Real distance(const Shape& a, const Shape& b) {
  if (const auto* c = std::get_if<Circle>(&a)) return circle_distance(*c, b);
  if (const auto* c = std::get_if<Circle>(&b)) return circle_distance(*c, a);
  const auto* ra = std::get_if<Rect>(&a);
  const auto* rb = std::get_if<Rect>(&b);
  if (ra && rb) return rect_rect_distance(*ra, *rb);
  if (ra) return rect_ellipse_distance(*ra, std::get<Ellipse>(b));
  if (rb) return rect_ellipse_distance(*rb, std::get<Ellipse>(a));
  throw std::logic_error("reference: ellipse-ellipse is not covered");
}

bool overlap(const Shape& a, const Shape& b) {
  const auto* ra = std::get_if<Rect>(&a);
  const auto* rb = std::get_if<Rect>(&b);
  const auto* eb = std::get_if<Ellipse>(&b);
  const auto* ea = std::get_if<Ellipse>(&a);
  if (ra && eb) return rect_ellipse_overlap(*ra, *eb);
  if (rb && ea) return rect_ellipse_overlap(*rb, *ea);
  if (ra && rb) return rect_rect_overlap(*ra, *rb);
  return distance(a, b) == 0;
}

}  // namespace collide2d::reference
