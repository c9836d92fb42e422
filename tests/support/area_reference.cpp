#include "area_reference.h"

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <array>
#include <functional>
#include <variant>
#include <vector>

namespace collide2d::reference {
namespace {

using boost::multiprecision::abs;
using boost::multiprecision::atan2;
using boost::multiprecision::cos;
using boost::multiprecision::sin;
using boost::multiprecision::sqrt;

const Real kPi = boost::math::constants::pi<Real>();

Point operator+(const Point& p, const Point& q) { return {p.x + q.x, p.y + q.y}; }
Point operator-(const Point& p, const Point& q) { return {p.x - q.x, p.y - q.y}; }
Point operator*(const Real& k, const Point& p) { return {k * p.x, k * p.y}; }
Real dot(const Point& p, const Point& q) { return p.x * q.x + p.y * q.y; }
Real length(const Point& p) { return sqrt(dot(p, p)); }

struct Turn {
  Real c = 1;
  Real s = 0;
  static Turn of(double angle) { return {cos(Real(angle)), sin(Real(angle))}; }
  Point apply(const Point& p) const { return {c * p.x - s * p.y, s * p.x + c * p.y}; }
  Point undo(const Point& p) const { return {c * p.x + s * p.y, -s * p.x + c * p.y}; }
};

// An edge from p0 to p1, or the arc c + R (a cos t, b sin t) for t from theta0 over sweep.
struct Piece {
  bool curved = false;
  Point p0, p1;
  Point c;
  Turn r;
  Real a, b, theta0, sweep;

  Point at(const Real& t) const {
    if (!curved) return p0 + t * (p1 - p0);
    const Real theta = theta0 + t * sweep;
    return c + r.apply({a * cos(theta), b * sin(theta)});
  }
  Point velocity(const Real& t) const {
    if (!curved) return p1 - p0;
    const Real theta = theta0 + t * sweep;
    return sweep * r.apply({-a * sin(theta), b * cos(theta)});
  }
};

Piece edge(const Point& p0, const Point& p1) { return {false, p0, p1, {}, {}, 0, 0, 0, 0}; }
Piece arc(const Point& c, const Turn& r, const Real& a, const Real& b, const Real& theta0, const Real& sweep) {
  return {true, {}, {}, c, r, a, b, theta0, sweep};
}

// A solid: its boundary loop, counter-clockwise, and its signed distance (or a bound of it that
// keeps its sign): negative inside, zero on the boundary, positive outside. It says which side of
// the other shape's boundary a run between two cuts lies on, and the tie between the two.
struct Solid {
  std::vector<Piece> loop;
  std::function<Real(const Point&)> inside;
  Point center;
  Real size;
};

// The point's squared distance from the segment pq.
Real segment_squared(const Point& x, const Point& p, const Point& q) {
  const Point d = q - p;
  const Real t = std::clamp(Real(dot(x - p, d) / dot(d, d)), Real(0), Real(1));
  const Point off = x - (p + t * d);
  return dot(off, off);
}

// The convex polygon (a segment for two vertices) grown by r: its loop and signed distance.
Solid rounded(const std::vector<Point>& v, const Real& r) {
  const std::size_t n = v.size();
  std::vector<Point> normals;
  for (std::size_t i = 0; i < n; ++i) {
    const Point d = v[(i + 1) % n] - v[i];
    normals.push_back((1 / length(d)) * Point{d.y, -d.x});
  }
  Solid s;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t next = (i + 1) % n;
    s.loop.push_back(edge(v[i] + r * normals[i], v[next] + r * normals[i]));
    if (r == 0) continue;
    const Real from = atan2(normals[i].y, normals[i].x);
    Real sweep = atan2(normals[next].y, normals[next].x) - from;
    if (sweep <= 0) sweep += 2 * kPi;
    s.loop.push_back(arc(v[next], Turn{}, r, r, from, sweep));
  }
  // The core's largest face value inside it, its distance outside, less r.
  s.inside = [v, normals, r](const Point& x) {
    Real deepest = -1e300;
    for (std::size_t i = 0; i < v.size(); ++i) deepest = std::max(deepest, Real(dot(x - v[i], normals[i])));
    if (r == 0 || (v.size() > 2 && deepest <= 0)) return deepest - r;
    Real nearest = 1e300;
    for (std::size_t i = 0; i < v.size(); ++i)
      nearest = std::min(nearest, segment_squared(x, v[i], v[(i + 1) % v.size()]));
    return sqrt(nearest) - r;
  };
  return s;
}

Solid solid(const Circle& c) {
  const Point o = to_mp(c.center);
  const Real r(c.radius);
  return {{arc(o, Turn{}, r, r, 0, 2 * kPi)}, [o, r](const Point& x) { return length(x - o) - r; }, o, r};
}

Solid solid(const Ellipse& e) {
  const Point o = to_mp(e.center);
  const Turn t = Turn::of(e.angle);
  const Real a(e.a), b(e.b);
  const auto inside = [o, t, a, b](const Point& x) {
    const Point q = t.undo(x - o);
    return (length({q.x / a, q.y / b}) - 1) * std::min(a, b);
  };
  return {{arc(o, t, a, b, 0, 2 * kPi)}, inside, o, std::max(a, b)};
}

std::vector<Point> placed(const Vec2& center, double angle, const std::vector<Point>& local) {
  const Turn t = Turn::of(angle);
  std::vector<Point> out;
  for (const Point& p : local) out.push_back(to_mp(center) + t.apply(p));
  return out;
}

Solid solid(const Rect& r) {
  const Real hx(r.half_extents.x()), hy(r.half_extents.y());
  Solid s = rounded(placed(r.center, r.angle, {{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}}), 0);
  return {s.loop, s.inside, to_mp(r.center), std::max(hx, hy)};
}

Solid solid(const Capsule& c) {
  const Real h(c.half_length);
  Solid s = rounded(placed(c.center, c.angle, {{-h, 0}, {h, 0}}), Real(c.radius));
  return {s.loop, s.inside, to_mp(c.center), h + c.radius};
}

Solid solid(const ConvexPolygon& p) {
  std::vector<Point> local;
  for (const Vec2& v : p.vertices()) local.push_back(to_mp(v));
  Solid s = rounded(placed(p.center, p.angle, local), Real(p.radius()));
  return {s.loop, s.inside, to_mp(p.center), Real(p.outline->reach)};
}

Solid solid(const Segment&) { throw std::invalid_argument("a segment has no area"); }

Solid solid_of(const Shape& s) {
  return std::visit([](const auto& x) { return solid(x); }, s);
}

// 24-point Gauss-Legendre nodes and weights on [-1, 1], by Newton's method on P_24.
struct Quadrature {
  std::array<Real, 24> x, w;
  Quadrature() {
    constexpr int n = 24;
    for (int i = 0; i < n; ++i) {
      Real z = cos(kPi * (i + Real(0.75)) / (n + Real(0.5))), slope;
      for (int step = 0; step < 100; ++step) {
        Real p0 = 1, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const Real p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1, p1 = p2;
        }
        slope = n * (z * p1 - p0) / (z * z - 1);
        const Real delta = p1 / slope;
        z -= delta;
        if (abs(delta) < Real(1e-60)) break;
      }
      x[i] = z;
      w[i] = 2 / ((1 - z * z) * slope * slope);
    }
  }
};

// The area and first moments of a region, about an origin, summed over boundary runs.
struct Sums {
  Point origin;
  Real area = 0, mx = 0, my = 0;

  void add(const Piece& piece, const Real& t0, const Real& t1) {
    static const Quadrature q;
    const int panels = piece.curved ? 4 : 1;
    for (int k = 0; k < panels; ++k) {
      const Real lo = t0 + (t1 - t0) * k / panels, hi = t0 + (t1 - t0) * (k + 1) / panels;
      const Real mid = (lo + hi) / 2, half = (hi - lo) / 2;
      for (int j = 0; j < 24; ++j) {
        const Real t = mid + half * q.x[j], w = half * q.w[j];
        const Point p = piece.at(t) - origin, v = piece.velocity(t);
        area += w * (p.x * v.y - p.y * v.x) / 2;
        mx += w * p.x * p.x * v.y / 2;
        my -= w * p.y * p.y * v.x / 2;
      }
    }
  }
};

// The function of the plane that is zero on the curve a piece lies on: an edge's line by the cross
// product with the edge; a conic's |N (x - c)|^2 - 1, N carrying it onto the unit circle.
Real on_curve(const Piece& q, const Point& x) {
  if (!q.curved) {
    const Point e = q.p1 - q.p0, v = x - q.p0;
    return e.x * v.y - e.y * v.x;
  }
  const Point v = q.r.undo(x - q.c), w{v.x / q.a, v.y / q.b};
  return dot(w, w) - 1;
}

// Whether x, a point of q's curve, lies on the piece itself (to 1e-30, so that a crossing at a
// piece's end counts on both pieces it ends: a cut twice over is harmless).
bool within(const Piece& q, const Point& x) {
  const Real tolerance("1e-30");
  if (!q.curved) {
    const Point e = q.p1 - q.p0;
    const Real t = dot(x - q.p0, e) / dot(e, e);
    return t >= -tolerance && t <= 1 + tolerance;
  }
  if (q.sweep >= 2 * kPi) return true;
  const Point v = q.r.undo(x - q.c);
  Real turn = atan2(v.y / q.b, v.x / q.a) - q.theta0;
  while (turn < 0) turn += 2 * kPi;
  while (turn >= 2 * kPi) turn -= 2 * kPi;
  return turn <= q.sweep + tolerance || turn >= 2 * kPi - tolerance;
}

// The gradient of on_curve() at x.
Point curve_gradient(const Piece& q, const Point& x) {
  if (!q.curved) return {q.p0.y - q.p1.y, q.p1.x - q.p0.x};
  const Point v = q.r.undo(x - q.c);
  return 2 * q.r.apply({v.x / (q.a * q.a), v.y / (q.b * q.b)});
}

Real l1(const Point& p) { return abs(p.x) + abs(p.y); }

// A bound on |d^2/dt^2 on_curve(q, p.at(t))| for t in [0, 1]: 0 for an edge along a line; for an
// arc on a conic, f = |G u + g|^2 - 1 along the unit vector u, whose angle-free part (the trace of
// G^T G) drops out, so that the bound shrinks with f where the two curves nearly coincide.
Real curvature_bound(const Piece& p, const Piece& q) {
  if (!q.curved) return p.curved ? p.sweep * p.sweep * l1(q.p1 - q.p0) * std::max(p.a, p.b) : Real(0);
  const auto n = [&q](const Point& v) {
    const Point w = q.r.undo(v);
    return Point{w.x / q.a, w.y / q.b};
  };
  if (!p.curved) return 2 * dot(n(p.p1 - p.p0), n(p.p1 - p.p0));
  const Point g0 = n(p.r.apply({p.a, 0})), g1 = n(p.r.apply({0, p.b})), g = n(p.c - q.c);
  const Real varying = abs(dot(g0, g0) - dot(g1, g1)) + 2 * abs(dot(g0, g1)),
             linear = abs(dot(g0, g)) + abs(dot(g1, g));
  return p.sweep * p.sweep * (4 * varying + 2 * linear);
}

// The root in [lo, hi] of f, whose sign differs at the ends: regula falsi with the Illinois step
// (the kept end's value halved when the same end stays twice), every other step a bisection, to
// 1e-45 of the bracket.
template <class F>
Real bisect(F f, Real lo, Real hi) {
  Real f_lo = f(lo), f_hi = f(hi);
  int side = 0;
  const Real width = hi - lo;
  for (int k = 0; k < 400 && hi - lo > Real(1e-45) * width; ++k) {
    Real mid = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (k % 2 == 1 || !(mid > lo && mid < hi)) mid = (lo + hi) / 2;
    const Real f_mid = f(mid);
    if (f_mid == 0) return mid;
    if ((f_mid < 0) == (f_lo < 0)) {
      lo = mid, f_lo = f_mid;
      if (side == -1) f_hi /= 2;
      side = -1;
    } else {
      hi = mid, f_hi = f_mid;
      if (side == 1) f_lo /= 2;
      side = 1;
    }
  }
  return (lo + hi) / 2;
}

struct Value {
  Real f, slope;
};

// The roots in [lo, hi] of f, given f at the ends and a bound on |f''|: with the slope at the
// middle, f' is bounded over the interval. Where it keeps its sign, f has one root (by regula
// falsi) where its sign changes and none elsewhere; an interval whose ends' values are too far from
// 0 for f to reach it and come back is dropped; the rest are halved, down to 2^-120 of [0, 1],
// where a change of sign is a root.
template <class F>
void roots_of(F f, const Real& lo, const Real& hi, const Real& f_lo, const Real& f_hi, const Real& curvature, int depth,
              std::vector<Real>& roots) {
  const bool change = (f_lo < 0) != (f_hi < 0);
  if (depth == 120) {
    if (change) roots.push_back((lo + hi) / 2);
    return;
  }
  const Real mid = (lo + hi) / 2, width = hi - lo;
  const Value m = f(mid);
  const Real steepest = abs(m.slope) + curvature * width / 2, least = abs(m.slope) - curvature * width / 2;
  if (least > 0) {  // monotone: one root where the sign changes, none elsewhere
    if (change) roots.push_back(bisect([&f](const Real& t) { return f(t).f; }, lo, hi));
    return;
  }
  if (!change && abs(f_lo) + abs(f_hi) > steepest * width) return;
  roots_of(f, lo, mid, f_lo, m.f, curvature, depth + 1, roots);
  roots_of(f, mid, hi, m.f, f_hi, curvature, depth + 1, roots);
}

// The parameters where the piece crosses the other loop's pieces.
std::vector<Real> cuts_along(const Piece& p, const std::vector<Piece>& other) {
  std::vector<Real> cuts;
  for (const Piece& q : other) {
    const auto f = [&](const Real& t) {
      const Point x = p.at(t);
      return Value{on_curve(q, x), dot(curve_gradient(q, x), p.velocity(t))};
    };
    std::vector<Real> roots;
    roots_of(f, Real(0), Real(1), f(Real(0)).f, f(Real(1)).f, curvature_bound(p, q), 0, roots);
    for (const Real& t : roots)
      if (within(q, p.at(t))) cuts.push_back(t);
  }
  std::sort(cuts.begin(), cuts.end());
  return cuts;
}

// Adds the runs of the solid's boundary inside the other: on the other's boundary too where
// `on_counts` and the two run the same way there (the outward normal up the other's function).
void add_inside(const Solid& s, const Solid& other, bool on_counts, Sums& sums) {
  const Real tie = Real(1e-40) * (s.size + other.size), step = Real(1e-25) * (s.size + other.size);
  for (const Piece& piece : s.loop) {
    std::vector<Real> cuts = cuts_along(piece, other.loop);
    cuts.insert(cuts.begin(), Real(0));
    cuts.push_back(Real(1));
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const Real mid = (cuts[k] + cuts[k + 1]) / 2;
      const Point p = piece.at(mid);
      const Real value = other.inside(p);
      bool keep = value < -tie;
      if (abs(value) <= tie && on_counts) {
        const Point v = piece.velocity(mid), outward{v.y, -v.x};
        keep = other.inside(p + (step / length(outward)) * outward) > other.inside(p);
      }
      if (keep) sums.add(piece, cuts[k], cuts[k + 1]);
    }
  }
}

}  // namespace

AreaReference overlap_area(const Shape& a, const Shape& b) {
  const Solid sa = solid_of(a), sb = solid_of(b);
  Sums sums{sa.center};
  add_inside(sa, sb, true, sums);
  add_inside(sb, sa, false, sums);
  if (sums.area <= 0) return {0, sa.center};
  return {sums.area, {sa.center.x + sums.mx / sums.area, sa.center.y + sums.my / sums.area}};
}

Real area(const Shape& s) {
  const Solid solid = solid_of(s);
  Sums sums{solid.center};
  for (const Piece& piece : solid.loop) sums.add(piece, 0, 1);
  return sums.area;
}

}  // namespace collide2d::reference
