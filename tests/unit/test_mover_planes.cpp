// The mover's planes: solve_planes() and clip_vector() on constructions whose answers are exact in
// double (a floor, a wall, a corner, a soft plane at its limit), and on random sets of planes
// against independent references in long double: for planes that push without limit, the nearest
// point of the half-planes' intersection by enumeration of every candidate (the target, its
// projection on each line, each two lines' crossing); with limits, projected Gauss-Seidel run far
// past convergence. Also the narrow crease that sweeps alone do not settle, and the refusals.
#include <collide2d/mover.h>

#include <gtest/gtest.h>

#include "refusals.h"

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace collide2d {
namespace {

using testing::expect_refused;
using Real = long double;
struct RealVec {
  Real x, y;
};

constexpr double kInf = std::numeric_limits<double>::infinity();

CollisionPlane plane(double angle, double offset, double limit = kInf) {
  return {.normal = Vec2(std::cos(angle), std::sin(angle)), .offset = offset, .push_limit = limit};
}

Real dot(const CollisionPlane& p, const RealVec& d) {
  return static_cast<Real>(p.normal.x()) * d.x + static_cast<Real>(p.normal.y()) * d.y;
}

// The nearest point to t of {d : n.d >= offset for every plane}, by enumeration.
RealVec nearest_allowed(const Vec2& t, const std::vector<CollisionPlane>& planes) {
  const RealVec target{t.x(), t.y()};
  std::vector<RealVec> candidates{target};
  for (const CollisionPlane& p : planes) {
    const Real gap = static_cast<Real>(p.offset) - dot(p, target);
    candidates.push_back({target.x + gap * p.normal.x(), target.y + gap * p.normal.y()});
  }
  for (std::size_t i = 0; i < planes.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      const Real ax = planes[i].normal.x(), ay = planes[i].normal.y(), bx = planes[j].normal.x(),
                 by = planes[j].normal.y();
      const Real det = ax * by - ay * bx, oi = planes[i].offset, oj = planes[j].offset;
      if (std::abs(det) > 1e-14L) candidates.push_back({(oi * by - oj * ay) / det, (ax * oj - bx * oi) / det});
    }
  }
  RealVec best{0, 0};
  Real best_distance = std::numeric_limits<Real>::infinity();
  for (const RealVec& c : candidates) {
    bool allowed = true;
    for (const CollisionPlane& p : planes) allowed = allowed && dot(p, c) >= static_cast<Real>(p.offset) - 1e-15L;
    const Real dx = c.x - target.x, dy = c.y - target.y, distance = dx * dx + dy * dy;
    if (allowed && distance < best_distance) best = c, best_distance = distance;
  }
  return best;
}

// Projected Gauss-Seidel in long double, run to a standstill.
RealVec sweeps_to_standstill(const Vec2& t, const std::vector<CollisionPlane>& planes) {
  RealVec d{t.x(), t.y()};
  std::vector<Real> push(planes.size(), 0);
  for (int sweep = 0; sweep < 200000; ++sweep) {
    Real moved = 0;
    for (std::size_t i = 0; i < planes.size(); ++i) {
      const CollisionPlane& p = planes[i];
      const Real before = push[i];
      push[i] =
          std::clamp(before + (static_cast<Real>(p.offset) - dot(p, d)), Real(0), static_cast<Real>(p.push_limit));
      d.x += (push[i] - before) * p.normal.x(), d.y += (push[i] - before) * p.normal.y();
      moved += std::abs(push[i] - before);
    }
    if (moved == 0) break;
  }
  return d;
}

void expect_near(const Vec2& got, const RealVec& want, double within) {
  EXPECT_LE(std::abs(static_cast<Real>(got.x()) - want.x), within) << got.transpose();
  EXPECT_LE(std::abs(static_cast<Real>(got.y()) - want.y), within) << got.transpose();
}

TEST(SolvePlanes, FloorKeepsTheSlide) {
  CollisionPlane planes[] = {{.normal = Vec2(0, 1)}};
  const PlaneSolution s = solve_planes(Vec2(0.375, -0.25), planes);
  EXPECT_EQ(s.delta, Vec2(0.375, 0.0));
  EXPECT_EQ(planes[0].push, 0.25);
}

// The example of mover.h.
TEST(SolvePlanes, CornerBlocksBothWays) {
  CollisionPlane planes[] = {{.normal = Vec2(0, 1)}, {.normal = Vec2(-1, 0)}};
  EXPECT_EQ(solve_planes(Vec2(0.375, -0.25), planes).delta, Vec2(0, 0));
  EXPECT_EQ(planes[0].push, 0.25);
  EXPECT_EQ(planes[1].push, 0.375);
  EXPECT_EQ(clip_vector(Vec2(2.0, -1.0), planes), Vec2(0, 0));
  // Moving away from both, neither pushes.
  EXPECT_EQ(solve_planes(Vec2(-0.5, 0.5), planes).delta, Vec2(-0.5, 0.5));
  EXPECT_EQ(planes[0].push, 0.0);
  EXPECT_EQ(planes[1].push, 0.0);
}

TEST(SolvePlanes, BacksOutOfAPositiveOffset) {
  CollisionPlane planes[] = {{.normal = Vec2(0, 1), .offset = 0.125}};
  EXPECT_EQ(solve_planes(Vec2(0.5, 0.0), planes).delta, Vec2(0.5, 0.125));
}

TEST(SolvePlanes, SoftPlanePushesAtMostItsLimit) {
  CollisionPlane planes[] = {{.normal = Vec2(1, 0), .offset = 0.0, .push_limit = 0.125}};
  EXPECT_EQ(solve_planes(Vec2(-0.5, 0.25), planes).delta, Vec2(-0.375, 0.25));
  EXPECT_EQ(planes[0].push, 0.125);
}

TEST(SolvePlanes, NarrowCreaseIsExact) {
  // Two walls meeting at 1e-6 rad: the sweeps alone gain a factor of about 1 - 1e-12 per sweep.
  for (const double angle : {1e-3, 1e-6, 1e-7}) {
    std::vector<CollisionPlane> planes = {plane(M_PI / 2 - angle, -0.25), plane(M_PI / 2 + angle, -0.25)};
    const Vec2 target(0.0, -1.0);
    const RealVec want = nearest_allowed(target, planes);
    const PlaneSolution s = solve_planes(target, planes);
    expect_near(s.delta, want, 1e-15 / angle);
    for (const CollisionPlane& p : planes) EXPECT_GE(p.normal.dot(s.delta) - p.offset, -1e-15) << angle;
  }
}

TEST(SolvePlanes, RandomRigidPlanesMatchEnumeration) {
  std::mt19937_64 random(54321);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), offset(-1.0, 0.0), coordinate(-2.0, 2.0);
  double worst = 0.0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::vector<CollisionPlane> planes;
    const int count = 1 + trial % 6;
    for (int i = 0; i < count; ++i) planes.push_back(plane(angle(random), offset(random)));
    const Vec2 target(coordinate(random), coordinate(random));
    const RealVec want = nearest_allowed(target, planes);
    const PlaneSolution s = solve_planes(target, planes);
    const double error = static_cast<double>(
        std::max(std::abs(static_cast<Real>(s.delta.x()) - want.x), std::abs(static_cast<Real>(s.delta.y()) - want.y)));
    worst = std::max(worst, error);
    ASSERT_LE(error, 1e-12) << "trial " << trial;
  }
  RecordProperty("worst_error", (::testing::Message() << worst).GetString());
}

TEST(SolvePlanes, RandomSoftPlanesMatchLongSweeps) {
  std::mt19937_64 random(12345);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), offset(-0.5, 0.5), coordinate(-2.0, 2.0), limit(0.0, 1.0);
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<CollisionPlane> planes;
    const int count = 1 + trial % 3;
    // Normals at least 0.3 rad apart, so that the long sweeps settle.
    const double first = angle(random);
    for (int i = 0; i < count; ++i)
      planes.push_back(plane(first + i * (0.3 + 1.5 * std::abs(offset(random))), offset(random), limit(random)));
    const Vec2 target(coordinate(random), coordinate(random));
    const RealVec want = sweeps_to_standstill(target, planes);
    const PlaneSolution s = solve_planes(target, planes);
    expect_near(s.delta, want, 1e-12);
    for (const CollisionPlane& p : planes) {
      EXPECT_GE(p.push, 0.0);
      EXPECT_LE(p.push, p.push_limit);
    }
  }
}

TEST(ClipVector, RemovesOnlyTheBlockedComponent) {
  CollisionPlane floor{.normal = Vec2(0, 1), .push = 0.25};
  CollisionPlane wall{.normal = Vec2(-1, 0), .push = 0.5};
  const CollisionPlane both[] = {floor, wall};
  EXPECT_EQ(clip_vector(Vec2(2.0, -1.0), std::span(both, 1)), Vec2(2.0, 0.0));
  EXPECT_EQ(clip_vector(Vec2(2.0, -1.0), both), Vec2(0.0, 0.0));
  EXPECT_EQ(clip_vector(Vec2(-2.0, 1.0), both), Vec2(-2.0, 1.0));
  // A plane that pushed nothing, or that does not clip, leaves the velocity.
  wall.push = 0.0;
  floor.clip_velocity = false;
  const CollisionPlane neither[] = {floor, wall};
  EXPECT_EQ(clip_vector(Vec2(2.0, -1.0), neither), Vec2(2.0, -1.0));
}

TEST(ClipVector, CreaseIsNotClippedIntoTheFirstPlane) {
  // Two floors of a V at 120 degrees: clipping by one and then the other would leave a velocity
  // into the first; the nearest velocity into neither is zero for one straight down.
  const CollisionPlane v[] = {{.normal = Vec2(std::sin(M_PI / 3), 0.5), .push = 1.0},
                              {.normal = Vec2(-std::sin(M_PI / 3), 0.5), .push = 1.0}};
  const Vec2 clipped = clip_vector(Vec2(0.25, -1.0), v);
  EXPECT_LE(clipped.norm(), 1e-15);
  std::vector<CollisionPlane> planes(std::begin(v), std::end(v));
  for (CollisionPlane& p : planes) p.offset = 0.0;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
  for (int trial = 0; trial < 1000; ++trial) {
    const Vec2 velocity(coordinate(random), coordinate(random));
    expect_near(clip_vector(velocity, v), nearest_allowed(velocity, planes), 1e-14);
  }
}

TEST(SolvePlanes, RefusesBadInput) {
  CollisionPlane good{.normal = Vec2(0, 1)};
  const auto refused = [&](CollisionPlane p, Vec2 target, const std::string& words) {
    CollisionPlane planes[] = {good, p};
    expect_refused<std::invalid_argument>([&] { solve_planes(target, planes); }, words);
    EXPECT_EQ(planes[0].push, 0.0) << "a refused call writes nothing";
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  refused(good, Vec2(nan, 0), "target delta x must be finite (got nan)");
  refused({.normal = Vec2(0, 2)}, Vec2(0, 0), "plane 1 normal must be of unit length (got length 2)");
  refused({.normal = Vec2(1, 0), .offset = kInf}, Vec2(0, 0), "plane 1 offset must be finite (got inf)");
  refused({.normal = Vec2(1, 0), .push_limit = -1.0}, Vec2(0, 0), "plane 1 push limit must not be negative (got -1)");
  refused({.normal = Vec2(1, 0), .push_limit = nan}, Vec2(0, 0), "plane 1 push limit must not be negative (got nan)");
  const CollisionPlane planes[] = {good};
  expect_refused<std::invalid_argument>([&] { clip_vector(Vec2(0, kInf), planes); },
                                        "vector y must be finite (got inf)");
}

}  // namespace
}  // namespace collide2d
