// Time of impact against constructions whose first contact time is known exactly, and the
// guarantees over random motions: never after the first contact, within tolerance at the time
// reported, no contact anywhere before it.
#include <collide2d/time_of_impact.h>

#include <collide2d/query.h>
#include "mp_reference.h"
#include "tools/random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace collide2d {
namespace {

constexpr double kU = 1.1102230246251565e-16;

// The reported time lies before the exact first contact t0, by no more than the tolerance over the
// closing speed (plus the rounding of the construction, `slack`).
void expect_hit_before(const TimeOfImpact& got, double t0, double tolerance, double closing, double slack = 0) {
  ASSERT_EQ(got.status, ToiStatus::hit);
  EXPECT_LE(got.t, t0 + slack);
  EXPECT_GE(got.t, t0 - tolerance / closing - slack);
}

TEST(TimeOfImpact, CirclesHeadOn) {
  const Circle a{{0, 0}, 1}, b{{10, 0}, 1};
  const TimeOfImpact got = time_of_impact(a, {}, b, {{-20, 0}, 0}, {1e-9, 1000});
  expect_hit_before(got, 0.4, 1e-9, 20, 4 * kU);
  EXPECT_NEAR(got.normal.x(), 1.0, 1e-15);
  EXPECT_NEAR(got.point.x(), 1.0, 1e-8);
  EXPECT_LE(got.iterations, 3);
}

TEST(TimeOfImpact, BothMoving) {
  const Circle a{{-3, 0}, 0.5}, b{{3, 0}, 0.5};
  const TimeOfImpact got = time_of_impact(a, {{4, 0}, 0}, b, {{-6, 0}, 0}, {1e-9, 1000});
  expect_hit_before(got, 0.5, 1e-9, 10, 4 * kU);  // gap 5 closed at 10 per step
}

// A bullet at 10 to 1e6 of its size per step through a wall 10 of its sizes thick: without
// continuous collision it is on one side at t = 0 and on the other at t = 1.
TEST(TimeOfImpact, BulletsDoNotTunnel) {
  const Rect wall{{0, 0}, {0.005, 1}, 0};
  for (const double sizes_per_step : {10.0, 1e2, 1e3, 1e4, 1e5, 1e6}) {
    const double r = 0.001, speed = sizes_per_step * 2 * r;
    const Circle bullet{{-speed / 2, 0.3}, r};  // after the step, as far beyond the wall
    ASSERT_FALSE(overlaps(wall, at_time(bullet, {{speed, 0}, 0}, 1.0)));
    const TimeOfImpact got = time_of_impact(wall, {}, bullet, {{speed, 0}, 0}, {1e-12, 1000});
    const double t0 = (speed / 2 - 0.005 - r) / speed;
    expect_hit_before(got, t0, 1e-12, speed, 8 * kU);
    EXPECT_NEAR(got.normal.x(), -1.0, 1e-12) << sizes_per_step;
  }
}

// An ellipse falling onto a rectangle's face, and a spinning one.
TEST(TimeOfImpact, EllipseOntoAFace) {
  const Rect floor{{0, 0}, {4, 1}, 0};
  const Ellipse e{{0.5, 5}, 2, 0.5, 0};
  const TimeOfImpact got = time_of_impact(floor, {}, e, {{0, -10}, 0}, {1e-9, 1000});
  expect_hit_before(got, 0.35, 1e-9, 10, 8 * kU);
  EXPECT_NEAR(got.normal.y(), 1.0, 1e-12);
}

// A needle (half-length 1, half-width 0.01) turning about its centre towards a circle of radius 0.1
// centred 0.5 along the normal of its start: its side reaches the circle when 0.5 cos(theta) =
// 0.11, at theta = acos(0.22), whatever the rate (1.6 to 100 radians per step).
TEST(TimeOfImpact, SpinningNeedle) {
  const Rect needle{{0, 0}, {1, 0.01}, 0};
  const Circle c{{0, 0.5}, 0.1};
  const double theta = std::acos(0.22);
  for (const double w : {std::numbers::pi / 2, 10.0, 100.0}) {
    const TimeOfImpact got = time_of_impact(needle, {Vec2::Zero(), w}, c, {}, {1e-12, 100000});
    ASSERT_EQ(got.status, ToiStatus::hit) << w;
    const double t0 = theta / w;
    EXPECT_LE(got.t, t0 + 8 * kU) << w;
    EXPECT_GE(got.t, t0 - 1e-9) << w << " after " << got.iterations << " steps";
    std::printf("[toi] needle turning %.3g rad per step: %d steps\n", w, got.iterations);
  }
}

TEST(TimeOfImpact, GrazingPasses) {
  const Rect wall{{0, 0}, {0.5, 0.5}, 0};
  for (const double gap : {1e-3, 1e-6, 1e-9}) {
    const Circle passing{{-3, 0.5 + 0.1 + gap}, 0.1};
    const TimeOfImpact miss = time_of_impact(wall, {}, passing, {{6, 0}, 0}, {gap / 4, 1000});
    EXPECT_EQ(miss.status, ToiStatus::miss) << gap;
    EXPECT_EQ(miss.t, 1.0);
    const Circle touching{{-3, 0.5 + 0.1 - gap}, 0.1};
    const TimeOfImpact hit = time_of_impact(wall, {}, touching, {{6, 0}, 0}, {gap / 4, 1000});
    EXPECT_EQ(hit.status, ToiStatus::hit) << gap;
  }
}

TEST(TimeOfImpact, OverlappingAtTheStart) {
  const TimeOfImpact got = time_of_impact(Circle{{0, 0}, 1}, {}, Ellipse{{1, 0}, 1, 0.5, 0.3}, {{5, 0}, 0});
  EXPECT_EQ(got.status, ToiStatus::overlapping);
  EXPECT_EQ(got.t, 0.0);
  EXPECT_EQ(got.iterations, 1);
}

TEST(TimeOfImpact, MovingApartMisses) {
  const TimeOfImpact got = time_of_impact(Rect{{0, 0}, {1, 1}, 0}, {}, Circle{{3, 0}, 1}, {{1, 0}, 0});
  EXPECT_EQ(got.status, ToiStatus::miss);
  EXPECT_EQ(got.iterations, 1);
}

// Random pairs of every kind with random motions, spins up to 20 radians per step: at a hit the
// separation is within (0, tolerance], and 200 times before it the pair is apart; at a miss
// the pair is apart at 200 times over the step and at its end.
TEST(TimeOfImpact, NeverAfterTheFirstContact) {
  std::mt19937_64 rng(7);
  const tool::Uniform u(-1, 1);
  const auto shape = [&](int kind) -> Shape {
    const double y = 3 * u(rng);
    const Vec2 c(3 * u(rng), y);
    const double s = 0.1 + 0.45 * (u(rng) + 1);
    if (kind == 0) return Circle{c, s};
    if (kind == 1) return Ellipse{c, s, s * (0.05 + 0.475 * (u(rng) + 1)), 3 * u(rng)};
    return Rect{c, {s, s * (0.05 + 0.475 * (u(rng) + 1))}, 3 * u(rng)};
  };
  int hits = 0, misses = 0, checked = 0, most = 0;
  for (int k = 0; k < 600; ++k) {
    const Shape a = shape(k % 3), b = shape((k / 3) % 3);
    if (overlaps(a, b)) continue;
    const Motion ma{{6 * u(rng), 6 * u(rng)}, k % 2 ? 20 * u(rng) : 0.0};
    const Motion mb{{6 * u(rng), 6 * u(rng)}, k % 4 == 1 ? 20 * u(rng) : 0.0};
    const double tolerance = 1e-9;
    const TimeOfImpact got = time_of_impact(a, ma, b, mb, {tolerance, 100000});
    ASSERT_NE(got.status, ToiStatus::stalled) << k;
    most = std::max(most, got.iterations);
    ASSERT_NE(got.status, ToiStatus::overlapping) << k;
    const double end = got.status == ToiStatus::hit ? got.t : 1.0;
    for (int j = 0; j <= 200; ++j) {
      const double t = end * j / 200;
      const double d = contact(at_time(a, ma, t), at_time(b, mb, t)).separation;
      EXPECT_GT(d, 0) << "case " << k << " apart until " << end << " but not at " << t;
      ++checked;
    }
    if (got.status == ToiStatus::hit) {
      ++hits;
      const double d = contact(at_time(a, ma, got.t), at_time(b, mb, got.t)).separation;
      EXPECT_LE(d, tolerance);
    } else {
      ++misses;
    }
  }
  EXPECT_GT(hits, 40);
  EXPECT_GT(misses, 50);
  std::printf("[toi] random motions: %d hits, %d misses, %d earlier times apart; at most %d steps\n", hits, misses,
              checked, most);
}

// The separation, in 50 digits, of two circles, or of two axis-aligned rectangles, at time t of
// their motions: the poses c + t v exact, not rounded to doubles.
reference::Real separation_at(const Shape& a, const Motion& ma, const Shape& b, const Motion& mb, double t) {
  using reference::Real;
  const auto at = [t](const Shape& s, const Motion& m, int k) {
    return Real(center_of(s)[k]) + Real(t) * Real(m.velocity[k]);
  };
  const Real dx = at(b, mb, 0) - at(a, ma, 0), dy = at(b, mb, 1) - at(a, ma, 1);
  if (const auto* ca = std::get_if<Circle>(&a)) {
    return boost::multiprecision::sqrt(dx * dx + dy * dy) - Real(ca->radius) - Real(std::get<Circle>(b).radius);
  }
  const Vec2 ha = std::get<Rect>(a).half_extents, hb = std::get<Rect>(b).half_extents;
  const Real gx = abs(dx) - Real(ha.x()) - Real(hb.x()), gy = abs(dy) - Real(ha.y()) - Real(hb.y());
  if (gx > 0 && gy > 0) return boost::multiprecision::sqrt(gx * gx + gy * gy);
  return gx > gy ? gx : gy;
}

// Far from the origin the pair is solved relative to A, so the documented bound holds where the
// poses are exact: at the time reported, the exact separation of the exact poses lies in
// (0, tolerance], tolerance 1e-9 of the reaches, up to the rounding of the pair's relative
// coordinates (16 u of them). Circles and axis-aligned rectangles (their separation in closed form)
// at offsets of 1e6 and 1e9, closing at random speeds, and the pair near (-1e6, -7e5) that landed
// at 2.3 tolerances.
TEST(TimeOfImpact, FarFromTheOriginKeepsItsBound) {
  std::mt19937_64 rng(19);
  const tool::Uniform u(-1, 1);
  struct Pair {
    Shape a, b;
    Motion ma, mb;
  };
  std::vector<Pair> pairs = {{Circle{{-1000000.0, -700000.0}, 0.2678036854418022},
                              Circle{{-1000003.036265183, -699998.7082726184}, 0.745590260396122},
                              {},
                              {{2.634324061738085, -2.183742880388848}, 0.0}}};
  for (const double offset : {1e6, 1e9}) {
    for (int k = 0; k < 300; ++k) {
      const double at_y = offset * u(rng);
      const Vec2 at(offset * u(rng), at_y);
      const double gap_y = 3 * u(rng);
      const Vec2 gap(3 * u(rng), gap_y);
      const Motion ma{{2 * u(rng), 2 * u(rng)}, 0.0}, mb{Vec2(-gap * (1.2 + u(rng) * 0.1) + ma.velocity), 0.0};
      if (k % 2 == 0) {
        pairs.push_back({Circle{at, 0.1 + 0.5 * (u(rng) + 1)}, Circle{at + gap, 0.1 + 0.5 * (u(rng) + 1)}, ma, mb});
      } else {
        pairs.push_back({Rect{at, {0.2 + 0.3 * (u(rng) + 1), 0.2 + 0.3 * (u(rng) + 1)}, 0},
                         Rect{at + gap, {0.2 + 0.3 * (u(rng) + 1), 0.2 + 0.3 * (u(rng) + 1)}, 0}, ma, mb});
      }
    }
  }
  int hits = 0;
  double worst = 0;  // of the tolerance
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const Pair& p = pairs[k];
    if (overlaps(p.a, p.b)) continue;
    const TimeOfImpact got = time_of_impact(p.a, p.ma, p.b, p.mb);
    if (got.status != ToiStatus::hit) continue;
    ++hits;
    const double tolerance = 1e-9 * (reach_of(p.a) + reach_of(p.b));
    const Vec2 relative = center_of(p.b) - center_of(p.a), closing = p.mb.velocity - p.ma.velocity;
    const double rounding = 16 * kU * (relative.norm() + closing.norm() + reach_of(p.a) + reach_of(p.b));
    const double d = static_cast<double>(separation_at(p.a, p.ma, p.b, p.mb, got.t));
    worst = std::max(worst, d / tolerance);
    EXPECT_GT(d, -rounding) << "pair " << k;
    EXPECT_LE(d, tolerance + rounding) << "pair " << k << ": " << d / tolerance << " tolerances";
  }
  EXPECT_GT(hits, 500);
  std::printf("[toi] far from the origin: %d hits, worst separation %.2f of the tolerance\n", hits, worst);
}

// A circle of radius 0.5 cast 4 to the right at a box whose face is 2.5 away from its edge: the
// fraction 2.5 / 4, the point on the face, the box's outward normal (towards the circle); a cast
// that stops short misses; one that starts in overlap hits at 0.
TEST(ShapeCast, FractionPointAndTheTargetsNormal) {
  const Rect box{{4, 0}, {1, 1}, 0};
  const auto hit = shape_cast(Circle{{0, 0}, 0.5}, Vec2(4, 0), box, {1e-12, 1000});
  ASSERT_TRUE(hit);
  EXPECT_LE(hit->fraction, 2.5 / 4);
  EXPECT_GE(hit->fraction, 2.5 / 4 - 1e-12 / 4 - 4 * kU);
  EXPECT_NEAR(hit->normal.x(), -1.0, 1e-15);
  EXPECT_NEAR(hit->point.x(), 3.0, 1e-12);
  EXPECT_FALSE(shape_cast(Circle{{0, 0}, 0.5}, Vec2(2, 0), box));
  const auto inside = shape_cast(Circle{{3.4, 0}, 0.5}, Vec2(-4, 0), box);
  ASSERT_TRUE(inside);
  EXPECT_EQ(inside->fraction, 0.0);
}

// The first contact by the 50-digit reference alone, as a bracket [apart, touching] no wider than
// 1e-13 of the step; nullopt when the shapes do not touch. Translation only: the distance of convex
// shapes is convex in t, so its minimum (golden section) decides whether they meet, and bisection
// on overlap() before it finds the first contact. With rotation: overlap() at `samples` even times,
// then bisection after the last sample apart (a contact shorter than a sample can pass unseen, so
// these families turn slowly enough per sample).
struct Bracket {
  double apart;
  double touching;
};

std::optional<Bracket> reference_first_contact(const Shape& a, const Motion& ma, const Shape& b, const Motion& mb,
                                               int samples) {
  const auto touch = [&](double t) { return reference::overlap(at_time(a, ma, t), at_time(b, mb, t)); };
  if (touch(0)) return Bracket{0, 0};
  double lo = 0, hi = 1;
  if (ma.angular_velocity == 0 && mb.angular_velocity == 0) {
    const auto gap = [&](double t) { return reference::distance(at_time(a, ma, t), at_time(b, mb, t)); };
    const double g = (std::sqrt(5.0) - 1) / 2;
    double x0 = 0, x1 = 1, m0 = x1 - g * (x1 - x0), m1 = x0 + g * (x1 - x0);
    auto f0 = gap(m0), f1 = gap(m1);
    for (int k = 0; k < 80; ++k) {
      if (f0 <= f1) {
        x1 = m1, m1 = m0, f1 = f0, m0 = x1 - g * (x1 - x0), f0 = gap(m0);
      } else {
        x0 = m0, m0 = m1, f0 = f1, m1 = x0 + g * (x1 - x0), f1 = gap(m1);
      }
    }
    const double least = f0 <= f1 ? m0 : m1;
    if (!touch(least) && !touch(1.0)) return std::nullopt;
    hi = touch(least) ? least : 1.0;
  } else {
    int k = 1;
    while (k <= samples && !touch(static_cast<double>(k) / samples)) ++k;
    if (k > samples) return std::nullopt;
    lo = static_cast<double>(k - 1) / samples;
    hi = static_cast<double>(k) / samples;
  }
  while (hi - lo > 1e-13) {
    const double mid = (lo + hi) / 2;
    (touch(mid) ? hi : lo) = mid;
  }
  return Bracket{lo, hi};
}

struct MovingCase {
  Shape a;
  Motion ma;
  Shape b;
  Motion mb;
  double tolerance;
  bool grazing;  // the time is ill-conditioned: only "never after" is asserted
};

struct ToiFamily {
  std::string name;
  std::vector<MovingCase> cases;
  int samples = 0;  // with rotation: the reference's samples over the step
};

std::vector<ToiFamily> toi_families() {
  std::mt19937_64 rng(31);
  const tool::Uniform u(0, 1);
  const auto turn = [&] { return 6.283185307179586 * u(rng); };
  const auto unit = [](double angle) { return Vec2(std::cos(angle), std::sin(angle)); };
  std::vector<ToiFamily> out;
  // Bullets (radius r) at 10 to 1e6 of their size per step through a turned wall 10 sizes thick, then
  // through a segment (a wall of no thickness), at scales 1e-6, 1 and 1e6 and offsets 0 and 1e6.
  for (const bool segment : {false, true}) {
    for (const auto& [scale, offset] : {std::pair{1.0, 0.0}, {1e-6, 0.0}, {1e6, 0.0}, {1.0, 1e6}}) {
      char name[64];
      std::snprintf(name, sizeof name, "bullets%s, size %g, offset %g", segment ? " at a segment" : "", scale, offset);
      ToiFamily f{name, {}};
      for (const double sizes : {10.0, 1e2, 1e3, 1e4, 1e5, 1e6}) {
        const double r = 0.001 * scale, angle = turn(), speed = sizes * 2 * r;
        const Vec2 c = Vec2::Constant(offset), normal = unit(angle);
        const Vec2 along(-normal.y(), normal.x());
        const Shape wall = segment ? Shape(Segment::between(c - scale * along, c + scale * along))
                                   : Shape(Rect{c, {0.01 * scale, scale}, angle});
        const Circle bullet{c - (speed / 2) * normal + (0.5 * scale * (u(rng) - 0.5)) * along, r};
        f.cases.push_back({wall, {}, bullet, {speed * normal, 0}, 1e-12 * scale, false});
      }
      out.push_back(f);
    }
  }
  // Needles of aspect 1e3 crossing a needle at 10 to 1e6 of their width per step.
  ToiFamily needles{"needles crossing", {}};
  for (const double sizes : {10.0, 1e2, 1e3, 1e4, 1e5, 1e6}) {
    const double angle = turn(), w = 0.001, speed = sizes * 2 * w;
    const Vec2 n = unit(angle + 1.5707963267948966);
    const Rect still{{0, 0}, {1, w}, angle},
        moving{-(speed / 2) * n + 0.3 * unit(angle), {1, w}, angle + 0.2 * (u(rng) - 0.5)};
    needles.cases.push_back({still, {}, moving, {speed * n, 0}, 1e-12, false});
  }
  out.push_back(needles);
  // Grazing passes beside a box's face and along an ellipse's major axis: apart by delta at the
  // closest (must miss) or overlapping by delta (must hit), delta = 1e-3 ... 1e-12.
  ToiFamily grazing{"grazing passes", {}};
  for (const double delta : {1e-3, 1e-6, 1e-9, 1e-12}) {
    for (const double side : {1.0, -1.0}) {
      const double gap = side * delta;
      grazing.cases.push_back(
          {Rect{{0, 0}, {1, 0.5}, 0}, {}, Circle{{-3, 0.5 + 0.25 + gap}, 0.25}, {{6, 0}, 0}, delta / 4, true});
      grazing.cases.push_back(
          {Ellipse{{0, 0}, 2, 0.5, 0}, {}, Circle{{-4, 0.5 + 0.25 + gap}, 0.25}, {{8, 0}, 0}, delta / 4, true});
    }
  }
  out.push_back(grazing);
  // A needle turning 1 to 100 radians per step about its centre, a circle within its reach.
  ToiFamily spinning{"spinning needles", {}, 20000};
  for (const double w : {1.0, 10.0, 100.0}) {
    for (int k = 0; k < 3; ++k) {
      const double reach = 0.2 + 0.7 * u(rng), angle = turn();
      spinning.cases.push_back({Rect{{0, 0}, {1, 0.01}, angle},
                                {Vec2::Zero(), k % 2 ? w : -w},
                                Circle{reach * unit(angle + 1.2 + 2 * u(rng)), 0.05},
                                {},
                                1e-12,
                                false});
    }
  }
  out.push_back(spinning);
  // Both moving: a circle and an ellipse, then a box and a circle, on random courses that mostly meet.
  ToiFamily both{"both moving", {}};
  for (int k = 0; k < 8; ++k) {
    const double y = u(rng);
    const Vec2 ca(u(rng), y), cb = ca + 3 * unit(turn());
    const Vec2 va = 2 * unit(turn()), vb = (ca - cb) * (2 + u(rng)) + va;
    const Shape a = k % 2 ? Shape(Ellipse{ca, 0.6, 0.2, turn()}) : Shape(Rect{ca, {0.6, 0.2}, turn()});
    both.cases.push_back({a, {va, 0}, Circle{cb, 0.3}, {vb, 0}, 1e-12, false});
  }
  out.push_back(both);
  // Starting in contact: touching exactly (circles 2 apart, boxes face to face), closing or opening.
  ToiFamily start{"starting in contact", {}};
  for (const double v : {1.0, -1.0}) {
    start.cases.push_back({Circle{{0, 0}, 1}, {}, Circle{{2, 0}, 1}, {{-v, 0}, 0}, 1e-12, false});
    start.cases.push_back({Rect{{0, 0}, {1, 1}, 0}, {}, Rect{{0, 2}, {0.5, 1}, 0}, {{0, -v}, 0.5}, 1e-12, false});
  }
  out.push_back(start);
  return out;
}

// Every family against the reference: a contact it finds is hit (or stalled) at a time no later
// than its bracket, and no earlier than the bracket less 1e-9 where the approach is not grazing; no
// contact is a miss.
TEST(TimeOfImpact, MatchesTheReferenceOnEveryFamily) {
  for (const ToiFamily& f : toi_families()) {
    int hits = 0, misses = 0, most = 0;
    double earliest = 0;  // how far before the reference's bracket, at worst
    for (std::size_t k = 0; k < f.cases.size(); ++k) {
      const MovingCase& c = f.cases[k];
      const auto ref = reference_first_contact(c.a, c.ma, c.b, c.mb, f.samples);
      const TimeOfImpact got = time_of_impact(c.a, c.ma, c.b, c.mb, {c.tolerance, 100000});
      most = std::max(most, got.iterations);
      const std::string what = f.name + " case " + std::to_string(k);
      if (!ref) {
        EXPECT_EQ(got.status, ToiStatus::miss) << what << " t " << got.t;
        ++misses;
        continue;
      }
      ++hits;
      ASSERT_TRUE(got.status == ToiStatus::hit || got.status == ToiStatus::overlapping) << what;
      // Where the coordinates are large, the reference's poses (rounded doubles) resolve time only to
      // their ulps over the closing speed; FarFromTheOriginKeepsItsBound checks exact poses there.
      const double coordinates = center_of(c.a).cwiseAbs().maxCoeff() + center_of(c.b).cwiseAbs().maxCoeff() +
                                 c.ma.velocity.cwiseAbs().maxCoeff() + c.mb.velocity.cwiseAbs().maxCoeff();
      const double speed = (c.mb.velocity - c.ma.velocity).norm();
      const double resolution = speed > 0 ? 16 * kU * coordinates / speed : 0.0;
      EXPECT_LE(got.t, ref->touching + 1e-15 + resolution) << what;
      if (!c.grazing) EXPECT_GE(got.t, ref->apart - 1e-9 - resolution) << what;
      earliest = std::max(earliest, ref->apart - got.t);
    }
    std::printf("[toi] %-44s %2d hits %2d misses, worst %.1e before the reference's bracket, at most %d steps\n",
                f.name.c_str(), hits, misses, earliest, most);
  }
}

// Either order of a pair gives the same answer to the bit, turned round (the normal negated): Worlds
// that number the same bodies differently report the same impacts (partition.h).
TEST(TimeOfImpact, EitherOrderToTheBit) {
  int hits = 0;
  for (const ToiFamily& f : toi_families()) {
    for (const MovingCase& c : f.cases) {
      const TimeOfImpact ab = time_of_impact(c.a, c.ma, c.b, c.mb, {c.tolerance, 100000});
      const TimeOfImpact ba = time_of_impact(c.b, c.mb, c.a, c.ma, {c.tolerance, 100000});
      ASSERT_EQ(ab.status, ba.status) << f.name;
      EXPECT_EQ(ab.t, ba.t) << f.name;
      EXPECT_EQ(ab.normal, Vec2(-ba.normal)) << f.name;
      EXPECT_EQ(ab.point, ba.point) << f.name;
      EXPECT_EQ(ab.iterations, ba.iterations) << f.name;
      hits += ab.status == ToiStatus::hit ? 1 : 0;
    }
  }
  EXPECT_GT(hits, 50);
}

TEST(TimeOfImpact, BadMotionsNameTheField) {
  const Circle c{{0, 0}, 1};
  const auto message = [&](const Motion& ma, const Motion& mb, const ToiOptions& o = {}) {
    try {
      time_of_impact(c, ma, c, mb, o);
    } catch (const InvalidShape& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({{NAN, 0}, 0}, {}).find("A velocity x must be finite"), std::string::npos);
  EXPECT_NE(message({}, {{0, INFINITY}, 0}).find("B velocity y must be finite"), std::string::npos);
  EXPECT_NE(message({}, {{0, 0}, NAN}).find("B angular velocity must be finite"), std::string::npos);
  EXPECT_NE(message({{2e50, 0}, 0}, {}).find("A velocity x carries the centre beyond"), std::string::npos);
  EXPECT_NE(message({}, {}, {-1.0, 10}).find("tolerance must be finite and not negative"), std::string::npos);
}

}  // namespace
}  // namespace collide2d
