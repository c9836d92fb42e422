#include "mp_reference.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

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

double sqrt_of(double x) { return std::sqrt(x); }
Real sqrt_of(const Real& x) { return sqrt(x); }

template <class R>
R signed_curve_distance(R a, R b, R x, R y);

Real point_ellipse(const Ellipse& e, const Point& world) {
  const Point p = to_local(frame_of(e.center, e.angle), world);
  return std::max(Real(0), signed_curve_distance(Real(e.a), Real(e.b), p.x, p.y));
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
  const Real dd = d0 * d0 + d1 * d1;  // 0 for an edge of a rectangle with no width
  const Real t = dd > 0 ? std::clamp(-(w0 * d0 + w1 * d1) / dd, Real(0), Real(1)) : Real(0);
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

// Separating axes: each rectangle's two axis directions (from its frame rather than its edges, so
// that a rectangle with no width, a segment, keeps the axis across it).
bool rect_rect_overlap(const Rect& a, const Rect& b) {
  const auto ca = rect_corners(a), cb = rect_corners(b);
  for (const Rect* r : {&a, &b}) {
    const Frame f = frame_of(r->center, r->angle);
    for (const auto& [ux, uy] : {std::pair{f.c, f.s}, std::pair{-f.s, f.c}}) {
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

// Signed distance from (x, y) (in the ellipse frame) to the curve of the ellipse (a, b): negative
// inside. With a >= b the nearest point is (a^2 y0 / (t + a^2), b^2 y1 / (t + b^2)) for the root t
// of F(t) = (a y0 / (t + a^2))^2 + (b y1 / (t + b^2))^2 - 1, convex and decreasing for t > -b^2;
// Newton from a point where F >= 0 (t = 0 outside, t = -b^2 + b y1 inside) climbs to it
// monotonically. Inside on the major axis the nearest point leaves the axis within the evolute.
template <class R>
R signed_curve_distance(R a, R b, R x, R y) {
  using boost::multiprecision::abs;
  using std::abs;
  if (b > a) std::swap(a, b), std::swap(x, y);
  const R y0 = abs(x), y1 = abs(y);
  const R q = (y0 / a) * (y0 / a) + (y1 / b) * (y1 / b);
  if (q == 1) return R(0);
  const R a2 = a * a, b2 = b * b;
  R x0, x1;
  if (q < 1 && y1 == 0) {
    if (y0 * a < a2 - b2) {
      x0 = a2 * y0 / (a2 - b2);
      const R w = 1 - (x0 / a) * (x0 / a);
      x1 = b * sqrt_of(w < 0 ? R(0) : w);
    } else {
      x0 = a, x1 = 0;
    }
  } else {
    R t = q > 1 ? R(0) : -b2 + b * y1;
    for (int k = 0; k < 2000; ++k) {
      const R r0 = a * y0 / (t + a2), r1 = b * y1 / (t + b2);
      const R f = r0 * r0 + r1 * r1 - 1;
      const R df = -2 * (r0 * r0 / (t + a2) + r1 * r1 / (t + b2));
      const R next = t - f / df;
      if (!(next > t)) break;
      t = next;
    }
    x0 = a2 * y0 / (t + a2), x1 = b2 * y1 / (t + b2);
  }
  const R d = sqrt_of((x0 - y0) * (x0 - y0) + (x1 - y1) * (x1 - y1));
  return q > 1 ? d : -d;
}

// The largest distance from (x, y) (in the ellipse frame) to the curve of the ellipse (a, b). With
// a >= b and (y0, y1) = (|x|, |y|), the farthest point is (a^2 y0 / (t + a^2), b^2 y1 / (t + b^2))
// for the root t < -a^2 of the F above, where F is convex and increasing from -1 to +infinity; Newton
// from t = -a^2 - a y0 (where F >= 0) descends to it monotonically. On the minor axis (y0 = 0) that
// root exists only when b y1 > a^2 - b^2; otherwise t = -a^2 and the farthest points leave the axis.
Real farthest_curve_distance(Real a, Real b, Real x, Real y) {
  if (b > a) std::swap(a, b), std::swap(x, y);
  const Real y0 = abs(x), y1 = abs(y), a2 = a * a, b2 = b * b;
  Real x0, x1;
  if (y0 == 0 && !(b * y1 > a2 - b2)) {
    x1 = a2 > b2 ? -b2 * y1 / (a2 - b2) : Real(0);
    const Real w = 1 - (x1 / b) * (x1 / b);
    x0 = a * sqrt(w < 0 ? Real(0) : w);
  } else {
    Real t = y0 > 0 ? -a2 - a * y0 : -b2 - b * y1;
    for (int k = 0; k < 2000 && y0 > 0; ++k) {
      const Real r0 = a * y0 / (t + a2), r1 = b * y1 / (t + b2);
      const Real f = r0 * r0 + r1 * r1 - 1;
      const Real df = -2 * (r0 * r0 / (t + a2) + r1 * r1 / (t + b2));
      const Real next = t - f / df;
      if (!(next < t)) break;
      t = next;
    }
    x0 = a2 * y0 / (t + a2), x1 = b2 * y1 / (t + b2);
  }
  return sqrt((x0 - y0) * (x0 - y0) + (x1 - y1) * (x1 - y1));
}

// The gap between the curves of a circle and an ellipse from the distances of the circle's centre
// to the ellipse's curve, nearest and farthest (both roots of secular equations, each unique on its
// branch): no sampling, so no extremum can be missed.
Real circle_ellipse_boundary(const Circle& c, const Ellipse& e) {
  const Point p = to_local(frame_of(e.center, e.angle), to_mp(c.center));
  const Real near = signed_curve_distance(Real(e.a), Real(e.b), p.x, p.y);
  const Real r(c.radius);
  if (abs(near) >= r) return abs(near) - r;  // apart, or the circle inside the ellipse
  const Real far = farthest_curve_distance(Real(e.a), Real(e.b), p.x, p.y);
  return far <= r ? r - far : Real(0);  // the ellipse inside the circle, or crossing curves
}

Real circle_circle_boundary(const Circle& a, const Circle& b) {
  const Point pa = to_mp(a.center), pb = to_mp(b.center);
  const Real d = norm(pb.x - pa.x, pb.y - pa.y), ra(a.radius), rb(b.radius);
  if (d >= ra + rb) return d - ra - rb;
  return d <= abs(ra - rb) ? abs(ra - rb) - d : Real(0);
}

// A's curve in B's frame: f(t) is the signed distance of A's point at parameter t to B's curve.
template <class R>
struct CurveOnCurve {
  R px, py, c, s, a0, b0, a1, b1;

  static CurveOnCurve of(const Ellipse& a, const Ellipse& b) {
    using boost::multiprecision::cos;
    using boost::multiprecision::sin;
    using std::cos;
    using std::sin;
    const R ca = cos(R(a.angle)), sa = sin(R(a.angle)), cb = cos(R(b.angle)), sb = sin(R(b.angle));
    const R dx = R(a.center.x()) - R(b.center.x()), dy = R(a.center.y()) - R(b.center.y());
    return {
        cb * dx + sb * dy, -sb * dx + cb * dy, cb * ca + sb * sa, cb * sa - sb * ca, R(a.a), R(a.b), R(b.a), R(b.b)};
  }
  R operator()(const R& t) const {
    using boost::multiprecision::cos;
    using boost::multiprecision::sin;
    using std::cos;
    using std::sin;
    const R u = a0 * cos(t), v = b0 * sin(t);
    return signed_curve_distance(a1, b1, px + c * u - s * v, py + s * u + c * v);
  }
};

// Least value of g near the sample t (spacing h): golden section in double, then in 50 digits over a
// narrow bracket around the double minimiser.
template <class G2, class G50>
Real refine_minimum(G2 g2, G50 g50, double t, double h) {
  const auto golden = [](auto g, auto lo, auto hi, int steps) {
    using T = decltype(lo);
    const T r = (sqrt_of(T(5)) - 1) / 2;
    T x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
    T f1 = g(x1), f2 = g(x2);
    for (int k = 0; k < steps; ++k) {
      if (f1 <= f2) {
        hi = x2, x2 = x1, f2 = f1, x1 = hi - r * (hi - lo), f1 = g(x1);
      } else {
        lo = x1, x1 = x2, f1 = f2, x2 = lo + r * (hi - lo), f2 = g(x2);
      }
    }
    return f1 <= f2 ? std::pair{x1, f1} : std::pair{x2, f2};
  };
  const double t2 = golden(g2, t - h, t + h, 80).first;
  const Real w(1e-6);
  return golden(g50, Real(t2) - w, Real(t2) + w, 70).second;
}

// Indices of the `count` smallest local minima of the cyclic sequence v.
std::vector<int> lowest_local_minima(const std::vector<double>& v, int count) {
  std::vector<int> out;
  const int n = static_cast<int>(v.size());
  for (int i = 0; i < n; ++i) {
    if (v[i] <= v[(i + n - 1) % n] && v[i] <= v[(i + 1) % n]) out.push_back(i);
  }
  std::sort(out.begin(), out.end(), [&v](int i, int j) { return v[i] < v[j]; });
  if (static_cast<int>(out.size()) > count) out.resize(static_cast<std::size_t>(count));
  return out;
}

// The extremum of f (sign +1: least, -1: largest) from its samples.
Real extreme_of(const CurveOnCurve<double>& f2, const CurveOnCurve<Real>& f50, const std::vector<double>& samples,
                double sign) {
  std::vector<double> v;
  for (const double x : samples) v.push_back(sign * x);
  const double h = 2 * std::numbers::pi / static_cast<double>(samples.size());
  Real best = 0;
  bool first = true;
  for (const int i : lowest_local_minima(v, 4)) {
    const double t = h * i;
    const Real m = refine_minimum([&](double x) { return sign * f2(x); },
                                  [&](const Real& x) { return Real(sign * f50(x)); }, t, h);
    if (first || m < best) best = m, first = false;
  }
  return sign * best;
}

bool centre_in(const Ellipse& e, const Vec2& p) {
  const Point l = to_local(frame_of(e.center, e.angle), to_mp(p));
  return (l.x / Real(e.a)) * (l.x / Real(e.a)) + (l.y / Real(e.b)) * (l.y / Real(e.b)) <= 1;
}

}  // namespace

Real curve_distance(const Ellipse& e, const Point& p) {
  const Point l = to_local(frame_of(e.center, e.angle), p);
  return abs(signed_curve_distance(Real(e.a), Real(e.b), l.x, l.y));
}

namespace {

// What A's curve says about the pair: overlap found (a point of A's curve in B, or B's centre in A),
// and otherwise the least distance from A's curve to B's; plus the least distance between the
// curves as seen from A's curve (0 when they cross).
EllipsePairReference one_side(const Ellipse& a, const Ellipse& b) {
  const auto f2 = CurveOnCurve<double>::of(a, b);
  const auto f50 = CurveOnCurve<Real>::of(a, b);
  constexpr int kSamples = 720;
  std::vector<double> samples;
  bool any_out = false, any_in = false;
  const double size = std::max({a.a, a.b, b.a, b.b});
  for (int k = 0; k < kSamples; ++k) {
    const double t = 2 * std::numbers::pi * k / kSamples;
    samples.push_back(f2(t));
    // Near zero the sign of the double sample is rounding: take it from 50 digits.
    if (std::abs(samples.back()) < 1e-9 * size) samples.back() = static_cast<double>(f50(Real(t)));
    any_out = any_out || samples.back() > 0;
    any_in = any_in || samples.back() < 0;
  }
  EllipsePairReference r{true, Real(0), Real(0)};
  if (any_out && any_in) return r;  // the curves cross
  if (any_out) {
    const Real m = extreme_of(f2, f50, samples, 1.0);
    if (m <= 0) return r;
    r.boundary = m;
    r.overlap = centre_in(a, b.center);
    r.distance = r.overlap ? Real(0) : m;
    return r;
  }
  const Real m = extreme_of(f2, f50, samples, -1.0);
  r.boundary = m < 0 ? Real(-m) : Real(0);
  return r;
}

}  // namespace

// Both curves are scanned: a shallow dip of one curve into the other can fall between the samples
// of one side (needle tips) and still show from the other.
EllipsePairReference ellipse_pair(const Ellipse& a, const Ellipse& b) {
  const EllipsePairReference ab = one_side(a, b);
  const EllipsePairReference ba = one_side(b, a);
  const bool overlap = ab.overlap || ba.overlap;
  return {overlap, overlap ? Real(0) : std::min(ab.distance, ba.distance), std::min(ab.boundary, ba.boundary)};
}

Real boundary_distance(const Shape& a, const Shape& b) {
  const auto* ca = std::get_if<Circle>(&a);
  const auto* cb = std::get_if<Circle>(&b);
  if (ca && cb) return circle_circle_boundary(*ca, *cb);
  if (ca) return circle_ellipse_boundary(*ca, std::get<Ellipse>(b));
  if (cb) return circle_ellipse_boundary(*cb, std::get<Ellipse>(a));
  return ellipse_pair(std::get<Ellipse>(a), std::get<Ellipse>(b)).boundary;
}

Point to_mp(const Vec2& p) { return {Real(p.x()), Real(p.y())}; }

namespace {

// x rounded to a double towards -infinity (down) or +infinity.
double rounded(const Real& x, bool down) {
  const double d = static_cast<double>(x);
  if (down ? Real(d) > x : Real(d) < x) return std::nextafter(d, down ? -INFINITY : INFINITY);
  return d;
}

// Half widths of the shape's box along x and y.
std::pair<Real, Real> half_widths(const Shape& s) {
  if (const auto* c = std::get_if<Circle>(&s)) return {Real(c->radius), Real(c->radius)};
  const Frame f = frame_of(center_of(s), angle_of(s));
  if (const auto* e = std::get_if<Ellipse>(&s)) {
    const Real a(e->a), b(e->b);
    return {norm(a * f.c, b * f.s), norm(a * f.s, b * f.c)};
  }
  const auto& r = std::get<Rect>(s);
  const Real hx(r.half_extents.x()), hy(r.half_extents.y());
  return {abs(hx * f.c) + abs(hy * f.s), abs(hx * f.s) + abs(hy * f.c)};
}

}  // namespace

Aabb bounding_box(const Shape& s) {
  const Point c = to_mp(center_of(s));
  if (const auto* g = std::get_if<Segment>(&s)) {  // its two points' box
    const Frame f = frame_of(g->center, g->angle);
    const Real ex(g->end.x()), ey(g->end.y());
    const Real x = c.x + f.c * ex - f.s * ey, y = c.y + f.s * ex + f.c * ey;
    return {Vec2(rounded(std::min(c.x, x), true), rounded(std::min(c.y, y), true)),
            Vec2(rounded(std::max(c.x, x), false), rounded(std::max(c.y, y), false))};
  }
  const auto [wx, wy] = half_widths(s);
  return {Vec2(rounded(c.x - wx, true), rounded(c.y - wy, true)),
          Vec2(rounded(c.x + wx, false), rounded(c.y + wy, false))};
}

Real distance_to(const Shape& s, const Point& p) {
  if (const auto* c = std::get_if<Capsule>(&s)) {
    const Frame f = frame_of(c->center, c->angle);
    const Point q = to_local(f, p);
    const Real h(c->half_length);
    const Real d = point_segment(q, {-h, Real(0)}, {h, Real(0)}) - Real(c->radius);
    return d > 0 ? d : Real(0);
  }
  if (const auto* poly = std::get_if<ConvexPolygon>(&s)) {
    const Point q = to_local(frame_of(poly->center, poly->angle), p);
    const auto v = poly->vertices();
    bool inside = true;
    Real nearest = std::numeric_limits<Real>::infinity();
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Point a = to_mp(v[i]), b = to_mp(v[(i + 1) % v.size()]);
      inside = inside && (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x) >= 0;
      nearest = std::min(nearest, point_segment(q, a, b));
    }
    const Real d = nearest - Real(poly->radius());
    return inside || d <= 0 ? Real(0) : d;
  }
  if (const auto* g = std::get_if<Segment>(&s)) {
    const Point q = to_local(frame_of(g->center, g->angle), p);
    return point_segment(q, {Real(0), Real(0)}, to_mp(g->end));
  }
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
  return ellipse_pair(std::get<Ellipse>(a), std::get<Ellipse>(b)).distance;
}

bool overlap(const Shape& a, const Shape& b) {
  const auto* ra = std::get_if<Rect>(&a);
  const auto* rb = std::get_if<Rect>(&b);
  const auto* eb = std::get_if<Ellipse>(&b);
  const auto* ea = std::get_if<Ellipse>(&a);
  if (ra && eb) return rect_ellipse_overlap(*ra, *eb);
  if (rb && ea) return rect_ellipse_overlap(*rb, *ea);
  if (ra && rb) return rect_rect_overlap(*ra, *rb);
  if (ea && eb) return ellipse_pair(*ea, *eb).overlap;
  return distance(a, b) == 0;
}

namespace {

// s(theta) for the pair, in the scalar R: closed-form support functions in the shapes' frames (a
// polygon's, the largest of its vertices' projections).
template <class R>
struct Dual {
  struct Side {
    int kind;  // 0 circle, 1 ellipse, 2 rectangle, 3 capsule, 4 polygon or segment
    R c, s, p, q;
    std::vector<std::pair<R, R>> vertices;  // a polygon's
  };
  R dx, dy;
  Side a, b;

  static Side side_of(const Shape& shape, const R& c, const R& s) {
    if (const auto* x = std::get_if<Circle>(&shape)) return {0, c, s, R(x->radius), R(x->radius), {}};
    if (const auto* x = std::get_if<Ellipse>(&shape)) return {1, c, s, R(x->a), R(x->b), {}};
    if (const auto* x = std::get_if<Capsule>(&shape)) return {3, c, s, R(x->half_length), R(x->radius), {}};
    if (const auto* x = std::get_if<ConvexPolygon>(&shape)) {
      Side out{4, c, s, R(0), R(x->radius()), {}};
      for (const Vec2& v : x->vertices()) out.vertices.emplace_back(R(v.x()), R(v.y()));
      return out;
    }
    if (const auto* x = std::get_if<Segment>(&shape)) {  // its two points, as a polygon's vertices
      return {4, c, s, R(0), R(0), {{R(0), R(0)}, {R(x->end.x()), R(x->end.y())}}};
    }
    const auto& r = std::get<Rect>(shape);
    return {2, c, s, R(r.half_extents.x()), R(r.half_extents.y()), {}};
  }
  static R h(const Side& x, const R& ux, const R& uy) {
    using std::abs;
    using std::sqrt;
    if (x.kind == 0) return x.p;
    const R l0 = x.c * ux + x.s * uy, l1 = -x.s * ux + x.c * uy;
    if (x.kind == 1) return sqrt(x.p * x.p * l0 * l0 + x.q * x.q * l1 * l1);
    if (x.kind == 3) return x.p * abs(l0) + x.q;
    if (x.kind == 4) {
      R best = x.vertices[0].first * l0 + x.vertices[0].second * l1;
      for (const auto& [vx, vy] : x.vertices) best = std::max<R>(best, vx * l0 + vy * l1);
      return best + x.q;
    }
    return x.p * abs(l0) + x.q * abs(l1);
  }
  R operator()(const R& theta) const {
    using std::cos;
    using std::sin;
    const R ux = cos(theta), uy = sin(theta);
    return ux * dx + uy * dy - h(a, ux, uy) - h(b, -ux, -uy);
  }
};

// The directions where s has kinks or turns fast, in the world: the shape's axes, a polygon's face
// normals.
std::vector<double> axes_of(const Shape& s) {
  std::vector<double> out;
  const double phi = angle_of(s);
  if (const auto* p = std::get_if<ConvexPolygon>(&s)) {
    for (std::size_t i = 0; i < p->vertices().size(); ++i) {
      const Vec2 e = p->vertices()[(i + 1) % p->vertices().size()] - p->vertices()[i];
      out.push_back(phi + std::atan2(-e.x(), e.y()));
      out.push_back(out.back() + std::numbers::pi);
    }
    return out;
  }
  if (const auto* g = std::get_if<Segment>(&s)) {  // its normals and its direction, each way
    for (int k = 0; k < 4; ++k) out.push_back(phi + std::atan2(g->end.y(), g->end.x()) + k * std::numbers::pi / 2);
    return out;
  }
  for (int k = 0; k < 4; ++k) out.push_back(phi + k * std::numbers::pi / 2);
  return out;
}

// Golden-section search for the maximum of f on [lo, hi] down to width `width`.
template <class R, class F>
R golden_maximum(const F& f, R lo, R hi, const R& width) {
  const R g = (sqrt_of(R(5)) - 1) / 2;
  R x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  R f1 = f(x1), f2 = f(x2);
  while (hi - lo > width) {
    if (f1 >= f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  return f1 >= f2 ? x1 : x2;
}

}  // namespace

std::optional<Point> support_point(const Shape& s, const Point& n) {
  if (const auto* c = std::get_if<Circle>(&s)) {
    const Frame f = frame_of(c->center, 0.0);
    return to_world(f, {Real(c->radius) * n.x, Real(c->radius) * n.y});
  }
  const Frame f = frame_of(center_of(s), angle_of(s));
  const Point l = to_local(Frame{{Real(0), Real(0)}, f.c, f.s}, n);
  if (const auto* e = std::get_if<Ellipse>(&s)) {
    const Real a(e->a), b(e->b);
    const Real h = norm(a * l.x, b * l.y);
    return to_world(f, {a * a * l.x / h, b * b * l.y / h});
  }
  const Dual<Real>::Side side = Dual<Real>::side_of(s, Real(1), Real(0));
  std::vector<Point> vertices;
  if (side.kind == 2) {
    for (const Real x : {-side.p, side.p})
      for (const Real y : {-side.q, side.q}) vertices.push_back({x, y});
  } else if (side.kind == 3) {
    vertices = {{-side.p, Real(0)}, {side.p, Real(0)}};
  } else {
    for (const auto& [x, y] : side.vertices) vertices.push_back({x, y});
  }
  const Real radius = side.kind == 3 || side.kind == 4 ? side.q : Real(0);
  const auto along = [&](const Point& v) { return v.x * l.x + v.y * l.y; };
  const auto best = std::max_element(vertices.begin(), vertices.end(),
                                     [&](const Point& u, const Point& v) { return along(u) < along(v); });
  const Real tie = Real(1e-9) * Real(reach_of(s));
  for (auto v = vertices.begin(); v != vertices.end(); ++v) {
    if (v != best && along(*best) - along(*v) <= tie) return std::nullopt;
  }
  return to_world(f, {best->x + radius * l.x, best->y + radius * l.y});
}

SignedDistance signed_distance(const Shape& a, const Shape& b) {
  const double angle_a = angle_of(a), angle_b = angle_of(b);
  const Point ca = to_mp(center_of(a)), cb = to_mp(center_of(b));
  const Frame fa = frame_of(center_of(a), angle_a), fb = frame_of(center_of(b), angle_b);
  const Dual<Real> exact{cb.x - ca.x, cb.y - ca.y, Dual<Real>::side_of(a, fa.c, fa.s),
                         Dual<Real>::side_of(b, fb.c, fb.s)};
  const Dual<double> rough{static_cast<double>(exact.dx), static_cast<double>(exact.dy),
                           Dual<double>::side_of(a, std::cos(angle_a), std::sin(angle_a)),
                           Dual<double>::side_of(b, std::cos(angle_b), std::sin(angle_b))};
  const double two_pi = 2 * std::numbers::pi;
  std::vector<double> angles;
  for (int i = 0; i < 4096; ++i) angles.push_back(two_pi * i / 4096);
  std::vector<double> axes = axes_of(a);
  for (const double t : axes_of(b)) axes.push_back(t);  // each direction with its opposite
  for (const double axis : axes) {
    angles.push_back(axis);
    for (double step = 0.1; step > 1e-16; step /= 10) {
      angles.push_back(axis + step);
      angles.push_back(axis - step);
    }
  }
  for (double& t : angles) t -= two_pi * std::floor(t / two_pi);
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end()), angles.end());  // a repeat would close a bracket
  const std::size_t n = angles.size();
  std::vector<double> values(n);
  for (std::size_t i = 0; i < n; ++i) values[i] = rough(angles[i]);
  // Local maxima of the cyclic scan, highest first.
  std::vector<std::size_t> peaks;
  for (std::size_t i = 0; i < n; ++i) {
    if (values[i] >= values[(i + n - 1) % n] && values[i] >= values[(i + 1) % n]) peaks.push_back(i);
  }
  std::sort(peaks.begin(), peaks.end(), [&values](std::size_t i, std::size_t j) { return values[i] > values[j]; });
  // The six highest, each more than 1e-6 rad from those kept: a flat top or a kink shows as a
  // cluster of ties.
  std::vector<std::size_t> kept;
  for (const std::size_t i : peaks) {
    const auto near = [&](std::size_t j) {
      const double turn = std::abs(angles[i] - angles[j]);
      return std::min(turn, two_pi - turn) <= 1e-6;
    };
    if (kept.size() < 6 && std::none_of(kept.begin(), kept.end(), near)) kept.push_back(i);
  }
  peaks = kept;
  // The scan's angles unrolled: index j < 0 or >= n is a turn before or after.
  const auto angle = [&](long j) {
    const long m = static_cast<long>(n);
    const long turns = j >= 0 ? j / m : -((-j + m - 1) / m);
    return angles[static_cast<std::size_t>(j - turns * m)] + two_pi * static_cast<double>(turns);
  };
  std::vector<std::pair<Real, Real>> found;  // value, angle
  for (const std::size_t peak : peaks) {
    // Climbed in 50 digits over the scan's angles first: at a flat maximum the rounding of the
    // double values can put the highest sample a few angles away from the maximiser, and a
    // bracket of its two neighbours would miss it.
    long i = static_cast<long>(peak);
    Real here = exact(Real(angle(i)));
    for (int step = 0; step < 64; ++step) {
      const Real left = exact(Real(angle(i - 1))), right = exact(Real(angle(i + 1)));
      if (left > here) {
        --i, here = left;
      } else if (right > here) {
        ++i, here = right;
      } else {
        break;
      }
    }
    // All in 50 digits: a search in double would be steered by the same rounding.
    const Real t50 = golden_maximum<Real>(exact, Real(angle(i - 1)), Real(angle(i + 1)), Real(1e-22));
    found.emplace_back(exact(t50), t50);
  }
  std::sort(found.begin(), found.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  const Real& t = found[0].second;
  const Real h(1e-12);
  SignedDistance out{found[0].first,
                     {boost::multiprecision::cos(t), boost::multiprecision::sin(t)},
                     -std::numeric_limits<Real>::infinity(),
                     (2 * exact(t) - exact(t + h) - exact(t - h)) / (h * h)};
  for (std::size_t i = 1; i < found.size(); ++i) {
    const Real turn = abs(found[i].second - found[0].second);
    const Real apart = std::min(turn, Real(two_pi) - turn);
    if (apart > 1e-6 && found[i].first > out.runner_up) out.runner_up = found[i].first;
  }
  return out;
}

}  // namespace collide2d::reference
