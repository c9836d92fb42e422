// D. Eberly, "Distance Between Ellipses in 2D" (Geometric Tools): a baseline to measure.
//
// With X = C0 + A U, Y = C1 + B V (A = R0 diag(a0, b0), |U| = |V| = 1) and Delta = C0 - C1, the
// Lagrange conditions make A^-T U, B^-T V and A U - B V + Delta parallel. With W = perp(A^-T U),
// W.(A U - B V + Delta) = 0 and W.(B^-T V) = 0 are linear in V, solved by Cramer's rule, and |V| = 1
// gives P(u0, u1) = (m11^2 + m10^2) n^2 - (m00 m11 - m01 m10)^2 = 0, of degree 6; u1^2 = 1 - u0^2
// splits it as alpha(u0) + u1 beta(u0), and S = alpha^2 + (u0^2 - 1) beta^2 has degree 12.
// The coefficients m_ij and n are formed here from the matrices rather than copied from the text,
// whose extraction garbles them. When either ellipse is a circle, the problem is the distance from
// the circle's centre to the other ellipse: the quartic
// (a x0)^2 (t + b^2)^2 + (b y0)^2 (t + a^2)^2 - (t + a^2)^2 (t + b^2)^2 = 0.
//
// Roots come from the companion-matrix eigenvalues (Eigen's unsupported Polynomials module). A root
// counts as real when its imaginary part is below 1e-3 (near-double roots split into complex pairs of
// size sqrt(u)); each candidate is put back on its curve (V normalised, the quartic's point scaled
// onto the ellipse), so every candidate is a true pair of curve points and the minimum never
// undershoots. Everything else is as published: it finds only stationary points of the distance
// between the curves, so it misses crossing curves, and it inherits the conditioning of the
// polynomial near tangency and for eccentric ellipses.
#include "narrowphase/baselines/ellipse_seed_solvers.h"

#include "shapes/internal.h"

#include <Eigen/Dense>
#include <unsupported/Eigen/Polynomials>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace collide2d::detail {
namespace {

constexpr double kImaginaryTolerance = 1e-3;

// Univariate polynomial, coefficients in ascending order.
using Poly = std::vector<double>;

Poly multiply(const Poly& p, const Poly& q) {
  Poly r(p.size() + q.size() - 1, 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = 0; j < q.size(); ++j) r[i + j] += p[i] * q[j];
  }
  return r;
}

Poly add(Poly p, const Poly& q, double scale = 1.0) {
  if (p.size() < q.size()) p.resize(q.size(), 0.0);
  for (std::size_t i = 0; i < q.size(); ++i) p[i] += scale * q[i];
  return p;
}

// Bivariate polynomial in (u0, u1) of total degree at most 6: c[i][j] multiplies u0^i u1^j.
struct Poly2 {
  std::array<std::array<double, 7>, 7> c{};
};

Poly2 times(const Poly2& p, const Poly2& q) {
  Poly2 r;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; i + j < 7; ++j)
      for (int k = 0; i + k < 7; ++k)
        for (int l = 0; j + l < 7 && i + k + j + l < 7; ++l) r.c[i + k][j + l] += p.c[i][j] * q.c[k][l];
  return r;
}

// p + scale q
Poly2 sum(Poly2 p, const Poly2& q, double scale) {
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) p.c[i][j] += scale * q.c[i][j];
  return p;
}

Poly2 linear(double c0, double c1) {
  Poly2 p;
  p.c[1][0] = c0;
  p.c[0][1] = c1;
  return p;
}

// (1 - u0^2)^k
Poly one_minus_square(int k) {
  Poly r{1.0};
  for (int i = 0; i < k; ++i) r = multiply(r, {1.0, 0.0, -1.0});
  return r;
}

// Real parts of the (nearly) real roots; an empty list for a constant.
std::vector<double> real_roots(Poly p, double imaginary_tolerance) {
  double largest = 0.0;
  for (const double c : p) largest = std::max(largest, std::abs(c));
  while (p.size() > 1 && std::abs(p.back()) <= 1e-14 * largest) p.pop_back();
  std::vector<double> out;
  if (p.size() < 2) return out;
  Eigen::PolynomialSolver<double, Eigen::Dynamic> solver;
  solver.compute(Eigen::Map<const Eigen::VectorXd>(p.data(), static_cast<Eigen::Index>(p.size())));
  for (const auto& z : solver.roots()) {
    if (std::abs(z.imag()) <= imaginary_tolerance * std::max(1.0, std::abs(z.real()))) out.push_back(z.real());
  }
  return out;
}

Eigen::Matrix2d axes(const Ellipse& e, double a, double b) {
  const auto r = Rotation<double>::of(e.angle);
  Eigen::Matrix2d m;
  m << r.c * a, -r.s * b, r.s * a, r.c * b;
  return m;
}

struct Best {
  double distance = INFINITY;
  Vec2 x = Vec2::Zero();
  Vec2 y = Vec2::Zero();
  int candidates = 0;
  void offer(const Vec2& px, const Vec2& py, double d) {
    ++candidates;
    if (d < distance) distance = d, x = px, y = py;
  }
};

SolverReport report(const Best& best) {
  const bool found = std::isfinite(best.distance);
  if (found && best.distance == 0) return {DistanceResult::touching(best.x), best.candidates, true};
  return {DistanceResult::apart(best.distance, best.x, best.y), best.candidates, found};
}

// The degree-12 path for two ellipses that are not circles.
SolverReport general(const Ellipse& e0, const Ellipse& e1) {
  const Eigen::Matrix2d A = axes(e0, e0.a, e0.b);
  const Eigen::Matrix2d B = axes(e1, e1.a, e1.b);
  const Vec2 delta = e0.center - e1.center;
  Eigen::Matrix2d J;
  J << 0, 1, -1, 0;
  const Eigen::Matrix2d L = J * axes(e0, 1.0 / e0.a, 1.0 / e0.b);  // W = L U
  const Eigen::Matrix2d LB = L.transpose() * B;
  const Eigen::Matrix2d LBi = L.transpose() * axes(e1, 1.0 / e1.a, 1.0 / e1.b);
  const Eigen::Matrix2d LA = L.transpose() * A;
  const Vec2 Ld = L.transpose() * delta;
  const Poly2 m00 = linear(LB(0, 0), LB(1, 0)), m01 = linear(LB(0, 1), LB(1, 1));
  const Poly2 m10 = linear(LBi(0, 0), LBi(1, 0)), m11 = linear(LBi(0, 1), LBi(1, 1));
  Poly2 n = linear(Ld.x(), Ld.y());
  n.c[2][0] = LA(0, 0);
  n.c[1][1] = LA(0, 1) + LA(1, 0);
  n.c[0][2] = LA(1, 1);
  const Poly2 det = sum(times(m00, m11), times(m01, m10), -1.0);
  const Poly2 P = sum(times(sum(times(m11, m11), times(m10, m10), 1.0), times(n, n)), times(det, det), -1.0);

  Poly alpha{0.0}, beta{0.0};
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; i + j < 7; ++j) {
      Poly term(static_cast<std::size_t>(i) + 1, 0.0);
      term[static_cast<std::size_t>(i)] = P.c[i][j];
      if (j % 2 == 0)
        alpha = add(alpha, multiply(term, one_minus_square(j / 2)));
      else
        beta = add(beta, multiply(term, one_minus_square((j - 1) / 2)));
    }
  }
  const Poly S = add(multiply(alpha, alpha), multiply({-1.0, 0.0, 1.0}, multiply(beta, beta)));

  Best best;
  const auto eval = [](const Poly2& p, double u0, double u1) {
    std::array<double, 7> power0{1.0}, power1{1.0};  // by products, the same bits on every platform
    for (int i = 1; i < 7; ++i) power0[i] = power0[i - 1] * u0, power1[i] = power1[i - 1] * u1;
    double s = 0.0;
    for (int i = 0; i < 7; ++i)
      for (int j = 0; i + j < 7; ++j) s += p.c[i][j] * power0[i] * power1[j];
    return s;
  };
  for (const double root : real_roots(S, kImaginaryTolerance)) {
    const double u0 = std::clamp(root, -1.0, 1.0);
    for (const double sign : {1.0, -1.0}) {
      const Vec2 U(u0, sign * std::sqrt(1.0 - u0 * u0));
      const double nv = eval(n, U.x(), U.y());
      Vec2 V(eval(m11, U.x(), U.y()) * nv, -eval(m10, U.x(), U.y()) * nv);
      if (!(V.norm() > 0)) continue;
      V /= V.norm();  // Cramer's 1/det only scales V; its sign is covered by trying -V too
      for (const Vec2& v : {V, Vec2(-V)}) {
        const Vec2 x = e0.center + A * U;
        const Vec2 y = e1.center + B * v;
        best.offer(x, y, (x - y).norm());
      }
    }
  }
  return report(best);
}

// The quartic path: circle c against ellipse e; `circle_first` says which was A.
SolverReport circle_path(const Ellipse& c, const Ellipse& e, bool circle_first) {
  const double r = c.a;
  const auto rot = Rotation<double>::of(e.angle);
  const Vec2 p = rot.apply_inverse(Vec2(c.center - e.center));
  const double a2 = e.a * e.a, b2 = e.b * e.b;
  const Poly ta{a2, 1.0}, tb{b2, 1.0};
  const Poly ta2 = multiply(ta, ta), tb2 = multiply(tb, tb);
  const double ax = e.a * p.x(), by = e.b * p.y();
  const Poly F = add(add(multiply(tb2, {ax * ax}), multiply(ta2, {by * by})), multiply(ta2, tb2), -1.0);
  Best best;
  for (const double t : real_roots(F, kImaginaryTolerance * (a2 + b2))) {
    Vec2 q(a2 * p.x() / (t + a2), b2 * p.y() / (t + b2));
    const double level = hypotenuse(q.x() / e.a, q.y() / e.b);
    if (!(level > 0) || !std::isfinite(level)) continue;
    q /= level;
    const Vec2 on_e = e.center + rot.apply(q);
    const Vec2 to_e = on_e - c.center;
    const double d = to_e.norm();
    if (!(d > 0)) continue;
    const Vec2 on_c = c.center + (r / d) * to_e;
    if (circle_first)
      best.offer(on_c, on_e, std::abs(d - r));
    else
      best.offer(on_e, on_c, std::abs(d - r));
  }
  return report(best);
}

}  // namespace

SolverReport polynomial_curves(const Ellipse& a, const Ellipse& b) {
  if (a.a == a.b) return circle_path(a, b, true);
  if (b.a == b.b) return circle_path(b, a, false);
  return general(a, b);
}

}  // namespace collide2d::detail
