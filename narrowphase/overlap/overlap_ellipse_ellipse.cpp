#include <collide2d/kernels.h>

#include "narrowphase/overlap/overlap_ellipse_ellipse.h"

#include "narrowphase/shared/ellipse/ellipse_contact.h"
#include "narrowphase/shared/lanes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace collide2d {
namespace detail {
#include "narrowphase/overlap/overlap_ellipse_ellipse-inl.h"

namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

// The centres farther apart than the two longer semi-axes, beyond the rounding: no sine or cosine
// needed.
bool far_apart(const Ellipse& a, const Ellipse& b, double length) {
  const double reach = std::max(a.a, a.b) + std::max(b.a, b.b);
  return length - reach > 8 * kU * (length + reach);
}

// Whether the point p (relative to the centre of e) is inside e by more than the rounding of the
// quadratic: its axis components carry 3 u |p| of error each, scaled by 1/a and 1/b.
bool clearly_inside(const EllipseSupport<double>& e, const Vec2& p) {
  const Vec2 l = e.rot.apply_inverse(p);
  const double u = l.x() / e.a;
  const double v = l.y() / e.b;
  return u * u + v * v < 1.0 - 16 * kU * (1.0 + p.norm() * (1.0 / e.a + 1.0 / e.b));
}

// The bounding boxes in the pair's frame apart along an axis by more than their rounding: then that
// axis separates the ellipses exactly, a direction the iteration need not find. It matters for
// needles of aspect beyond about 1e16, whose separating directions are kinks finer than a double
// angle. The rounding is that of the three terms of the gap, not of the pair's scale: a needle of
// length 1e20 has a half-height known to a few ulps of its b in its own frame, and a gap of 0.5
// beside it is certain (at a scale where 0.5 is below 8 u; LongNeedleKeepsALocalGap). delta's
// component carries a few u of its composition's magnitude (d the centres' difference in world
// axes). The shorter ellipse's half-width sqrt((a c)^2 + (b s)^2) moves by at most a dc + b ds
// where its cosine and sine carry dc and ds, a few u of their magnitudes (EllipsePair::turn). An
// allowance of (a + b) u, whatever the turn, would be far too wide for two needles turned by a tiny
// angle from each other: for needles 2.4e24 and 5.1e25 long turned by 1e-297 and 0.56 apart across
// their axes it is 1e9 times the gap, and the pair would go to GJK, whose double-double pass cannot
// decide it (NeedlesTurnedByTinyAnglesApartAcrossAxes).
bool boxes_apart(const EllipsePair<double>& p, const Vec2& d, Vec2& axis) {
  const bool a_frame = std::max(p.A.a, p.A.b) >= std::max(p.B.a, p.B.b);
  for (int k = 0; k < 2; ++k) {
    const auto half = [k](const EllipseSupport<double>& e) {
      const double c = k == 0 ? e.rot.c : e.rot.s, s = k == 0 ? e.rot.s : e.rot.c;
      return std::sqrt(e.a * e.a * c * c + e.b * e.b * s * s);
    };
    const auto turned = [&](const EllipseSupport<double>& e, bool frame) {
      return frame ? 0.0 : e.a * p.turn[k] + e.b * p.turn[1 - k];
    };
    const double along = k == 0 ? std::abs(p.frame.c * d.x()) + std::abs(p.frame.s * d.y())
                                : std::abs(p.frame.c * d.y()) + std::abs(p.frame.s * d.x());
    const double half_a = half(p.A), half_b = half(p.B);
    const double gap = std::abs(p.delta[k]) - half_a - half_b;
    if (gap > 8 * kU * (along + half_a + half_b + turned(p.A, a_frame) + turned(p.B, !a_frame))) {
      axis = Vec2::Zero();
      axis[k] = p.delta[k] > 0 ? 1.0 : -1.0;
      return true;
    }
  }
  return false;
}

// Whether the two ellipses share a point of the segment between their centres: A holds it from c_A
// up to s_A |d| along it, B back from c_B up to s_B |d|, and s_A + s_B > 1. For an ellipse, s = ab
// / |(b l_u, a l_v)| with l the offset in its axes, so the test is W_A P_B + W_B P_A > W_A W_B (1 +
// slack), P = ab, W = |(b l_u, a l_v)|: no division. It decides most overlapping pairs that would
// otherwise run GJK (and is implied by either centre lying inside the other ellipse). Slack: l's
// components carry up to 4 u |d| of rounding (the pair's frame and each ellipse's rotation in it),
// which moves W relatively by at most 8 u times the ellipse's aspect (W >= min(a, b) |d|), and the
// products add a few u more.
bool centre_segment_shared(const EllipsePair<double>& p) {
  const auto reach = [&p](const EllipseSupport<double>& e, double& aspect) {
    const Vec2 l = e.rot.apply_inverse(p.delta);
    aspect += std::max(e.a, e.b) / std::min(e.a, e.b);
    return std::sqrt(e.b * l.x() * e.b * l.x() + e.a * l.y() * e.a * l.y());
  };
  double aspect = 2.0;
  const double wa = reach(p.A, aspect), wb = reach(p.B, aspect);
  return wa * (p.B.a * p.B.b) + wb * (p.A.a * p.A.b) > wa * wb * (1.0 + 32 * kU * aspect);
}

template <class Real>
Vec2 to_double(const V2<Real>& v) {
  return {static_cast<double>(v[0]), static_cast<double>(v[1])};
}

// The outcome in world axes.
template <class Real>
EllipseContact from_gjk(const GjkOutcome<Real>& g, const EllipsePair<Real>& p, const Ellipse& a, int iterations) {
  return {g.verdict != FilterVerdict::separated, to_double(p.to_world(g.direction)),
          a.center + to_double(p.to_world(g.witness)), iterations};
}

}  // namespace

EllipseContact ellipse_contact(const Ellipse& a, const Ellipse& b, std::optional<EllipsePair<double>>& pair,
                               FilterVerdict* double_verdict, bool verdict_only) {
  const Vec2 delta = b.center - a.center;
  const double length = delta.norm();
  FilterVerdict verdict = FilterVerdict::uncertain;
  EllipseContact out;
  const bool apart = far_apart(a, b, length);
  if (!apart && !pair) pair = EllipsePair<double>::of(a, b);
  Vec2 axis = Vec2::Zero();
  if (apart) {
    verdict = FilterVerdict::separated;
    out = {false, delta / length, Vec2::Zero(), 0};
  } else if (boxes_apart(*pair, delta, axis)) {
    verdict = FilterVerdict::separated;
    out = {false, pair->to_world(axis), Vec2::Zero(), 0};
  } else if (clearly_inside(pair->A, pair->delta)) {
    verdict = FilterVerdict::overlap;
    out = {true, Vec2::UnitX(), b.center, 0};
  } else if (clearly_inside(pair->B, Vec2(-pair->delta))) {
    verdict = FilterVerdict::overlap;
    out = {true, Vec2::UnitX(), a.center, 0};
  } else if (verdict_only && centre_segment_shared(*pair)) {
    verdict = FilterVerdict::overlap;
    out = {true, Vec2::UnitX(), Vec2::Zero(), 0};
  } else {
    const auto g = decide(*pair);
    verdict = g.verdict;
    out = from_gjk(g, *pair, a, g.iterations);
  }
  if (double_verdict) *double_verdict = verdict;
  if (verdict != FilterVerdict::uncertain || double_verdict) return out;
  const auto wide = EllipsePair<DoubleDouble>::of(a, b);
  const auto g = decide(wide);
  EllipseContact last = from_gjk(g, wide, a, out.iterations + g.iterations);
  // Within double-double rounding of touching: the sign of s at the maximum is the best evidence.
  if (g.verdict == FilterVerdict::uncertain) last.overlap = !(g.separation > 0);
  return last;
}

}  // namespace detail

namespace {

// A pair not far apart: the algebraic test (overlap_ellipse_ellipse-inl.h, which the batch runs on vectors),
// else the certain cases and GJK of ellipse_contact.
bool near_overlap(const Ellipse& a, const Orientation& a_orientation, const Ellipse& b,
                  const Orientation& b_orientation) {
  const auto cubic = detail::ellipse_cubic_verdicts(detail::Scalar{},
                                                    detail::ellipse_ellipse_lanes(a, a_orientation, b, b_orientation));
  if (cubic.separated || cubic.overlap) return cubic.overlap;
  std::optional<detail::EllipsePair<double>> pair = detail::EllipsePair<double>::of(
      a, detail::Rotation<double>::of(a_orientation), b, detail::Rotation<double>::of(b_orientation));
  return detail::ellipse_contact(a, b, pair, nullptr, true).overlap;
}

}  // namespace

// Far apart first: no sines and cosines for those.
bool overlap_ellipse_ellipse(const Ellipse& a, const Ellipse& b) {
  if (detail::far_apart(a, b, (b.center - a.center).norm())) return false;
  return near_overlap(a, Orientation::of(a.angle), b, Orientation::of(b.angle));
}

bool overlap_ellipse_ellipse(const Ellipse& a, const Orientation& a_orientation, const Ellipse& b,
                             const Orientation& b_orientation) {
  if (detail::far_apart(a, b, (b.center - a.center).norm())) return false;
  return near_overlap(a, a_orientation, b, b_orientation);
}

detail::FilterVerdict detail::overlap_ellipse_ellipse_filter(const Ellipse& a, const Ellipse& b) {
  std::optional<detail::EllipsePair<double>> pair;
  FilterVerdict verdict = FilterVerdict::uncertain;
  detail::ellipse_contact(a, b, pair, &verdict, true);
  return verdict;
}

}  // namespace collide2d
