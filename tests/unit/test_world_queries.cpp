// The World's queries (shapes, boxes, points, rays, casts) against brute force and the 50-digit
// reference, their callback forms, and the World held still while they run.
#include <collide2d/ray_cast.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>
#include "tools/random.h"
#include "world_testing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace collide2d {
namespace {

using namespace testing;
TEST(World, QueriesMatchBruteForce) {
  Rng rng(8);
  const World world = random_world(rng, 300);
  for (int k = 0; k < 100; ++k) {
    const Shape probe = random_shape(rng, 10.0);
    const Vec2 point = uniform_point(rng, 0, 10);
    const double d = uniform(rng, 0.0, 1.0);
    // Every third box has no width, no height, or neither (a segment or a point).
    const double w = k % 3 == 0 && k % 2 == 0 ? 0.0 : uniform(rng, 0, 2);
    const double h = k % 3 == 0 && k % 4 != 0 ? 0.0 : uniform(rng, 0, 2);
    const Aabb box{point, point + Vec2(w, h)};
    const Rect box_shape{point + Vec2(w / 2, h / 2), Vec2(w / 2, h / 2), 0.0};
    std::vector<BodyId> hit, near_point, near_shape, in_box;
    for (const BodyId id : world.bodies()) {
      const Shape& s = world.shape(id);
      if (overlaps(probe, s)) hit.push_back(id);
      if (static_cast<double>(reference::distance_to(s, reference::to_mp(point))) <= d) near_point.push_back(id);
      if (distance(probe, s).distance <= d) near_shape.push_back(id);
      if (reference::overlap(s, box_shape)) in_box.push_back(id);  // the shape itself, not its box
    }
    ASSERT_EQ(world.overlapping(probe), hit) << k;
    ASSERT_EQ(world.within(point, d), near_point) << k;
    ASSERT_EQ(world.within(probe, d), near_shape) << k;
    ASSERT_EQ(world.overlapping(box), in_box) << k;
  }
}

// The first query builds the moving shapes' tree: queries from several threads at once on a World
// moved since its update (some shapes out of their fat boxes) each find what brute force finds,
// and so do queries after the next update, which keeps the tree.
TEST(World, FirstQueriesFromSeveralThreadsAgree) {
  Rng rng(12);
  World world = random_world(rng, 400);
  world.update();
  for (const BodyId id : world.bodies()) {
    if (uniform(rng, 0, 1) < 0.5) world.move_by(id, uniform_point(rng, -1, 1), uniform(rng, -1, 1));
  }
  std::vector<Shape> probes;
  for (int k = 0; k < 40; ++k) probes.push_back(random_shape(rng, 10.0));
  const auto brute_force = [&world](const Shape& probe) {
    std::vector<BodyId> hit;
    for (const BodyId id : world.bodies()) {
      if (overlaps(probe, world.shape(id))) hit.push_back(id);
    }
    return hit;
  };
  for (int round = 0; round < 2; ++round) {
    std::vector<std::vector<BodyId>> expected;
    for (const Shape& probe : probes) expected.push_back(brute_force(probe));
    std::atomic<bool> go{false};
    std::vector<std::vector<std::vector<BodyId>>> found(4);
    std::vector<std::thread> threads;
    for (auto& mine : found) {
      threads.emplace_back([&] {
        while (!go.load()) std::this_thread::yield();
        for (const Shape& probe : probes) mine.push_back(world.overlapping(probe));
      });
    }
    go = true;
    for (std::thread& t : threads) t.join();
    for (std::size_t t = 0; t < found.size(); ++t)
      EXPECT_EQ(found[t], expected) << "round " << round << ", thread " << t;
    for (const BodyId id : world.bodies()) world.move_by(id, uniform_point(rng, -0.5, 0.5), 0.1);
    world.update();
  }
}

// The first hit lies on the body's boundary (50-digit distance to the solid 0, to a point just
// before it positive), and no body contains a point of the ray before it, among the bodies that do
// not contain the origin (skipped by default) or among all of them (from_inside: those are hit at 0).
TEST(World, RayCastFindsTheFirstExactHit) {
  Rng rng(9);
  const World world = random_world(rng, 150);
  int hits = 0, inside = 0;
  for (int k = 0; k < 600; ++k) {
    const Vec2 origin = uniform_point(rng, -2, 12);
    const double angle = uniform(rng, 0, 6.3);
    const Vec2 dir(std::cos(angle), std::sin(angle));
    const RayOptions options{.from_inside = k % 2 == 1};
    const auto hit = world.ray_cast(origin, 3.0 * dir, 20.0, {}, options);
    double first = 20.0;
    for (const BodyId id : world.bodies()) {
      if (!options.from_inside && contains(world.shape(id), origin)) continue;
      for (int i = 0; i <= 4000; ++i) {
        const double t = 20.0 * i / 4000;
        if (contains(world.shape(id), origin + t * dir)) {
          first = std::min(first, t);
          break;
        }
      }
    }
    if (!hit) {
      EXPECT_EQ(first, 20.0) << k;
      continue;
    }
    ++hits;
    EXPECT_LE(hit->distance, first + 1e-12) << k;
    EXPECT_GE(hit->distance, first - 20.0 / 4000) << k;
    const double off =
        static_cast<double>(reference::distance_to(world.shape(hit->body), reference::to_mp(hit->point)));
    EXPECT_LE(off, 1e-12) << k;
    if (hit->distance > 0) {
      const Vec2 before = hit->point - 1e-9 * dir;
      EXPECT_GT(static_cast<double>(reference::distance_to(world.shape(hit->body), reference::to_mp(before))), 0) << k;
      EXPECT_NEAR(hit->normal.norm(), 1.0, 1e-12);
      EXPECT_LT(hit->normal.dot(dir), 0.0) << k;
    } else {
      EXPECT_TRUE(options.from_inside) << k;
      EXPECT_TRUE(contains(world.shape(hit->body), origin)) << k;
      EXPECT_EQ(hit->normal, Vec2::Zero()) << k;
      ++inside;
    }
  }
  EXPECT_GT(hits, 100);
  EXPECT_GT(inside, 20);
}

// The ray kernel on needles (an axis 1e-20 to 1e-4 of the other) and on round ellipses, from near
// and from far, against the quadratic solved in 50 digits (axis-aligned, so the frame is exact): the
// same verdict, and the entering distance within 1e-12 of the ray's reach. In double, the textbook
// discriminant B^2 - A C cancels to noise for a needle seen from afar and gave hits beyond its ends.
TEST(RayCast, NeedlesAndRoundEllipsesMatchTheQuadraticIn50Digits) {
  using reference::Real;
  Rng rng(41);
  int hits = 0, misses = 0;
  for (int k = 0; k < 4000; ++k) {
    const double thin = std::pow(10.0, -uniform(rng, 0, 20));
    const double a = k % 4 == 0 ? uniform(rng, 0.5, 4) : thin, b = uniform(rng, 0.5, 4);
    const Ellipse e{uniform_point(rng, -2, 2), a, b, 0.0};
    const double far = k % 2 == 0 ? 10.0 : 1e4;
    const Vec2 origin = uniform_point(rng, -far, far);
    // Aimed near the needle: at a point of its long axis, or just past its end.
    const Vec2 aim = e.center + Vec2(0.0, uniform(rng, -1.3, 1.3) * b);
    const Vec2 unit = (aim - origin).normalized();
    const double reach = 3 * far;
    const auto got = ray_cast(Shape(e), origin, unit, reach);
    const Real ox = Real(origin.x()) - e.center.x(), oy = Real(origin.y()) - e.center.y();
    const Real dx = unit.x(), dy = unit.y(), a2 = Real(a) * a, b2 = Real(b) * b;
    const Real qa = b2 * dx * dx + a2 * dy * dy, qb = b2 * ox * dx + a2 * oy * dy,
               qc = b2 * ox * ox + a2 * oy * oy - a2 * b2;
    const Real disc = qb * qb - qa * qc;
    if (qc <= 0) continue;  // the origin inside: a hit at 0, not this test's case
    const bool hit = qb < 0 && disc >= 0 && (-qb - sqrt(disc)) / qa <= reach;
    ASSERT_EQ(got.has_value(), hit) << k << ": a " << a << " b " << b << " from " << origin.transpose();
    if (!hit) {
      ++misses;
      continue;
    }
    ++hits;
    EXPECT_NEAR(got->distance, static_cast<double>((-qb - sqrt(disc)) / qa), 1e-12 * reach) << k;
  }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(misses, 500);
}

// A shape far smaller than its distance from the origin: the hit point o + t d rounds to the centre
// itself, so the normal has to come from elsewhere. Aimed along an axis at a circle or an axis-aligned
// ellipse, the answer is exact: the normal is -d. Aimed at a shape of any size and turn from any
// distance, a hit beyond the origin has a unit normal facing the ray, since a zero normal means the ray
// starts inside (the World's skip rule reads it).
TEST(RayCast, TinyShapesFarAwayHaveAUnitNormal) {
  const Vec2 axes[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  for (const double size : {1e-50, 1e-30, 1e-12, 1.0}) {
    for (const Vec2& d : axes) {
      for (const Shape& s : {Shape(Circle{{0, 0}, size}), Shape(Ellipse{{0, 0}, size, 3 * size, 0.0})}) {
        const auto hit = ray_cast(s, Vec2(-5e3 * d), d, 1e4);
        ASSERT_TRUE(hit.has_value()) << size;
        EXPECT_EQ(hit->normal, Vec2(-d)) << size << ' ' << d.transpose();
      }
    }
  }
  Rng rng(43);
  int hits = 0;
  for (int k = 0; k < 20000; ++k) {
    const double size = std::pow(10.0, -uniform(rng, 0, 50));
    const double angle = uniform(rng, -3.2, 3.2);
    const Vec2 c = uniform_point(rng, -2, 2);
    const Shape shapes[] = {Circle{c, size}, Ellipse{c, size, size * uniform(rng, 0.01, 100), angle},
                            Rect{c, Vec2(size, size * uniform(rng, 0.01, 100)), angle}};
    const Shape& s = shapes[k % 3];
    const Vec2 direction = uniform_point(rng, -1, 1);
    const Vec2 origin = c + std::pow(10.0, uniform(rng, 0, 8)) * direction;
    const Vec2 unit = Vec2(c - origin).normalized();
    const auto hit = ray_cast(s, origin, unit, 1e9);
    if (!hit || contains(s, origin)) continue;
    ++hits;
    EXPECT_NEAR(hit->normal.norm(), 1.0, 1e-15) << k;
    EXPECT_LE(hit->normal.dot(unit), 1e-12) << k;
  }
  EXPECT_GT(hits, 5000);
}

// cast() against brute force: the least fraction of every body's shape cast, the same body.
TEST(World, CastFindsTheFirstBody) {
  Rng rng(22);
  const World world = random_world(rng, 200);
  int hits = 0;
  int skipped = 0;
  for (int k = 0; k < 400; ++k) {
    const Shape probe = random_shape(rng, 10.0);
    const Vec2 translation = uniform_point(rng, -4, 4);
    const CastOptions options{.skip_initial_overlap = k % 2 == 1};
    std::optional<BodyCastHit> best;
    for (const BodyId id : world.bodies()) {
      if (options.skip_initial_overlap && overlaps(probe, world.shape(id))) {
        ++skipped;
        continue;
      }
      const auto hit = shape_cast(probe, translation, world.shape(id));
      if (hit && (!best || hit->fraction < best->fraction))
        best = BodyCastHit{id, world.shapes(id)[0], hit->fraction, hit->point, hit->normal};
    }
    const auto got = world.cast(probe, translation, {}, options);
    ASSERT_EQ(got.has_value(), best.has_value()) << k;
    if (!got) continue;
    ++hits;
    EXPECT_EQ(got->body, best->body) << k;
    EXPECT_EQ(got->fraction, best->fraction) << k;
  }
  EXPECT_GT(hits, 100);
  EXPECT_GT(skipped, 50);
  EXPECT_THROW(world.cast(Circle{{0, 0}, 1}, Vec2(NAN, 0)), std::invalid_argument);
  EXPECT_THROW(world.cast(Circle{{0, 0}, -1}, Vec2(1, 0)), InvalidShape);
}

// A ray from inside a ball skips it and hits the wall beyond (Box2D v3's rule); from_inside hits the
// ball at 0 with a zero normal. A box resting on the floor and cast towards a wall hits the floor
// at fraction 0; skip_initial_overlap finds the wall, at the fraction where the gap closes.
TEST(World, RaysSkipTheBodiesTheyStartIn) {
  World world;
  const BodyId ball = world.add(Circle{{0, 0}, 1});
  const BodyId wall = world.add(Rect{{5, 0}, {0.5, 3}, 0});
  const BodyId floor = world.add(Rect{{0, -2}, {10, 1}, 0});
  const auto first = world.ray_cast({0.25, 0}, {1, 0}, 10);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->body, wall);
  EXPECT_EQ(first->distance, 4.25);
  EXPECT_EQ(first->normal, Vec2(-1, 0));
  const auto inside = world.ray_cast({0.25, 0}, {1, 0}, 10, {}, {.from_inside = true});
  ASSERT_TRUE(inside);
  EXPECT_EQ(inside->body, ball);
  EXPECT_EQ(inside->distance, 0.0);
  EXPECT_EQ(inside->normal, Vec2::Zero());
  EXPECT_EQ(world.ray_cast_all({0.25, 0}, {1, 0}, 10).size(), 1u);
  EXPECT_EQ(world.ray_cast_all({0.25, 0}, {1, 0}, 10, {}, {.from_inside = true}).size(), 2u);

  const Shape crate = Rect{{2.5, -0.5}, {0.5, 0.5}, 0};  // on the floor, its right face 1.5 from the wall
  const auto stuck = world.cast(crate, {7, 0});
  ASSERT_TRUE(stuck);
  EXPECT_EQ(stuck->body, floor);
  EXPECT_EQ(stuck->fraction, 0.0);
  const auto slides = world.cast(crate, {7, 0}, {}, {.skip_initial_overlap = true});
  ASSERT_TRUE(slides);
  EXPECT_EQ(slides->body, wall);
  EXPECT_LE(slides->fraction, 1.5 / 7);
  EXPECT_GT(slides->fraction, 1.5 / 7 - 1e-9);
}

// The callback forms find what the vector forms find, and stop when told: a visit that returns
// false, or a ray's or a cast's that returns 0, is the last. A ray's visit that returns the hit's
// distance keeps only nearer hits, and ends on the first one.
TEST(World, CallbackQueriesStopWhenTold) {
  Rng rng(31);
  const World world = random_world(rng, 300);
  int stopped = 0;
  for (int k = 0; k < 100; ++k) {
    const Shape probe = random_shape(rng, 10.0);
    const Vec2 origin = uniform_point(rng, -1, 11);
    const Vec2 direction = uniform_point(rng, -1, 1);
    std::vector<BodyId> seen;
    world.within(probe, 0.5, [&seen](const BodyShape& found) {
      seen.push_back(found.body);
      return true;
    });
    std::sort(seen.begin(), seen.end());
    ASSERT_EQ(seen, world.within(probe, 0.5)) << k;
    int calls = 0;
    world.within(probe, 0.5, [&calls](const BodyShape&) { return ++calls < 2; });
    EXPECT_EQ(calls, std::min<int>(2, static_cast<int>(seen.size()))) << k;
    stopped += seen.size() > 2;

    const std::vector<RayHit> all = world.ray_cast_all(origin, direction, 20.0);
    calls = 0;
    world.ray_cast(origin, direction, 20.0, [&calls](const RayHit&) { return ++calls, 0.0; });
    EXPECT_EQ(calls, all.empty() ? 0 : 1) << k;
    std::optional<RayHit> nearest;
    world.ray_cast(origin, direction, 20.0, [&nearest](const RayHit& hit) {
      if (nearest) EXPECT_LE(hit.distance, nearest->distance);
      nearest = hit;
      return hit.distance;
    });
    ASSERT_EQ(nearest.has_value(), !all.empty()) << k;
    if (nearest) EXPECT_EQ(nearest->distance, all.front().distance) << k;

    calls = 0;
    world.cast(probe, direction, [&calls](const BodyCastHit&) { return ++calls, 0.0; });
    EXPECT_EQ(calls, world.cast(probe, direction) ? 1 : 0) << k;
  }
  EXPECT_GT(stopped, 20);
}

// Changing the World from inside a query's callback throws std::logic_error and changes nothing;
// once the query is over (ended by the callback's own exception too), changes go through.
TEST(World, ChangesFromInsideACallbackAreRefused) {
  World world;
  const BodyId a = world.add(Circle{{0, 0}, 1});
  const BodyId b = world.add(Circle{{1, 0}, 1});
  std::vector<std::string> refusals;
  const auto refused = [&refusals](auto change) {
    try {
      change();
    } catch (const std::logic_error& e) {
      refusals.push_back(e.what());
    }
  };
  world.overlapping(Circle{{0.5, 0}, 0.1}, [&](const BodyShape& found) {
    const BodyId id = found.body;
    refused([&] { world.remove(id); });
    refused([&] { world.add(Circle{{5, 5}, 1}); });
    refused([&] { world.move_by(id, {1, 0}); });
    refused([&] { world.set_filter(id, {.category = 2}); });
    refused([&] { world.update(); });
    return true;
  });
  world.ray_cast({-5, 0}, {1, 0}, 10, [&](const RayHit& hit) {
    refused([&] { world.set_pose(hit.body, {9, 9}, 0); });
    return -1.0;
  });
  ASSERT_EQ(refusals.size(), 2 * 5 + 2u);
  EXPECT_EQ(refusals[0],
            "remove called from inside a query's callback: the World cannot change while a query walks it");
  EXPECT_EQ(world.size(), 2u);
  EXPECT_EQ(world.pose(a).position, Vec2(0, 0));
  EXPECT_EQ(world.filter(b).category, 1u);
  EXPECT_THROW(
      world.overlapping(Aabb{{-1, -1}, {1, 1}}, [](const BodyShape&) -> bool { throw std::runtime_error("game"); }),
      std::runtime_error);
  world.remove(b);
  world.update();
  EXPECT_EQ(world.size(), 1u);
}

}  // namespace
}  // namespace collide2d
