// The crossings are the roots of f(u) = |N u + h|^2 - 1 on the unit circle, a trigonometric
// polynomial of degree 2. Each half circle, u = +-((1 - t^2), 2t) / (1 + t^2) for t in [-1, 1), makes
// it a quartic in t on a bounded interval, whose real roots are isolated between the roots of its
// derivative (recursively down to a line), so that none is lost to a poor starting point, and found
// in their brackets by Newton's steps safeguarded by halving; Newton steps on f itself then restore
// the digits the quartic's coefficients lose.
#include "narrowphase/area/conic_roots.h"

#include "narrowphase/shared/frames/unit_vector.h"

#include <cmath>
#include <limits>

namespace collide2d::detail::areas {
namespace {

double evaluate(const double* c, int degree, double x) {
  double value = c[degree];
  for (int k = degree - 1; k >= 0; --k) value = value * x + c[k];
  return value;
}

// The polynomial's value and derivative at x.
struct ValueSlope {
  double value = 0;
  double slope = 0;
};
ValueSlope evaluate_with_slope(const double* c, int degree, double x) {
  ValueSlope v{c[degree], 0};
  for (int k = degree - 1; k >= 0; --k) {
    v.slope = v.slope * x + v.value;
    v.value = v.value * x + c[k];
  }
  return v;
}

// The root of the polynomial in [lo, hi], whose ends have signs opposite and f(lo) = f_lo: Newton's
// steps, each taken only where it stays inside the bracket the signs keep and shrinks faster than
// halving would, else a halving; until a step no longer moves x.
double root_between(const double* c, int degree, double lo, double hi, double f_lo) {
  double x = 0.5 * (lo + hi), step = hi - lo, last_step = step;
  for (int i = 0; i < 200; ++i) {
    const ValueSlope f = evaluate_with_slope(c, degree, x);
    if (f.value == 0) return x;
    if ((f.value < 0) == (f_lo < 0))
      lo = x, f_lo = f.value;
    else
      hi = x;
    const double newton = f.slope != 0 ? x - f.value / f.slope : lo;
    const double before = x;
    if (newton > lo && newton < hi && std::abs(2 * f.value) <= std::abs(last_step * f.slope)) {
      last_step = step;
      step = x - newton;
      x = newton;
    } else {
      last_step = step;
      step = 0.5 * (hi - lo);
      x = lo + step;
    }
    if (x == before || !(x >= lo && x <= hi)) return before;
  }
  return x;
}

// The real roots in [lo, hi) of c[0] + c[1] x + ... + c[degree] x^degree, ascending.
int roots_in(const double* c, int degree, double lo, double hi, double* out) {
  if (degree == 0) return 0;
  if (degree == 1) {
    const double r = -c[0] / c[1];
    if (!(c[1] != 0 && r >= lo && r < hi)) return 0;
    out[0] = r;
    return 1;
  }
  std::array<double, 4> slope{}, turns{};
  for (int k = 1; k <= degree; ++k) slope[k - 1] = k * c[k];
  const int m = roots_in(slope.data(), degree - 1, lo, hi, turns.data());
  int count = 0;
  double x0 = lo, f0 = evaluate(c, degree, lo);
  for (int k = 0; k <= m; ++k) {
    const double x1 = k < m ? turns[k] : hi, f1 = evaluate(c, degree, x1);
    if (f0 == 0 && (count == 0 || out[count - 1] != x0))
      out[count++] = x0;
    else if (f0 != 0 && f1 != 0 && (f0 < 0) != (f1 < 0))
      out[count++] = root_between(c, degree, x0, x1, f0);
    x0 = x1, f0 = f1;
  }
  return count;
}

struct Conic {
  Eigen::Matrix2d n;
  Vec2 h;
  // f and its derivative along the circle at u.
  double value(const Vec2& u) const {
    const double r = (n * u + h).norm();
    return (r - 1) * (r + 1);
  }
  double slope(const Vec2& u) const { return 2 * (n * u + h).dot(n * Vec2(-u.y(), u.x())); }
};

// Newton's steps on f along the circle, while they shrink.
Vec2 polish(const Conic& f, Vec2 u) {
  double last = std::numeric_limits<double>::infinity();
  for (int step = 0; step < 3; ++step) {
    const double slope = f.slope(u), delta = slope == 0 ? 0 : -f.value(u) / slope;
    if (!(std::abs(delta) < 0.5 * last && std::abs(delta) < 1e-3)) break;
    u = length_and_direction(u + delta * Vec2(-u.y(), u.x())).direction;
    last = std::abs(delta);
  }
  return u;
}

}  // namespace

UnitCircleRoots unit_circle_meets(const Eigen::Matrix2d& n, const Vec2& h) {
  const Eigen::Matrix2d s = n.transpose() * n;
  const Vec2 w = n.transpose() * h;
  const double k = (h.norm() - 1) * (h.norm() + 1);
  // The same curve, to the rounding of the maps that carried one into the other's frame.
  if ((s - Eigen::Matrix2d::Identity()).cwiseAbs().sum() + w.norm() + h.squaredNorm() <= 1e-13) return {};
  UnitCircleRoots roots;
  const Conic f{n, h};
  for (const double side : {1.0, -1.0}) {
    const double w1 = side * w.x(), w2 = side * w.y();
    const std::array<double, 5> c{s(0, 0) + 2 * w1 + k, 4 * s(0, 1) + 4 * w2, -2 * s(0, 0) + 4 * s(1, 1) + 2 * k,
                                  -4 * s(0, 1) + 4 * w2, s(0, 0) - 2 * w1 + k};
    int degree = 4;
    while (degree > 0 && c[degree] == 0) --degree;
    std::array<double, 4> t{};
    const int found = roots_in(c.data(), degree, -1, 1, t.data());
    for (int i = 0; i < found && roots.count < 4; ++i) {
      const double d = 1 + t[i] * t[i];
      roots.u[roots.count++] = polish(f, side * Vec2((1 - t[i]) * (1 + t[i]) / d, 2 * t[i] / d));
    }
  }
  return roots;
}

}  // namespace collide2d::detail::areas
