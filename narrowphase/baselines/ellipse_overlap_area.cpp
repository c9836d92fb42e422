#include "narrowphase/baselines/ellipse_overlap_area.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace collide2d::baselines {
namespace {

constexpr double pi = std::numbers::pi;

// x^2/a^2 + y^2/b^2 <= 1 about centre c turned by angle t.
struct Posed {
  double cx, cy, a, b, t;
  double level(double x, double y) const {
    const double c = std::cos(t), s = std::sin(t), dx = x - cx, dy = y - cy;
    const double u = (c * dx + s * dy) / a, v = (-s * dx + c * dy) / b;
    return u * u + v * v - 1;
  }
  // The parameter angle of a point on (or near) the curve.
  double angle_of(double x, double y) const {
    const double c = std::cos(t), s = std::sin(t), dx = x - cx, dy = y - cy;
    return std::atan2((-s * dx + c * dy) / b, (c * dx + s * dy) / a);
  }
};

// The real roots of a t^4 + b t^3 + c t^2 + d t + e by Ferrari's method: the depressed quartic,
// a root of its resolvent cubic (Cardano's formula), and two quadratics.
std::vector<double> quartic_roots(double a, double b, double c, double d, double e) {
  using C = std::complex<double>;
  b /= a, c /= a, d /= a, e /= a;
  const double p = c - 3 * b * b / 8, q = d - b * c / 2 + b * b * b / 8,
               r = e - b * d / 4 + b * b * c / 16 - 3 * b * b * b * b / 256;
  // The resolvent cubic m^3 + p m^2 + (p^2/4 - r) m - q^2/8 = 0, as y^3 + P y + Q with m = y - p/3.
  const double a2 = p, a1 = p * p / 4 - r, a0 = -q * q / 8;
  const double P = a1 - a2 * a2 / 3, Q = 2 * a2 * a2 * a2 / 27 - a2 * a1 / 3 + a0;
  const C disc = std::sqrt(C(Q * Q / 4 + P * P * P / 27));
  C u = std::pow(C(-Q / 2) + disc, 1.0 / 3);
  if (std::abs(u) == 0) u = std::pow(C(-Q / 2) - disc, 1.0 / 3);
  const C y = std::abs(u) == 0 ? C(0) : u - P / (3.0 * u);
  const C m = y - a2 / 3;
  const C s = std::sqrt(2.0 * m);
  std::vector<double> out;
  const auto keep_real = [&](C z) {
    if (std::abs(z.imag()) <= 1e-7 * std::max(1.0, std::abs(z.real()))) out.push_back(z.real() - b / 4);
  };
  if (std::abs(s) <= 1e-12) {  // q = 0: a quadratic in x^2
    const C root = std::sqrt(C(p * p - 4 * r));
    for (const C x2 : {(-p + root) / 2.0, (-p - root) / 2.0})
      for (const double sign : {1.0, -1.0}) keep_real(sign * std::sqrt(x2));
    return out;
  }
  // x^2 + sign s x + (p / 2 + m - sign q / (2 s)) for each sign: Ferrari's two quadratics.
  for (const double sign : {1.0, -1.0}) {
    const C half = sign * s, constant = p / 2 + m - sign * q / (2.0 * s);
    const C root = std::sqrt(half * half - 4.0 * constant);
    keep_real((-half + root) / 2.0);
    keep_real((-half - root) / 2.0);
  }
  return out;
}

double segment(double a, double b, double from, double to) {
  double d = to - from;
  while (d < 0) d += 2 * pi;
  return 0.5 * a * b * (d - std::sin(d));  // the sector less the triangle
}

}  // namespace

double ellipse_overlap_area(const Ellipse& ea, const Ellipse& eb) {
  // B in A's frame, A axis-aligned at the origin.
  const double ca = std::cos(ea.angle), sa = std::sin(ea.angle), dx = eb.center.x() - ea.center.x(),
               dy = eb.center.y() - ea.center.y();
  const Posed a{0, 0, ea.a, ea.b, 0}, b{ca * dx + sa * dy, -sa * dx + ca * dy, eb.a, eb.b, eb.angle - ea.angle};
  // B's conic A x^2 + B xy + C y^2 + D x + E y + F, and A's points (a (1 - t^2), 2 b t) / (1 + t^2).
  const double c = std::cos(b.t), s = std::sin(b.t), ia = 1 / (b.a * b.a), ib = 1 / (b.b * b.b);
  const double A = c * c * ia + s * s * ib, B = 2 * c * s * (ia - ib), C = s * s * ia + c * c * ib;
  const double D = -2 * A * b.cx - B * b.cy, E = -2 * C * b.cy - B * b.cx,
               F = A * b.cx * b.cx + B * b.cx * b.cy + C * b.cy * b.cy - 1;
  const double p = a.a, q = a.b;
  // Substituting x = p (1 - t^2) / (1 + t^2), y = 2 q t / (1 + t^2) and multiplying by (1 + t^2)^2.
  const double k4 = A * p * p - D * p + F, k3 = -2 * B * p * q + 2 * E * q, k2 = -2 * A * p * p + 4 * C * q * q + 2 * F,
               k1 = 2 * B * p * q + 2 * E * q, k0 = A * p * p + D * p + F;
  std::vector<double> angles;
  if (std::abs(k4) > 1e-300)
    for (const double t : quartic_roots(k4, k3, k2, k1, k0)) angles.push_back(2 * std::atan(t));
  std::sort(angles.begin(), angles.end());
  angles.erase(std::unique(angles.begin(), angles.end(), [](double x, double y) { return std::abs(x - y) < 1e-12; }),
               angles.end());
  const double area_a = pi * ea.a * ea.b, area_b = pi * eb.a * eb.b;
  if (angles.size() < 2) {
    if (b.level(a.a, 0) <= 0 && b.level(-a.a, 0) <= 0) return area_a;  // A inside B
    if (a.level(b.cx, b.cy) <= 0) return std::min(area_a, area_b);     // B inside A
    return 0;
  }
  // The polygon of the crossings, and a segment between each two.
  const std::size_t n = angles.size();
  double twice = 0, segments = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t0 = angles[i], t1 = i + 1 < n ? angles[i + 1] : angles[0] + 2 * pi;
    const double x0 = p * std::cos(t0), y0 = q * std::sin(t0), x1 = p * std::cos(t1), y1 = q * std::sin(t1);
    twice += x0 * y1 - x1 * y0;
    const double mid = 0.5 * (t0 + t1);
    if (b.level(p * std::cos(mid), q * std::sin(mid)) <= 0) {
      segments += segment(p, q, t0, t1);  // A bounds the overlap here
    } else {
      segments += segment(b.a, b.b, b.angle_of(x0, y0), b.angle_of(x1, y1));
    }
  }
  return std::max(0.5 * twice + segments, 0.0);
}

}  // namespace collide2d::baselines
