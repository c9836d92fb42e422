// M. Pewsey, "Minimum Distance Between Ellipses" (2021), reproduced as published: plain gradient
// descent on D^2(t1, t2) = |x1(t1) - x2(t2)|^2, learning rate 0.04 exp(-0.002 k), stop when
// max |dD^2/dt| < 1e-8 or after 10,000 steps. Not improved on purpose: it is a baseline the robust
// solver is measured against. Note that
// both the step and the stopping rule are absolute, so the method depends on the units (large
// ellipses overshoot, tiny ones stop at once).
//
// Start rule: t1 and t2 point along the line of centres, unless a centre lies in the other ellipse;
// then the best of the 24 x 24 pairs of evenly spaced parameter values (first minimum in the
// article's order, t1 outer). The article's `contains` does not subtract the ellipse centre, which
// makes it test the world origin; here it tests the centre as the text says. On the article's 19
// sample pairs (first ellipse at the origin) the two differ only in which start they take.
#include "narrowphase/baselines/ellipse_seed_solvers.h"

#include "shapes/internal.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace collide2d::detail {
namespace {

constexpr double kTolerance = 1e-8;
constexpr int kMaxIterations = 10000;
constexpr double kLearningRate = 0.04;
constexpr double kDecay = 0x1.fefa1e333cd77p-1;  // exp(-0.002): the rate shrinks by it at each step

// A point of a curve relative to its centre, and the derivative there.
struct CurvePoint {
  Vec2 point;
  Vec2 tangent;
};

// One curve in the article's terms, parametrised by t.
struct Curve {
  Rotation<double> rot;
  double a;
  double b;
  CurvePoint at(double t) const {
    const CosSin u = cos_sin(t);
    return {rot.apply(Vec2(a * u.c, b * u.s)), rot.apply(Vec2(-a * u.s, b * u.c))};
  }
};

Curve curve_of(const Ellipse& e) { return {Rotation<double>::of(e.angle), e.a, e.b}; }

// The article's 24 x 24 vertex start.
Vec2 vertex_start(const Curve& c1, const Curve& c2, const Vec2& dx0) {
  constexpr int kVertices = 24;
  Vec2 best(0.0, 0.0);
  double best_distance = INFINITY;
  for (int i = 0; i < kVertices; ++i) {
    const double t1 = 2 * std::numbers::pi * i / kVertices;
    for (int j = 0; j < kVertices; ++j) {
      const double t2 = 2 * std::numbers::pi * j / kVertices;
      const double d = (c1.at(t1).point - c2.at(t2).point + dx0).norm();
      if (d < best_distance) best_distance = d, best = Vec2(t1, t2);
    }
  }
  return best;
}

}  // namespace

SolverReport gradient_descent_curves(const Ellipse& self, const Ellipse& other) {
  const Curve c1 = curve_of(self);
  const Curve c2 = curve_of(other);
  const Vec2 dx0 = self.center - other.center;
  Vec2 t(arc_tangent(-dx0.y(), -dx0.x()) - self.angle, arc_tangent(dx0.y(), dx0.x()) - other.angle);
  if (contains(self, other.center) || contains(other, self.center)) t = vertex_start(c1, c2, dx0);

  int iterations = 0;
  double error = kTolerance, rate = kLearningRate;
  CurvePoint x1 = c1.at(t[0]);
  CurvePoint x2 = c2.at(t[1]);
  while (error >= kTolerance && iterations < kMaxIterations) {
    x1 = c1.at(t[0]);
    x2 = c2.at(t[1]);
    const Vec2 delta = x1.point - x2.point + dx0;
    const Vec2 dp(2 * x1.tangent.dot(delta), -2 * x2.tangent.dot(delta));
    t -= rate * dp;
    rate *= kDecay;
    error = dp.cwiseAbs().maxCoeff();
    ++iterations;
  }
  const double y = (x1.point - x2.point + dx0).norm();
  const bool success = error < kTolerance && iterations < kMaxIterations;
  const Vec2 pa = self.center + x1.point;
  const Vec2 pb = other.center + x2.point;
  const DistanceResult r = y > 0 ? DistanceResult::apart(y, pa, pb) : DistanceResult::touching(pa);
  return {r, iterations, success};
}

}  // namespace collide2d::detail
