// The crossings are the roots of f(u) = |N u + h|^2 - 1 on the unit circle, a trigonometric
// polynomial of degree 2. Each half circle, u = +-((1 - t^2), 2t) / (1 + t^2) for t in [-1, 1), makes
// it a quartic in t on a bounded interval, whose real roots are isolated by halving the interval
// until the signs of the quartic's Bernstein coefficients there say it holds none or one, or else
// between the roots of its derivative (recursively down to a quadratic, solved by its formula), so
// that none is lost to a poor starting point; each is found in its bracket by Newton's steps
// safeguarded by halving, and Newton steps on f itself then restore the digits the quartic's
// coefficients lose.
#include "narrowphase/area/conic_roots.h"

#include "narrowphase/shared/frames/unit_vector.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace collide2d::detail::areas {
namespace {

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

// The root of the polynomial in [lo, hi], whose ends have signs opposite, f(lo) = f_lo and
// f(hi) = f_hi: from the secant's point, Newton's steps, each taken only where it stays inside the
// bracket the signs keep and shrinks faster than halving would, else a halving; until a step moves x
// by no more than its last place or `width`, or the bracket is narrower than `width`.
double root_between(const double* c, int degree, double lo, double hi, double f_lo, double f_hi, double width) {
  double x = lo + (hi - lo) * (f_lo / (f_lo - f_hi)), step = hi - lo, last_step = step;
  if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
  for (int i = 0; i < 200 && hi - lo > width; ++i) {
    const ValueSlope f = evaluate_with_slope(c, degree, x);
    if (f.value == 0) return x;
    if ((f.value < 0) == (f_lo < 0))
      lo = x, f_lo = f.value;
    else
      hi = x;
    const double newton = f.slope != 0 ? x - f.value / f.slope : lo;
    // A step within the last place of x is the rounding of f: x is the root to the digits it has.
    // A step within the width asked for leaves the root far closer than that, Newton's steps
    // converging quadratically.
    if (std::abs(newton - x) <= std::max(width, 0x1p-52 * std::abs(x))) return newton;
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

// The real roots in [lo, hi) of c[0] + c[1] x + c[2] x^2 (c[2] != 0), ascending, by the formula
// that takes the larger root in magnitude first and the other from the product of the two.
int quadratic_roots_in(const double* c, double lo, double hi, double* out) {
  const double discriminant = c[1] * c[1] - 4 * c[0] * c[2];
  if (discriminant < 0) return 0;
  const double q = -0.5 * (c[1] + std::copysign(std::sqrt(discriminant), c[1]));
  double r0 = q / c[2], r1 = q != 0 ? c[0] / q : r0;
  if (r1 < r0) std::swap(r0, r1);
  int count = 0;
  for (const double r : {r0, r1}) {
    if (r >= lo && r < hi && (count == 0 || out[count - 1] != r)) out[count++] = r;
  }
  return count;
}

// A turning point isolates the roots on either side of it as well within this width as exactly:
// where f' = 0 the value moves by f'' width^2 / 2, below the rounding of the coefficients.
constexpr double kTurningWidth = 0x1p-30;

// The real roots in [lo, hi) of c[0] + c[1] x + ... + c[degree] x^degree, ascending, between the
// roots of its derivative: to full precision, or within `width` where they only isolate the roots
// of the polynomial above.
int roots_by_turns(const double* c, int degree, double lo, double hi, double* out, double width = 0) {
  if (degree == 0) return 0;
  if (degree == 1) {
    const double r = -c[0] / c[1];
    if (!(c[1] != 0 && r >= lo && r < hi)) return 0;
    out[0] = r;
    return 1;
  }
  if (degree == 2) return quadratic_roots_in(c, lo, hi, out);
  std::array<double, 4> slope{}, turns{};
  for (int k = 1; k <= degree; ++k) slope[k - 1] = k * c[k];
  const int m = roots_by_turns(slope.data(), degree - 1, lo, hi, turns.data(), kTurningWidth);
  int count = 0;
  double x0 = lo, f0 = evaluate_with_slope(c, degree, lo).value;
  for (int k = 0; k <= m; ++k) {
    const double x1 = k < m ? turns[k] : hi, f1 = evaluate_with_slope(c, degree, x1).value;
    if (f0 == 0 && (count == 0 || out[count - 1] != x0))
      out[count++] = x0;
    else if (f0 != 0 && f1 != 0 && (f0 < 0) != (f1 < 0))
      out[count++] = root_between(c, degree, x0, x1, f0, f1, width);
    x0 = x1, f0 = f1;
  }
  return count;
}

// The polynomial in the Bernstein basis of one interval: p(x) = sum of b_i C(n, i) s^i (1 - s)^(n - i)
// with s the position in the interval, b_0 = p(lo) and b_n = p(hi).
struct Bernstein {
  std::array<double, 5> b{};
  int degree = 0;
};

Bernstein bernstein_of(const double* c, int degree, double lo, double hi) {
  // p(lo + (hi - lo) s) in powers of s, by Ruffini's shifts then the scaling.
  std::array<double, 5> a{};
  for (int j = 0; j <= degree; ++j) a[j] = c[j];
  for (int i = 0; i < degree; ++i) {
    for (int j = degree - 1; j >= i; --j) a[j] += lo * a[j + 1];
  }
  double scale = 1;
  for (int j = 0; j <= degree; ++j, scale *= hi - lo) a[j] *= scale;
  static constexpr double kBinomial[5][5] = {
      {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};
  Bernstein out{{}, degree};
  for (int i = 0; i <= degree; ++i) {
    for (int j = 0; j <= i; ++j) out.b[i] += kBinomial[i][j] / kBinomial[degree][j] * a[j];
  }
  return out;
}

// The two halves' coefficients, by de Casteljau's averages.
std::pair<Bernstein, Bernstein> halves(const Bernstein& p) {
  Bernstein left{{}, p.degree}, right{{}, p.degree};
  std::array<double, 5> row = p.b;
  for (int level = 0; level <= p.degree; ++level) {
    left.b[level] = row[0];
    right.b[p.degree - level] = row[p.degree - level];
    for (int i = 0; i < p.degree - level; ++i) row[i] = 0.5 * (row[i] + row[i + 1]);
  }
  return {left, right};
}

// How many times the coefficients change sign: at least the roots in the interval, and of their
// parity (Descartes' rule of signs in the Bernstein basis), so that 0 means none and 1 exactly one.
// -1 where a coefficient is within `trusted` of zero, too near for its sign to be certain.
int sign_changes(const Bernstein& p, double trusted) {
  int changes = 0;
  for (int i = 0; i <= p.degree; ++i) {
    if (!(std::abs(p.b[i]) > trusted)) return -1;
    changes += i > 0 && (p.b[i] < 0) != (p.b[i - 1] < 0);
  }
  return changes;
}

// Deeper than this, roots closer than 2^-10 of the interval are left to the turning points.
constexpr int kMaxHalvings = 10;

// The roots in [lo, hi) of the polynomial c, whose coefficients there are p: intervals halved until
// each holds none or one root by the signs of its coefficients (Collins and Akritas, "Polynomial real
// root isolation using Descartes' rule of signs", 1976, in the Bernstein basis), each root found in
// its interval; an interval whose signs stay unsettled goes to the turning points.
int isolated_roots(const double* c, const Bernstein& p, double lo, double hi, double trusted, int depth, double* out) {
  switch (depth < kMaxHalvings ? sign_changes(p, trusted) : -1) {
    case -1:
      return roots_by_turns(c, p.degree, lo, hi, out);
    case 0:
      return 0;
    case 1:
      out[0] = root_between(c, p.degree, lo, hi, p.b[0], p.b[p.degree], 0);
      return 1;
    default: {
      const double mid = 0.5 * (lo + hi);
      const auto [left, right] = halves(p);
      const int count = isolated_roots(c, left, lo, mid, trusted, depth + 1, out);
      return count + isolated_roots(c, right, mid, hi, trusted, depth + 1, out + count);
    }
  }
}

// The real roots in [lo, hi) of c[0] + c[1] x + ... + c[degree] x^degree, ascending.
int roots_in(const double* c, int degree, double lo, double hi, double* out) {
  if (degree <= 2) return roots_by_turns(c, degree, lo, hi, out);
  const Bernstein p = bernstein_of(c, degree, lo, hi);
  double size = 0;
  for (int i = 0; i <= degree; ++i) size = std::max(size, std::abs(p.b[i]));
  return isolated_roots(c, p, lo, hi, 0x1p-40 * size, 0, out);
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
