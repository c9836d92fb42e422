// Method: conservative advancement on the exact signed distance d(t) of contact(). At time t, with
// separation d and normal n, the separation of the pair along the fixed direction n changes at the
// rate n.(v_B - v_A) plus that of the two support functions, and a shape turning at rate w changes
// its support function at most |w| L, L the largest distance of its normal lines from its centre
// (a - b for an ellipse, the longer half side of a rectangle, 0 for a circle; turning_reach derives
// them), less than the farthest point that B. Mirtich's conservative advancement uses ("Impulse-based
// Dynamic Simulation of Rigid Body Systems", 1996). As d(t') >= s(n, t'),
//   d(t') >= d - (W - n.(v_B - v_A)) (t' - t),      W = |w_A| L_A + |w_B| L_B,
// and the step goes to where this lower bound reaches half the tolerance: never past the first time
// the shapes touch, nor past the first time their separation falls to half the tolerance. For
// translation alone (W = 0) d is convex in t (a maximum of functions affine in t) with slope
// n.(v_B - v_A) at t, so the step is Newton's on d from below its root: quadratic, never past it.
// With rotation that bound alone converges linearly, so Taylor bounds ride along. d(t') is at least
// the separation along any axis u(t'), as it is the largest over all of them; take u turning from
// n at a constant rate omega. Each shape then turns relative to the axis, and its support function
// along u is at most a parabola in t' - t (an ellipse's from its exact slope and h'' <= a^2 / b - b;
// a rectangle's the largest of one parabola per corner), as is the centres' offset projected on u
// from below, so d(t') is at least a concave function whose first root is safe too. The axes: the
// fixed one and one turning with the shape that turns, or, where both turn, one axis only, turning
// with a rectangle (a contact on a rectangle's face: along a fixed axis its far corner crosses at
// once while d does not move to first order; Box2D's face separation functions turn with the body
// too; of two rectangles, the one whose face normal lies nearest n) or with the slower of two
// ellipses (leading_axis, below). The step goes to the latest of all the first roots. Each step's
// probe, and the contact of two ellipses, climb from the last step's normal (ContactOptions::guess);
// each step reuses the cosine and sine of a shape that does not turn, and takes a turning one's from
// a polynomial (quick_orientation.h). Far from contact a pair with an ellipse (and no circle) takes
// the climb's direction once Newton's next gain is below 3% of the separation, without certifying
// the maximum, and two rectangles the widest gap along the last normal and their face normals: any
// direction's separation is a lower bound of d, and the step stays safe. Every result comes from an
// exact contact().

#include <collide2d/time_of_impact.h>

#include <collide2d/kernels.h>

#include "narrowphase/shared/curved/deepest_direction.h"
#include "narrowphase/toi/quick_orientation.h"
#include "shapes/internal.h"
#include "shapes/kinds.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <tuple>
#include <type_traits>

namespace collide2d {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

// How fast a shape's support function h(n) changes as the shape turns, per radian: the distance
// from the centre of the normal line at the support point, |p x n|, at its largest (each kind's
// turning_reach, shapes/internal.h): less than the farthest point, the bound of plain conservative
// advancement, and a circle's is 0.
double turning_reach(const Shape& s) {
  return std::visit([](const auto& x) { return detail::turning_reach(x); }, s);
}

// The motion must be finite and keep the centre within the supported range over the step.
void validate(const Shape& s, const Motion& m, const char* which) {
  validate(s);
  for (int k = 0; k < 2; ++k) {
    const char* field = k == 0 ? "velocity x" : "velocity y";
    const double v = m.velocity[k];
    if (!std::isfinite(v)) detail::reject(which, field, v, "must be finite");
    if (std::abs(center_of(s)[k] + v) > kMaxMagnitude)
      detail::reject(which, field, v, "carries the centre beyond +-1e50");
  }
  if (!std::isfinite(m.angular_velocity))
    detail::reject(which, "angular velocity", m.angular_velocity, "must be finite");
}

// A world direction in a shape's own axes, with its kept orientation.
Vec2 in_axes(const Orientation& o, const Vec2& n) { return detail::Rotation<double>::of(o).apply_inverse(n); }

// The support function of a shape along a unit direction given in its own axes (a segment's from its
// first point).
double support_in_axes(const Shape& s, const Vec2& local) {
  return std::visit([&local](const auto& x) { return detail::support_along(x, local); }, s);
}

// An upper bound of a turning shape's support function h along a fixed direction n over the rest of
// the step, for the Taylor bound (the method, above): the largest of a few parabolas in the time from
// now, each h_now - gap + slope t + bend t^2 / 2. The slope of h is w dh/dtheta = w n.perp(q), q the
// support point's offset from the centre (the envelope theorem). An ellipse's h + h'' is its radius
// of curvature at q, so h'' <= a^2 / b - b everywhere: one parabola. A rectangle's h is the largest
// of its corners' sinusoids A cos x + B sin x (x the turn since now, A = n.p, B = n.perp(p)), and
// each is at most A + B x + (|A| + |B|) x^2 / 2 (|cos x - 1| and |sin x - x| are at most x^2 / 2):
// one parabola per corner, so that the corner that takes over as the support is covered too.
struct Parabola {
  double gap;  // below h now
  double slope;
  double bend;
};
// Only the first `count` pieces are set: a turning step copies these often, and zeroing all four
// would cost more than the bound itself.
struct SupportBound {
  std::array<Parabola, 4> pieces;
  int count = 1;
};

SupportBound support_bound(const Shape& s, const Orientation& o, double w, const Vec2& n) {
  SupportBound out;
  out.pieces[0] = {0.0, 0.0, 0.0};
  if (w == 0) return out;
  const Vec2 local = in_axes(o, n);
  const auto turn = [&](const Vec2& q) { return local.y() * q.x() - local.x() * q.y(); };  // dh/dtheta
  std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, Ellipse>) {
          const Vec2 q(x.a * x.a * local.x(), x.b * x.b * local.y());
          const double major = std::max(x.a, x.b), minor = std::min(x.a, x.b);
          out.pieces[0] = {0.0, w * turn(q / detail::support_along(x, local)), w * w * (major * major / minor - minor)};
        } else if constexpr (std::is_same_v<T, Rect>) {
          // The support corner first: its pieces decide most steps. The corners' dot products are
          // written out in doubles, which compile to shorter code than arrays of Eigen 2-vectors.
          const double lx = local.x(), ly = local.y();
          const double px = std::copysign(x.half_extents.x(), lx), py = std::copysign(x.half_extents.y(), ly);
          const double cx[4] = {px, -px, px, -px}, cy[4] = {py, py, -py, -py};
          const double top = lx * px + ly * py;
          for (std::size_t i = 0; i < 4; ++i) {
            const double along = lx * cx[i] + ly * cy[i], across = ly * cx[i] - lx * cy[i];
            out.pieces[i] = {top - along, w * across, w * w * (std::abs(along) + std::abs(across))};
          }
          out.count = 4;
        } else if constexpr (requires { detail::core_points(x); }) {
          // Each core point's sinusoid (the radius adds a constant) is at most A + B x + (|A| + |B|)
          // x^2 / 2, and A is at most h now: one parabola with the largest slope and bend covers all.
          double slope = -std::numeric_limits<double>::infinity(), bend = 0.0;
          for (const Vec2& v : detail::core_points(x)) {
            const double along = local.dot(v), across = turn(v);
            slope = std::max(slope, w * across);
            bend = std::max(bend, w * w * (std::abs(along) + std::abs(across)));
          }
          out.pieces[0] = {0.0, slope, bend};
        }
      },
      s);
  return out;
}

// The first time at which gap + slope t - bend t^2 / 2 (gap > 0, bend >= 0) falls to 0; 0 where
// the terms overflow (an infinite bend over an infinite root would claim a miss).
double first_root(double gap, double slope, double bend) {
  if (std::isnan(slope) || std::isnan(bend)) return 0.0;
  if (bend == 0) return slope < 0 ? gap / -slope : INFINITY;
  const double root = slope <= 0 ? 2 * gap / (std::sqrt(slope * slope + 2 * bend * gap) - slope)
                                 : (slope + std::sqrt(slope * slope + 2 * bend * gap)) / bend;
  return root >= 0 ? root : 0.0;
}

// A lower bound of the separation along an axis u(t') that starts at the normal n and turns at a
// constant rate omega: d(t') >= s(u(t'), t') for any axis, as d is the largest separation over all
// of them. Each shape then turns relative to the axis, at its rate less omega, and the centres'
// offset c + v t' (now c) projects onto the axis as (c.n + t' v.n) cos x + (c.m + t' v.m) sin x,
// x = omega t', m = perp(n): at least c.n + (v.n + omega c.m) t' - bend t'^2 / 2 with
// bend = omega^2 (|c.n| + |c.m| + |v.n| + |v.m|) + 2 |omega v.m| for t' <= 1 (|cos x - 1| and
// |sin x - x| are at most x^2 / 2). An axis fixed in the world (omega 0) suits curved contacts; one
// that turns with a rectangle suits a contact on its face, which a fixed axis sees its far corner
// cross at once (Box2D's face separation functions turn with the body too).
struct Axis {
  double slope = 0.0;  // of the centres' term, less its rounding
  double bend = 0.0;
  SupportBound a;  // A's support function along u, B's along -u
  SupportBound b;
};

// The later of `step` and the first time at which the axis' bound could fall from `gap` (the
// separation less its target) to 0: the least over pairs of support pieces of a concave function of
// time. A pair of pieces not above 0 at `step` makes this axis no better than `step`; a pair
// positive at the least root found so far is positive before it (concave) and needs no root.
double later_root(double step, double gap, const Axis& axis) {
  double root = INFINITY;
  for (int i = 0; i < axis.a.count; ++i) {
    for (int j = 0; j < axis.b.count; ++j) {
      const Parabola& pa = axis.a.pieces[static_cast<std::size_t>(i)];
      const Parabola& pb = axis.b.pieces[static_cast<std::size_t>(j)];
      const double g = gap + pa.gap + pb.gap, bend = axis.bend + pa.bend + pb.bend;
      const double slope = axis.slope - pa.slope - pb.slope;
      const auto at = [&](double t) { return g + slope * t - bend * t * t / 2; };
      if (step < INFINITY && !(at(step) > 0)) return step;
      if (root < INFINITY && at(root) > 0) continue;
      root = std::min(root, first_root(g, slope, bend));
    }
  }
  return std::max(step, root);
}

// The separation along a direction near the maximiser, a lower bound of d that serves a step far
// from contact as well as d itself (the method, above), for pairs without a circle (whose contacts
// are closed forms and cheap). With an ellipse, the contact's climb from the last normal, stopped
// once its next gain is below 3% of the separation (the step is then within 3% of the exact one; a
// tighter stop costs more evaluations than the steps it saves), where an exact contact certifies
// its maximum to rounding (two or three more support evaluations); for two rectangles, and where
// the climb does not end apart, widest_gap (below).
// nullopt where neither finds the pair apart.
struct Probe {
  double separation;
  Vec2 normal;
};

template <class SA, class SB, class X, class Y>
std::optional<Probe> climb(const X& a, const Orientation& oa, const Y& b, const Orientation& ob, const Vec2& guess) {
  using Pair = detail::SupportPair<double, SA, SB>;
  const Pair p = Pair::of(a, detail::Rotation<double>::of(oa), b, detail::Rotation<double>::of(ob));
  const auto d = detail::certified_climb(p, p.from_world(guess), detail::climb_margin(p), 3e-2).deepest;
  if (!d || !(d->at.s > 0)) return std::nullopt;
  return Probe{d->at.s, p.to_world(d->n)};
}

// The widest gap along the last normal and each rectangle's face normals (the separating axes; for
// two rectangles apart, all the exact contact adds is a corner–corner distance beyond them, its
// closest features and its manifold): the probe of rectangle pairs, and where a climb does not end
// apart.
std::optional<Probe> widest_gap(const Shape& a, const Orientation& oa, const Shape& b, const Orientation& ob,
                                const Vec2& guess) {
  const Vec2 delta = center_of(b) - center_of(a);
  Probe best{0.0, Vec2::UnitX()};
  const auto try_axis = [&](const Vec2& axis) {
    const Vec2 n = delta.dot(axis) >= 0 ? axis : Vec2(-axis);
    const double gap = n.dot(delta) - support_in_axes(a, in_axes(oa, n)) - support_in_axes(b, in_axes(ob, Vec2(-n)));
    if (gap > best.separation) best = {gap, n};
  };
  if (guess != Vec2::Zero()) try_axis(guess);
  for (const auto& [s, o] : {std::pair{&a, &oa}, std::pair{&b, &ob}}) {
    if (std::holds_alternative<Rect>(*s)) {
      try_axis(Vec2(o->c, o->s));
      try_axis(Vec2(-o->s, o->c));
    }
  }
  if (!(best.separation > 0)) return std::nullopt;
  return best;
}

std::optional<Probe> probe(const Shape& a, const Orientation& oa, const Shape& b, const Orientation& ob,
                           const Vec2& guess) {
  using detail::EllipseSupport, detail::RectSupport;
  const auto* ea = std::get_if<Ellipse>(&a);
  const auto* eb = std::get_if<Ellipse>(&b);
  const auto* ra = std::get_if<Rect>(&a);
  const auto* rb = std::get_if<Rect>(&b);
  std::optional<Probe> r;
  if (ea && eb) r = climb<EllipseSupport<double>, EllipseSupport<double>>(*ea, oa, *eb, ob, guess);
  if (ra && eb) r = climb<RectSupport<double>, EllipseSupport<double>>(*ra, oa, *eb, ob, guess);
  if (ea && rb) {
    r = climb<RectSupport<double>, EllipseSupport<double>>(*rb, ob, *ea, oa, Vec2(-guess));
    if (r) r->normal = -r->normal;
  }
  if (r || std::holds_alternative<Circle>(a) || std::holds_alternative<Circle>(b)) return r;
  return widest_gap(a, oa, b, ob, guess);
}

// Where both shapes turn, the one axis worth its cost (1: turning with A, 2: with B). With a
// rectangle, one turning with it, as a contact on its face needs (of two rectangles, the one whose
// face normal lies nearest n, the contact's reference face); two ellipses, the slower one's, which
// bends the centres' term least (omega^2 times their offset, several times the shapes' own terms).
// A second turning axis saves a few steps but costs more than it saves.
std::size_t leading_axis(const Shape& a, const Orientation& oa, double wa, const Shape& b, const Orientation& ob,
                         double wb, const Vec2& n) {
  const bool rect_a = std::holds_alternative<Rect>(a), rect_b = std::holds_alternative<Rect>(b);
  if (rect_a && rect_b) {
    return in_axes(oa, n).cwiseAbs().maxCoeff() >= in_axes(ob, n).cwiseAbs().maxCoeff() ? 1 : 2;
  }
  if (rect_a || rect_b) return rect_a ? 1 : 2;
  return std::abs(wa) <= std::abs(wb) ? 1 : 2;
}

TimeOfImpact result(ToiStatus status, double t, const Contact& c, int iterations) {
  return {status, t, c.normal, Vec2((c.point_a + c.point_b) / 2), iterations};
}

}  // namespace

Shape at_time(const Shape& s, const Motion& m, double t) {
  return std::visit(
      [&](auto shape) -> Shape {
        shape.center += t * m.velocity;
        if constexpr (!std::is_same_v<decltype(shape), Circle>) shape.angle += t * m.angular_velocity;
        return shape;
      },
      s);
}

namespace {

// The first contact of a pair in A's frame of translation (A's centre at the origin, at rest).
TimeOfImpact relative_time_of_impact(const Shape& a, const Motion& a_motion, const Shape& b, const Motion& b_motion,
                                     const ToiOptions& options) {
  // Poses along the step are rounded to their coordinates' ulps, and a separation below that cannot
  // be kept: a step aimed closer could land on a rounded pose that overlaps. The tolerance is at
  // least 8 u of the coordinates (relative to A's centre, so of the pair's own extent and motion).
  const double coordinates = center_of(a).cwiseAbs().maxCoeff() + a_motion.velocity.cwiseAbs().maxCoeff() +
                             center_of(b).cwiseAbs().maxCoeff() + b_motion.velocity.cwiseAbs().maxCoeff();
  const double tolerance = std::max(options.tolerance > 0 ? options.tolerance : 1e-9 * (reach_of(a) + reach_of(b)),
                                    8 * std::numeric_limits<double>::epsilon() * coordinates);
  const Vec2 v = b_motion.velocity - a_motion.velocity;
  const double spin =
      std::abs(a_motion.angular_velocity) * turning_reach(a) + std::abs(b_motion.angular_velocity) * turning_reach(b);
  const double reaches = turning_reach(a) + turning_reach(b);
  // Shapes stay valid over the step (validate above), and only a turning one needs its cosine and
  // sine again, from quick_orientation where the angle allows (the C library's sincos would be a
  // large part of a turning pair's time).
  const auto orientation = [](const Shape& s, const Motion& m, const Orientation& start) {
    if (m.angular_velocity == 0) return start;
    const std::optional<Orientation> quick = detail::quick_orientation(angle_of(s));
    return quick ? *quick : Orientation::of(angle_of(s));
  };
  const auto kept = [](const Shape& s, const Motion& m) {
    return m.angular_velocity == 0 ? Orientation::of(angle_of(s)) : Orientation{};
  };
  const Orientation a_start = kept(a, a_motion), b_start = kept(b, b_motion);
  double t = 0.0;
  ContactOptions warm;  // each step's climb starts from the last normal, near the next one
  for (int k = 1;; ++k) {
    const Shape at_a = at_time(a, a_motion, t), at_b = at_time(b, b_motion, t);
    const Orientation oa = orientation(at_a, a_motion, a_start), ob = orientation(at_b, b_motion, b_start);
    // Far from contact a probe serves; near it, and for every result, the exact contact.
    const auto exact = [&] { return contact(at_a, oa, at_b, ob, warm); };
    std::optional<Probe> c = probe(at_a, oa, at_b, ob, warm.guess);
    if (!c || c->separation <= tolerance) {
      const Contact x = exact();
      if (k == 1 && x.separation <= 0) return result(ToiStatus::overlapping, 0.0, x, k);
      if (x.separation <= tolerance) return result(ToiStatus::hit, t, x, k);
      c = Probe{x.separation, x.normal};
    }
    warm.guess = c->normal;
    // The step goes to the latest of the first times at which a lower bound of d could fall to half
    // the tolerance: the rate bound, then the Taylor bounds along a fixed axis and along axes that
    // turn with either shape (the method, above).
    const Vec2 n = c->normal, m(-n.y(), n.x());
    const double along = n.dot(v), gap = c->separation - tolerance / 2;
    const double closing = spin - along;  // the fastest the separation can fall
    double step = closing > 0 ? gap / closing : INFINITY;
    const Vec2 centres = center_of(at_b) - center_of(at_a);
    const double offset = std::abs(centres.dot(n)) + std::abs(centres.dot(m)) + std::abs(along) + std::abs(m.dot(v));
    const double wa = a_motion.angular_velocity, wb = b_motion.angular_velocity;
    const std::array<double, 3> omegas{0.0, wa, wb};
    const std::size_t lead = wa != 0 && wb != 0 ? leading_axis(at_a, oa, wa, at_b, ob, wb, n) : 0;
    for (std::size_t i = 0; i < omegas.size(); ++i) {
      const double omega = omegas[i];
      // An axis already tried; where both shapes turn, only the leading one.
      if ((lead != 0 && i != lead) || (i > 0 && omega == 0.0) || (i == 2 && omega == wa)) continue;
      // The slope less the rounding of its terms (n is a rounded unit vector), which the tolerance
      // of a fast bullet would not cover.
      const double rounding = 16 * kU * (v.norm() + spin + std::abs(omega) * (centres.norm() + reaches));
      const Axis axis{along + omega * centres.dot(m) - rounding,
                      omega * omega * offset + 2 * std::abs(omega * m.dot(v)), support_bound(at_a, oa, wa - omega, n),
                      support_bound(at_b, ob, wb - omega, -n)};
      step = later_root(step, gap, axis);
    }
    if (!(t + step < 1.0)) return result(ToiStatus::miss, 1.0, exact(), k);
    if (k == options.max_iterations) return result(ToiStatus::stalled, t, exact(), k);
    t += step;
  }
}

}  // namespace

namespace {

// Whether the pair goes in the other order: by kind, then centre, angle and motion. The steps round
// in the first shape's frame, so that one order for both ways of giving the pair makes
// time_of_impact(b, a) time_of_impact(a, b) turned round to the bit, as Worlds that number the same
// bodies differently need (partition.h).
bool turned_round(const Shape& a, const Motion& a_motion, const Shape& b, const Motion& b_motion) {
  const auto key = [](const Shape& s, const Motion& m) {
    return std::tuple(detail::kind_number(s), center_of(s).x(), center_of(s).y(), angle_of(s), m.velocity.x(),
                      m.velocity.y(), m.angular_velocity);
  };
  return key(b, b_motion) < key(a, a_motion);
}

}  // namespace

// Solved relative to A: the poses along the step then round to the pair's own coordinates, not to
// its offset from the origin, which at 1e6 would cost more than the default tolerance.
TimeOfImpact time_of_impact(const Shape& a, const Motion& a_motion, const Shape& b, const Motion& b_motion,
                            const ToiOptions& options) {
  validate(a, a_motion, "A");
  validate(b, b_motion, "B");
  if (!(options.tolerance >= 0) || !std::isfinite(options.tolerance)) {
    detail::reject("time of impact", "tolerance", options.tolerance, "must be finite and not negative");
  }
  if (turned_round(a, a_motion, b, b_motion)) {
    TimeOfImpact r = time_of_impact(b, b_motion, a, a_motion, options);
    r.normal = -r.normal;
    return r;
  }
  const Vec2 origin = center_of(a);
  const auto relative = [&origin](const Shape& s) { return at_time(s, {Vec2(-origin), 0.0}, 1.0); };
  TimeOfImpact r =
      relative_time_of_impact(relative(a), {Vec2::Zero(), a_motion.angular_velocity}, relative(b),
                              {Vec2(b_motion.velocity - a_motion.velocity), b_motion.angular_velocity}, options);
  r.point += origin + r.t * a_motion.velocity;
  return r;
}

std::optional<CastHit> shape_cast(const Shape& shape, const Vec2& translation, const Shape& target,
                                  const ToiOptions& options) {
  const TimeOfImpact r = time_of_impact(target, {}, shape, {translation, 0.0}, options);
  if (r.status == ToiStatus::miss) return std::nullopt;
  return CastHit{r.t, r.point, r.normal};
}

}  // namespace collide2d
