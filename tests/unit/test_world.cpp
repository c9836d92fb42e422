// The World against an all-pairs narrow phase over many frames, its queries against brute force,
// and its refusal of bad input.
#include <collide2d/ray_cast.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>
#include "engine/thread_pool.h"
#include "mp_reference.h"
#include "world_reference.h"
#include "world_testing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <optional>
#include <random>

namespace collide2d {
namespace {

using Rng = std::mt19937_64;

}  // namespace

// gtest prints handles as index:generation.
void PrintTo(const BodyId& id, std::ostream* os) { *os << id.index << ':' << id.generation; }

namespace {

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

Shape random_shape(Rng& rng, double spread) {
  const Vec2 c(uniform(rng, 0, spread), uniform(rng, 0, spread));
  const double size = uniform(rng, 0.1, 1.0);
  switch (static_cast<int>(uniform(rng, 0, 3))) {
    case 0:
      return Circle{c, size};
    case 1:
      return Ellipse{c, size, size * uniform(rng, 0.05, 1.0), uniform(rng, 0, 6.3)};
    default:
      return Rect{c, Vec2(size, size * uniform(rng, 0.1, 1.0)), uniform(rng, 0, 6.3)};
  }
}

// The World's pairs against a scan of every pair (reference::all_pairs); the proximity pairs' distances
// are the narrow phase's (expect_sample_matches_reference checks that narrow phase itself).
void expect_matches_all_pairs(const World& world, double margin, const std::string& what) {
  const reference::AllPairs expected = reference::all_pairs(world, margin);
  ASSERT_EQ(world.overlapping(), expected.overlapping) << what;
  ASSERT_EQ(world.sensing(), expected.sensing) << what;
  std::vector<ShapePair> reported;
  for (const Proximity& p : world.proximity()) {
    reported.push_back({p.a, p.b, p.shape_a, p.shape_b});
    ASSERT_EQ(p.result.distance, distance(world.shape(p.shape_a), world.shape(p.shape_b)).distance);
  }
  ASSERT_EQ(reported, expected.near) << what;
}

using testing::expect_changes;

// The pair of two bodies of one shape each.
ShapePair solo_pair(const World& world, BodyId x, BodyId y) { return {x, y, world.shapes(x)[0], world.shapes(y)[0]}; }

bool has(const std::vector<ShapePair>& sorted, const ShapePair& p) {
  return std::binary_search(sorted.begin(), sorted.end(), p);
}

// Independently of the World's own aabb() and overlaps(): the pairs whose exact boxes (50 digits,
// rounded outward), grown by margin / 2, meet must include every overlapping and proximity pair;
// and a sample of them, half from the World's overlapping pairs, is checked against the 50-digit
// reference: the verdict, and with a margin, the distance and membership of the proximity list.
void expect_sample_matches_reference(const World& world, double margin, Rng& rng, const std::string& what) {
  const std::vector<ShapePair> near = reference::exact_box_pairs(world, margin / 2);
  for (const ShapePair& p : world.overlapping()) ASSERT_TRUE(has(near, p)) << what << ": exact boxes apart";
  for (const Proximity& p : world.proximity())
    ASSERT_TRUE(has(near, {p.a, p.b, p.shape_a, p.shape_b})) << what << ": exact boxes apart";
  const auto pick = [&rng](const std::vector<ShapePair>& from) {
    return from[std::uniform_int_distribution<std::size_t>(0, from.size() - 1)(rng)];
  };
  for (int k = 0; k < 12; ++k) {
    const ShapePair p = k % 2 == 0 && !world.overlapping().empty() ? pick(world.overlapping()) : pick(near);
    const Shape& a = world.shape(p.shape_a);
    const Shape& b = world.shape(p.shape_b);
    ASSERT_EQ(has(world.overlapping(), p), reference::overlap(a, b)) << what << ": " << p.a.index << "-" << p.b.index;
    if (margin == 0 || has(world.overlapping(), p)) continue;
    const double d = static_cast<double>(reference::distance(a, b));
    const auto reported = std::find_if(world.proximity().begin(), world.proximity().end(), [&p](const Proximity& q) {
      return q.shape_a == p.shape_a && q.shape_b == p.shape_b;
    });
    // Within rounding of the margin either answer is right.
    const double scale = 20.0, tolerance = 8 * std::numeric_limits<double>::epsilon() * scale;
    if (std::abs(d - margin) > tolerance) ASSERT_EQ(reported != world.proximity().end(), d <= margin) << what;
    if (reported != world.proximity().end()) ASSERT_NEAR(reported->result.distance, d, tolerance) << what;
  }
}

TEST(World, PairsMatchAllPairsNarrowPhaseOverFrames) {
  for (const double margin : {0.0, 0.3}) {
    Rng rng(7);
    World world({.fat_margin = 0.05, .proximity_margin = margin});
    std::vector<Vec2> velocity(400);
    for (int k = 0; k < 250; ++k) world.add(random_shape(rng, 15.0), {.user_id = static_cast<std::uint64_t>(k)});
    std::vector<ShapePair> previous;
    for (int frame = 0; frame < 40; ++frame) {
      for (const BodyId id : world.bodies()) {
        if (id.index >= velocity.size()) velocity.resize(id.index + 1);
        if (frame == 0) velocity[id.index] = Vec2(uniform(rng, -0.1, 0.1), uniform(rng, -0.1, 0.1));
        world.move_by(id, velocity[id.index], 0.02);
      }
      if (frame % 10 == 5) {  // churn
        const auto ids = world.bodies();
        for (std::size_t k = 0; k < ids.size(); k += 17) world.remove(ids[k]);
        for (int k = 0; k < 10; ++k) world.add(random_shape(rng, 15.0));
      }
      world.update();
      expect_matches_all_pairs(world, margin, "frame " + std::to_string(frame));
      if (HasFatalFailure()) return;
      expect_sample_matches_reference(world, margin, rng, "frame " + std::to_string(frame));
      if (HasFatalFailure()) return;
      expect_changes(previous, world.overlapping(), world.began(), world.ended(), "frame " + std::to_string(frame));
      if (HasFatalFailure()) return;
      previous = world.overlapping();
    }
    EXPECT_GT(world.overlapping().size(), 0u);
    if (margin > 0) EXPECT_GT(world.proximity().size(), 0u);
  }
}

World random_world(Rng& rng, int n) {
  World world;
  for (int k = 0; k < n; ++k) world.add(random_shape(rng, 10.0));
  return world;
}

TEST(World, QueriesMatchBruteForce) {
  Rng rng(8);
  const World world = random_world(rng, 300);
  for (int k = 0; k < 100; ++k) {
    const Shape probe = random_shape(rng, 10.0);
    const Vec2 point(uniform(rng, 0, 10), uniform(rng, 0, 10));
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

// The first hit lies on the body's boundary (50-digit distance to the solid 0, to a point just
// before it positive), and no body contains a point of the ray before it, among the bodies that do
// not contain the origin (skipped by default) or among all of them (from_inside: those are hit at 0).
TEST(World, RayCastFindsTheFirstExactHit) {
  Rng rng(9);
  const World world = random_world(rng, 150);
  int hits = 0, inside = 0;
  for (int k = 0; k < 600; ++k) {
    const Vec2 origin(uniform(rng, -2, 12), uniform(rng, -2, 12));
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
    const Ellipse e{Vec2(uniform(rng, -2, 2), uniform(rng, -2, 2)), a, b, 0.0};
    const double far = k % 2 == 0 ? 10.0 : 1e4;
    const Vec2 origin(uniform(rng, -far, far), uniform(rng, -far, far));
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
    const Vec2 c(uniform(rng, -2, 2), uniform(rng, -2, 2));
    const Shape shapes[] = {Circle{c, size}, Ellipse{c, size, size * uniform(rng, 0.01, 100), angle},
                            Rect{c, Vec2(size, size * uniform(rng, 0.01, 100)), angle}};
    const Shape& s = shapes[k % 3];
    const Vec2 origin = c + std::pow(10.0, uniform(rng, 0, 8)) * Vec2(uniform(rng, -1, 1), uniform(rng, -1, 1));
    const Vec2 unit = Vec2(c - origin).normalized();
    const auto hit = ray_cast(s, origin, unit, 1e9);
    if (!hit || contains(s, origin)) continue;
    ++hits;
    EXPECT_NEAR(hit->normal.norm(), 1.0, 1e-15) << k;
    EXPECT_LE(hit->normal.dot(unit), 1e-12) << k;
  }
  EXPECT_GT(hits, 5000);
}
// Contacts: off by default and then empty; on, exactly the overlapping pairs (and, with a
// speculative margin, the pairs whose contact separation is within it), each the contact the
// narrow phase gives for the pair, in the order of overlapping(), over frames of motion.
TEST(World, ContactsMatchAllPairsWhenAskedFor) {
  int circle_ellipse = 0;
  for (const double margin : {0.0, 0.2}) {
    Rng rng(11);
    World world({.fat_margin = 0.05, .contacts = true, .speculative_margin = margin});
    World plain({.fat_margin = 0.05});
    for (int k = 0; k < 200; ++k) {
      const Shape s = random_shape(rng, 12.0);
      world.add(s);
      plain.add(s);
    }
    for (int frame = 0; frame < 20; ++frame) {
      for (const BodyId id : world.bodies()) {
        const Vec2 shift(uniform(rng, -0.1, 0.1), uniform(rng, -0.1, 0.1));
        world.move_by(id, shift, 0.03);
        plain.move_by(id, shift, 0.03);
      }
      world.update();
      plain.update();
      EXPECT_TRUE(plain.contacts().empty());
      EXPECT_EQ(plain.last_frame().contacts, 0u);
      const std::vector<BodyId> ids = world.bodies();
      std::vector<BodyContact> expected;
      for (std::size_t i = 0; i < ids.size(); ++i) {
        for (std::size_t j = i + 1; j < ids.size(); ++j) {
          const Shape& a = world.shape(ids[i]);
          const Shape& b = world.shape(ids[j]);
          const Contact c = contact(a, b, {.margin = margin});
          const bool touching = overlaps(a, b);
          if (touching || (margin > 0 && c.separation <= margin)) {
            expected.push_back({ids[i], ids[j], world.shapes(ids[i])[0], world.shapes(ids[j])[0], world.user_id(ids[i]),
                                world.user_id(ids[j]), world.user_id(ids[i]), world.user_id(ids[j]), touching, c});
          }
        }
      }
      ASSERT_EQ(world.contacts().size(), expected.size()) << "frame " << frame;
      for (std::size_t k = 0; k < expected.size(); ++k) {
        const BodyContact& got = world.contacts()[k];
        ASSERT_EQ(BodyPair(got.a, got.b), BodyPair(expected[k].a, expected[k].b)) << "frame " << frame;
        // A speculative contact says so, from the exact verdict; the record carries both user ids.
        ASSERT_EQ(got.touching, expected[k].touching) << "frame " << frame;
        ASSERT_EQ(got.user_a, expected[k].user_a);
        ASSERT_EQ(got.user_b, expected[k].user_b);
        ASSERT_EQ(got.contact.separation, expected[k].contact.separation);
        ASSERT_EQ(got.contact.normal, expected[k].contact.normal);
        ASSERT_EQ(got.contact.point_a, expected[k].contact.point_a);
        ASSERT_EQ(got.contact.point_b, expected[k].contact.point_b);
        ASSERT_EQ(got.contact.manifold_size, expected[k].contact.manifold_size);
        // The pairs of a circle and an ellipse, in either order, are counted: the family is there.
        const Shape& a = world.shape(got.a);
        const Shape& b = world.shape(got.b);
        circle_ellipse += (std::holds_alternative<Circle>(a) && std::holds_alternative<Ellipse>(b)) ||
                          (std::holds_alternative<Ellipse>(a) && std::holds_alternative<Circle>(b));
      }
      EXPECT_EQ(world.last_frame().contacts, expected.size());
      EXPECT_EQ(plain.overlapping(), world.overlapping());
    }
    EXPECT_GT(world.contacts().size(), world.overlapping().size() * (margin > 0 ? 1 : 0));
  }
  EXPECT_GT(circle_ellipse, 100);
  std::printf("[measure] world contacts: %d circle-ellipse contacts checked\n", circle_ellipse);
}

TEST(World, BadInputIsRefusedAndChangesNothing) {
  World world({.proximity_margin = 0.5});
  const BodyId a = world.add(Circle{Vec2(0, 0), 1}, {.user_id = 1});
  const BodyId b = world.add(Ellipse{Vec2(1.5, 0), 1, 0.5, 0}, {.user_id = 2});
  world.update();
  const auto pairs = world.overlapping();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(world.add(Ellipse{Vec2(0, 0), -1, 1, 0}), InvalidShape);
  EXPECT_THROW(world.set_pose(a, Vec2(nan, 0), 0), std::invalid_argument);
  EXPECT_THROW(world.set_pose(b, Vec2(0, 0), INFINITY), std::invalid_argument);
  EXPECT_THROW(world.set_pose(BodyId{42, 1}, Vec2(0, 0), 0), std::out_of_range);
  EXPECT_THROW(world.move_by(BodyId{42, 1}, Vec2(0, 0)), std::out_of_range);
  EXPECT_THROW(world.remove(BodyId{42, 1}), std::out_of_range);
  EXPECT_THROW(world.shape(BodyId{}), std::out_of_range);
  EXPECT_THROW(world.set_proximity_margin(-1), std::invalid_argument);
  EXPECT_THROW(World({.contacts = true, .speculative_margin = -0.1}), std::invalid_argument);
  EXPECT_THROW(World({.contacts = true, .speculative_margin = std::nan("")}), std::invalid_argument);
  EXPECT_THROW(world.within(Vec2(0, 0), nan), std::invalid_argument);
  EXPECT_THROW(world.ray_cast(Vec2(0, 0), Vec2(0, 0), 1), std::invalid_argument);
  EXPECT_THROW(world.overlapping(Aabb{Vec2(1, 1), Vec2(0, 0)}), std::invalid_argument);
  const auto message = [](auto call) -> std::string {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message([&] { world.set_pose(a, Vec2(nan, 0), 0); }), "set_pose position x must be finite (got nan)");
  EXPECT_EQ(message([&] { world.move_by(a, Vec2(nan, 0)); }), "move_by shift x must be finite (got nan)");
  EXPECT_EQ(message([&] { world.move_by(a, Vec2(0, 1), INFINITY); }), "move_by turn must be finite (got inf)");
  EXPECT_EQ(message([&] { world.move_to(b, Vec2(0, 1e51), 0); }),
            "move_to position y is beyond the supported range of +-1e50 (got 1e+51)");
  const std::string point = message([&] { static_cast<void>(world.within(Vec2(nan, 0), 1)); });
  EXPECT_NE(point.find("point x must be finite"), std::string::npos) << point;
  const std::string box = message([&] { static_cast<void>(world.overlapping(Aabb{Vec2(1, 0), Vec2(0, 0)})); });
  EXPECT_EQ(box, "box min x must not exceed box max x (got 1)");
  const std::string origin = message([&] { static_cast<void>(world.ray_cast(Vec2(0, 1e60), Vec2(1, 0), 1)); });
  EXPECT_NE(origin.find("ray origin y is beyond the supported range"), std::string::npos) << origin;
  EXPECT_EQ(world.size(), 2u);
  EXPECT_EQ(center_of(world.shape(a)), Vec2(0, 0));
  EXPECT_EQ(world.user_id(b), 2u);
  world.update();
  EXPECT_EQ(world.overlapping(), pairs);
  EXPECT_TRUE(world.began().empty());
}

// Ended pairs of bodies removed mid-contact and mid-sensor are whole records: a handler reads their
// user ids from the record, never from the World, and `removed` says which ended for that reason. A
// slot reused since by a new body does not confuse them.
TEST(World, EventsOfRemovedBodiesAreWholeRecords) {
  World world;
  const BodyId enemy = world.add(Circle{Vec2(0, 0), 1}, {.user_id = 10});
  const BodyId player = world.add(Circle{Vec2(1.5, 0), 1}, {.user_id = 20});
  const BodyId rock = world.add(Rect{Vec2(3, 0), Vec2(1, 1), 0}, {.user_id = 30});
  world.add(Circle{Vec2(0, 0.5), 1.5}, {.user_id = 40, .sensor = true});
  world.update();
  ASSERT_EQ(world.overlapping().size(), 2u);  // enemy-player, player-rock
  ASSERT_EQ(world.sensing().size(), 2u);      // enemy and player in the trigger
  for (const ShapePair& p : world.overlapping()) EXPECT_EQ(p.user_a, world.user_id(p.a));
  world.remove(enemy);
  world.move_by(rock, Vec2(5, 0));  // ends player-rock without a removal
  world.update();
  world.add(Circle{Vec2(50, 50), 1}, {.user_id = 50});  // takes the enemy's slot
  std::vector<std::string> log;
  for (const ShapePair& p : world.ended()) {
    log.push_back(std::to_string(p.user_a) + "-" + std::to_string(p.user_b) + (p.removed ? " removed" : " parted"));
    if (!p.removed) EXPECT_EQ(world.user_id(p.a), p.user_a);
  }
  for (const SensorPair& s : world.sensor_ended()) {
    log.push_back(std::to_string(s.user_sensor) + ">" + std::to_string(s.user_visitor) +
                  (s.removed ? " removed" : " left"));
  }
  EXPECT_EQ(log, (std::vector<std::string>{"10-20 removed", "20-30 parted", "40>10 removed"}));
  EXPECT_FALSE(world.contains(enemy));
  EXPECT_TRUE(world.contains(player));
}

// A is the lower slot: a player re-added into a lower slot than the crate's comes first, and its
// contact's normal turns round; the user ids in the record say which is which.
TEST(World, RecordsNameTheirBodiesByUserId) {
  World world({.contacts = true});
  const BodyId spare = world.add(Circle{Vec2(50, 50), 1});
  const BodyId crate = world.add(Rect{Vec2(0, 0), Vec2(1, 1), 0}, {.user_id = 7});
  BodyId player = world.add(Circle{Vec2(0, 1.5), 1}, {.user_id = 3});
  world.update();
  ASSERT_EQ(world.contacts().size(), 1u);
  const BodyContact before = world.contacts()[0];
  EXPECT_EQ(before.user_a, 7u);
  EXPECT_EQ(before.user_b, 3u);
  world.remove(player);
  world.remove(spare);
  player = world.add(Circle{Vec2(0, 1.5), 1}, {.user_id = 3});  // into the spare's slot, below the crate's
  world.update();
  ASSERT_EQ(world.contacts().size(), 1u);
  const BodyContact after = world.contacts()[0];
  EXPECT_EQ(after.a, player);
  EXPECT_EQ(after.b, crate);
  EXPECT_EQ(after.user_a, 3u);
  EXPECT_EQ(after.user_b, 7u);
  EXPECT_EQ(after.contact.normal, Vec2(-before.contact.normal));
  // Oriented by the user ids, crate to player, the normal is the same as before.
  const Vec2 crate_to_player = after.user_a == 7 ? after.contact.normal : Vec2(-after.contact.normal);
  EXPECT_EQ(crate_to_player, before.contact.normal);
}

// A handle kept past remove() is refused, also once a new body has taken its slot, and the new
// body is untouched by calls made with it.
TEST(World, StaleHandlesAreRefusedAfterTheirSlotIsReused) {
  World world;
  const BodyId a = world.add(Circle{Vec2(0, 0), 1}, {.user_id = 1});
  world.add(Circle{Vec2(5, 0), 1}, {.user_id = 2});
  world.remove(a);
  world.update();  // the broad phase hands a's slot out again after an update
  const BodyId c = world.add(Circle{Vec2(10, 0), 1}, {.user_id = 3});
  ASSERT_EQ(c.index, a.index);
  EXPECT_NE(c.generation, a.generation);
  EXPECT_FALSE(world.contains(a));
  EXPECT_TRUE(world.contains(c));
  EXPECT_THROW(world.set_pose(a, Vec2(1, 1), 0), std::out_of_range);
  EXPECT_THROW(world.move_by(a, Vec2(1, 1)), std::out_of_range);
  EXPECT_THROW(world.remove(a), std::out_of_range);
  EXPECT_THROW(world.shape(a), std::out_of_range);
  EXPECT_THROW(world.user_id(a), std::out_of_range);
  EXPECT_EQ(center_of(world.shape(c)), Vec2(10, 0));
  EXPECT_EQ(world.user_id(c), 3u);
  EXPECT_EQ(world.size(), 2u);
  const auto message = [&world](BodyId id) -> std::string {
    try {
      world.remove(id);
    } catch (const std::out_of_range& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message(a), "stale body 0 (generation 1): that body was removed; its slot is at generation 2");
  EXPECT_EQ(message(BodyId{7, 1}), "unknown body 7 (generation 1)");
  EXPECT_EQ(message(BodyId{}), "unknown body 0 (generation 0)");
}

// A bullet 10 of its sizes per frame... 1,000 of them, through a wall 10 sizes thick: on one side
// at one update and on the other at the next. Without the flag the World sees nothing; with it,
// impacts() holds the pair, at the exact time less at most the tolerance over the speed.
TEST(World, ContinuousBodiesDoNotTunnel) {
  for (const bool flagged : {false, true}) {
    World world;
    const BodyId wall = world.add(Rect{{0, 0}, {0.005, 1}, 0});
    const BodyId bullet = world.add(Circle{{-1, 0.3}, 0.001});
    if (flagged) world.set_continuous(bullet);
    world.update();
    world.move_to(bullet, {1, 0.3}, 0);
    world.update();
    EXPECT_TRUE(world.overlapping().empty());
    if (!flagged) {
      EXPECT_TRUE(world.impacts().empty());
      continue;
    }
    ASSERT_EQ(world.impacts().size(), 1u);
    const Impact& hit = world.impacts()[0];
    EXPECT_EQ(hit.a, wall);
    EXPECT_EQ(hit.b, bullet);
    const double t0 = (1 - 0.005 - 0.001) / 2;
    EXPECT_LE(hit.t, t0 + 1e-15);
    EXPECT_GE(hit.t, t0 - 1e-9);
    EXPECT_NEAR(hit.normal.x(), -1.0, 1e-12);
    EXPECT_EQ(world.last_frame().impacts, 1u);
    world.update();  // the next step begins where this one ended: no motion, no impact
    EXPECT_TRUE(world.impacts().empty());
  }
}

// set_pose() teleports: a continuous bullet put across the wall, before or after a move_to() in the
// same frame, hits nothing; move_to() from where it landed sweeps again. A body's pose reads back as
// it was given, a circle's angle too.
TEST(World, SetPoseTeleportsAndMoveToSweeps) {
  World world;
  world.add(Rect{{0, 0}, {0.005, 1}, 0});
  const BodyId bullet = world.add(Circle{{-1, 0.3}, 0.001});
  world.set_continuous(bullet);
  EXPECT_TRUE(world.is_continuous(bullet));
  world.update();
  world.set_pose(bullet, {1, 0.3}, 2.5);
  world.update();
  EXPECT_TRUE(world.impacts().empty());
  EXPECT_EQ(world.pose(bullet).position, Vec2(1, 0.3));
  EXPECT_EQ(world.pose(bullet).angle, 2.5);
  world.move_to(bullet, {0.5, 0.3}, 0);
  world.set_pose(bullet, {-1, 0.3}, 0);  // the step starts again here
  world.update();
  EXPECT_TRUE(world.impacts().empty());
  world.move_to(bullet, {0.5, 0.3}, 0);
  world.move_by(bullet, {0.5, 0}, 1);
  world.update();
  ASSERT_EQ(world.impacts().size(), 1u);
  EXPECT_EQ(world.pose(bullet).position, Vec2(1, 0.3));
  EXPECT_EQ(world.pose(bullet).angle, 1.0);
}

// Over frames of random moves and turns, with a third of the bodies continuous (and some switched
// off again, some removed), impacts() equals time_of_impact on every pair with a continuous body
// from the poses the test recorded at the last update.
TEST(World, ImpactsMatchAllPairs) {
  Rng rng(21);
  World world;
  std::vector<BodyId> ids;
  for (int k = 0; k < 120; ++k) ids.push_back(world.add(random_shape(rng, 12.0)));
  for (std::size_t k = 0; k < ids.size(); k += 3) world.set_continuous(ids[k]);
  world.update();
  std::vector<Shape> start;
  for (const BodyId id : ids) start.push_back(world.shape(id));
  std::size_t total = 0;
  for (int frame = 0; frame < 12; ++frame) {
    for (std::size_t k = 0; k < ids.size(); ++k) {
      if (!world.contains(ids[k])) continue;
      const double speed = k % 3 == 0 ? 3.0 : 0.3;
      world.move_by(ids[k], Vec2(uniform(rng, -speed, speed), uniform(rng, -speed, speed)), uniform(rng, -1, 1));
    }
    if (frame == 5) world.set_continuous(ids[3], false);
    if (frame == 7) world.remove(ids[6]);
    world.update();
    std::vector<Impact> expected;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      for (std::size_t j = i + 1; j < ids.size(); ++j) {
        const bool ci = i % 3 == 0 && !(i == 3 && frame >= 5), cj = j % 3 == 0 && !(j == 3 && frame >= 5);
        if (!world.contains(ids[i]) || !world.contains(ids[j]) || !(ci || cj)) continue;
        const auto motion = [&](std::size_t k, bool c) {
          return c ? Motion{center_of(world.shape(ids[k])) - center_of(start[k]),
                            angle_of(world.shape(ids[k])) - angle_of(start[k])}
                   : Motion{};
        };
        const TimeOfImpact r = time_of_impact(ci ? start[i] : world.shape(ids[i]), motion(i, ci),
                                              cj ? start[j] : world.shape(ids[j]), motion(j, cj));
        if (r.status == ToiStatus::hit || r.status == ToiStatus::stalled)
          expected.push_back({ids[i], ids[j], world.shapes(ids[i])[0], world.shapes(ids[j])[0], world.user_id(ids[i]),
                              world.user_id(ids[j]), world.user_id(ids[i]), world.user_id(ids[j]), r.t, r.normal,
                              r.point});
      }
    }
    ASSERT_EQ(world.impacts().size(), expected.size()) << "frame " << frame;
    for (std::size_t k = 0; k < expected.size(); ++k) {
      const Impact& got = world.impacts()[k];
      EXPECT_EQ(got.a, expected[k].a);
      EXPECT_EQ(got.b, expected[k].b);
      EXPECT_EQ(got.user_a, expected[k].user_a);
      EXPECT_EQ(got.user_b, expected[k].user_b);
      EXPECT_EQ(got.t, expected[k].t);
      EXPECT_EQ(got.normal, expected[k].normal);
    }
    total += expected.size();
    for (std::size_t k = 0; k < ids.size(); ++k) {
      if (world.contains(ids[k])) start[k] = world.shape(ids[k]);
    }
  }
  EXPECT_GT(total, 20u);
  std::printf("[world] impacts over 12 frames: %zu, all equal to all-pairs time of impact\n", total);
}

// cast() against brute force: the least fraction of every body's shape cast, the same body.
TEST(World, CastFindsTheFirstBody) {
  Rng rng(22);
  const World world = random_world(rng, 200);
  int hits = 0;
  int skipped = 0;
  for (int k = 0; k < 400; ++k) {
    const Shape probe = random_shape(rng, 10.0);
    const Vec2 translation(uniform(rng, -4, 4), uniform(rng, -4, 4));
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
    const Vec2 origin(uniform(rng, -1, 11), uniform(rng, -1, 11));
    const Vec2 direction(uniform(rng, -1, 1), uniform(rng, -1, 1));
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

// Box2D's rules, case by case: masks both ways, a shared positive group overriding masks that
// refuse, a shared negative group overriding masks that accept, different groups left to the masks.
TEST(WorldFilter, FollowsBox2DsRules) {
  const Filter any;
  const Filter player{.category = 0b01, .mask = ~std::uint64_t{0b10}};
  const Filter bullet{.category = 0b10, .mask = ~std::uint64_t{0b01}};
  EXPECT_TRUE(should_pair(any, any));
  EXPECT_FALSE(should_pair(player, bullet));
  EXPECT_FALSE(should_pair(bullet, player));
  EXPECT_TRUE(should_pair(player, any));
  const Filter deaf{.category = 1, .mask = 0};
  EXPECT_FALSE(should_pair(deaf, any));
  EXPECT_FALSE(should_pair(any, deaf));
  EXPECT_TRUE(should_pair({.category = 1, .mask = 0, .group = 3}, {.category = 1, .mask = 0, .group = 3}));
  EXPECT_FALSE(should_pair({.group = -2}, {.group = -2}));
  EXPECT_TRUE(should_pair({.group = -2}, {.group = -3}));
  EXPECT_FALSE(should_pair({.category = 1, .mask = 0, .group = 3}, {.group = 4}));
}

Filter random_filter(Rng& rng) {
  const int groups[] = {0, 0, 0, 1, -1};
  return {.category = std::uint64_t{1} << static_cast<int>(uniform(rng, 0, 3)),
          .mask = static_cast<std::uint64_t>(uniform(rng, 0, 8)),
          .group = groups[static_cast<int>(uniform(rng, 0, 5))]};
}

// Over frames of motion, with random filters, a pair predicate, and filters changed mid-run: the
// overlapping pairs are exactly the all-pairs ones that pass both, and began()/ended() are the
// differences from the frame before (a filter change ends the pairs it refuses).
TEST(WorldFilter, PairsMatchAllPairsWithTheSameFilters) {
  Rng rng(21);
  World world({.fat_margin = 0.05});
  for (int k = 0; k < 200; ++k)
    world.add(random_shape(rng, 12.0), {.user_id = static_cast<std::uint64_t>(k), .filter = random_filter(rng)});
  world.set_pair_predicate([&world](BodyId a, BodyId b) { return (world.user_id(a) + world.user_id(b)) % 5 != 0; });
  std::vector<ShapePair> previous;
  std::size_t refused = 0, ended_by_filters = 0;
  for (int frame = 0; frame < 20; ++frame) {
    std::vector<BodyPair> moved_apart;
    if (frame == 10) {
      for (const BodyId id : world.bodies()) {
        if (id.index % 3 == 0) world.set_filter(id, random_filter(rng));
      }
    } else {
      for (const BodyId id : world.bodies())
        world.move_by(id, Vec2(uniform(rng, -0.1, 0.1), uniform(rng, -0.1, 0.1)), 0.03);
    }
    world.update();
    const std::vector<BodyId> ids = world.bodies();
    std::vector<ShapePair> expected;
    for (std::size_t i = 0; i < ids.size(); ++i) {
      for (std::size_t j = i + 1; j < ids.size(); ++j) {
        if (!overlaps(world.shape(ids[i]), world.shape(ids[j]))) continue;
        const bool pass = should_pair(world.filter(ids[i]), world.filter(ids[j])) &&
                          (world.user_id(ids[i]) + world.user_id(ids[j])) % 5 != 0;
        if (pass) {
          expected.push_back(solo_pair(world, ids[i], ids[j]));
        } else {
          ++refused;
        }
      }
    }
    ASSERT_EQ(world.overlapping(), expected) << "frame " << frame;
    expect_changes(previous, expected, world.began(), world.ended(), "frame " + std::to_string(frame));
    if (HasFatalFailure()) return;
    if (frame == 10) ended_by_filters = world.ended().size();
    EXPECT_GT(world.last_frame().filtered, 0u);
    previous = expected;
  }
  EXPECT_GT(refused, 100u);
  EXPECT_GT(ended_by_filters, 0u);  // no body moved in frame 10: those pairs ended by their filters
  std::printf("[world] filters: %zu overlapping pairs refused over 20 frames, %zu ended by a filter change\n", refused,
              ended_by_filters);
}

// Every query reports exactly the bodies brute force finds among those the query filter lets
// through.
TEST(WorldFilter, QueriesSkipWhatTheFilterRefuses) {
  Rng rng(22);
  World world;
  for (int k = 0; k < 200; ++k) world.add(random_shape(rng, 10.0), {.filter = random_filter(rng)});
  const auto through = [](const QueryFilter& q, const Filter& f) {
    return (f.category & q.mask) && (f.mask & q.category);
  };
  for (int k = 0; k < 60; ++k) {
    const QueryFilter q{.category = std::uint64_t{1} << static_cast<int>(uniform(rng, 0, 3)),
                        .mask = static_cast<std::uint64_t>(uniform(rng, 1, 8))};
    const Shape probe = random_shape(rng, 10.0);
    const Vec2 origin(uniform(rng, -1, 11), uniform(rng, -1, 11));
    const double angle = uniform(rng, 0, 6.3);
    const Vec2 dir(std::cos(angle), std::sin(angle));
    std::vector<BodyId> hit, near;
    std::optional<RayHit> first;
    for (const BodyId id : world.bodies()) {
      if (!through(q, world.filter(id))) continue;
      if (overlaps(probe, world.shape(id))) hit.push_back(id);
      if (distance(probe, world.shape(id)).distance <= 0.5) near.push_back(id);
      const auto r = ray_cast(world.shape(id), origin, Vec2(dir / dir.norm()), 30.0);  // as the World scales it
      if (r && !contains(world.shape(id), origin) && (!first || r->distance < first->distance))
        first = RayHit{id, world.shapes(id)[0], r->distance, r->point, r->normal};
    }
    ASSERT_EQ(world.overlapping(probe, q), hit) << k;
    ASSERT_EQ(world.within(probe, 0.5, q), near) << k;
    const auto got = world.ray_cast(origin, dir, 30.0, q);
    ASSERT_EQ(got.has_value(), first.has_value()) << k;
    if (got) ASSERT_EQ(got->distance, first->distance) << k;
  }
}

// A level: static bodies (overlapping each other, never paired), moving bodies and sensors of both
// kinds, with filters. Over frames of motion, static churn, a static body moved, bodies changing
// kind, a filter change and moving churn, everything the World reports matches all pairs under the
// same rules, and the began and ended lists (solid and sensor) are the differences from the frame
// before. A frame where nothing moves looks up no static neighbours.
TEST(WorldStatic, PairsMatchAllPairsWithStaticsAndSensors) {
  for (const double margin : {0.0, 0.25}) {
    Rng rng(31);
    World world({.fat_margin = 0.1, .proximity_margin = margin});
    const auto add = [&](bool is_static, bool sensor) {
      const Filter f = uniform(rng, 0, 1) < 0.2 ? random_filter(rng) : Filter{};
      return world.add(random_shape(rng, 15.0), {.user_id = 0, .filter = f, .is_static = is_static, .sensor = sensor});
    };
    for (int k = 0; k < 150; ++k) add(true, k % 15 == 0);
    for (int k = 0; k < 120; ++k) add(false, k % 20 == 0);
    std::vector<ShapePair> previous;
    std::vector<SensorPair> previous_sensing;
    std::size_t static_overlaps = 0, sensor_began = 0, sensor_ended = 0;
    for (int frame = 0; frame < 30; ++frame) {
      const std::vector<BodyId> ids = world.bodies();
      if (frame != 29) {
        for (const BodyId id : ids) {
          if (!world.is_static(id)) world.move_by(id, Vec2(uniform(rng, -0.15, 0.15), uniform(rng, -0.15, 0.15)), 0.05);
        }
      }
      if (frame == 7) {
        for (std::size_t k = 0; k < ids.size(); k += 11) {
          if (world.is_static(ids[k])) world.remove(ids[k]);
        }
        for (int k = 0; k < 12; ++k) add(true, k % 4 == 0);
      }
      if (frame == 12) {
        for (std::size_t k = 1; k < ids.size(); k += 13) {
          if (world.is_static(ids[k])) world.move_by(ids[k], Vec2(0.7, -0.4), 0.3);
        }
      }
      if (frame == 15) {
        for (std::size_t k = 2; k < ids.size(); k += 9) world.set_static(ids[k], !world.is_static(ids[k]));
      }
      if (frame == 20) {
        for (std::size_t k = 3; k < ids.size(); k += 7) world.set_filter(ids[k], random_filter(rng));
      }
      if (frame == 25) {
        for (std::size_t k = 4; k < ids.size(); k += 10) {
          if (!world.is_static(ids[k])) world.remove(ids[k]);
        }
        for (int k = 0; k < 10; ++k) add(false, k % 5 == 0);
      }
      world.update();
      const std::string what = "margin " + std::to_string(margin) + ", frame " + std::to_string(frame);
      expect_matches_all_pairs(world, margin, what);
      if (HasFatalFailure()) return;
      expect_changes(previous, world.overlapping(), world.began(), world.ended(), what);
      expect_changes(previous_sensing, world.sensing(), world.sensor_began(), world.sensor_ended(), what);
      if (HasFatalFailure()) return;
      if (frame == 29) EXPECT_EQ(world.last_frame().requeried, 0u) << "nothing moved, nothing static changed";
      previous = world.overlapping();
      previous_sensing = world.sensing();
      sensor_began += world.sensor_began().size();
      sensor_ended += world.sensor_ended().size();
    }
    const std::vector<BodyId> ids = world.bodies();
    for (std::size_t i = 0; i < ids.size(); ++i) {
      for (std::size_t j = i + 1; j < ids.size(); ++j) {
        const bool both = world.is_static(ids[i]) && world.is_static(ids[j]);
        if (both && overlaps(world.shape(ids[i]), world.shape(ids[j]))) ++static_overlaps;
      }
    }
    EXPECT_GT(static_overlaps, 10u);  // overlapping static pairs exist and were left out
    EXPECT_GT(sensor_began, 10u);
    EXPECT_GT(sensor_ended, 5u);
    EXPECT_GT(world.overlapping().size(), 20u);
    std::printf("[world] statics: %zu overlapping static pairs left out, %zu sensor entries, %zu exits\n",
                static_overlaps, sensor_began, sensor_ended);
  }
}

// Queries through the trees: the solid bodies, moving and static (never sensors), that a scan of
// every body finds, also right after bodies moved (no update in between).
TEST(WorldStatic, QueriesSeeSolidBodiesOfBothKinds) {
  Rng rng(32);
  World world({.fat_margin = 0.1});
  for (int k = 0; k < 450; ++k) {
    world.add(random_shape(rng, 12.0),
              {.user_id = 0, .filter = random_filter(rng), .is_static = k % 3 != 0, .sensor = k % 10 == 0});
  }
  world.update();
  const auto through = [](const QueryFilter& q, const Filter& f) {
    return (f.category & q.mask) && (f.mask & q.category);
  };
  for (int k = 0; k < 80; ++k) {
    if (k == 40) {
      for (const BodyId id : world.bodies())
        world.move_by(id, Vec2(uniform(rng, -0.5, 0.5), uniform(rng, -0.5, 0.5)), 0.2);
    }
    const QueryFilter q =
        k % 2 == 0 ? QueryFilter{} : QueryFilter{.category = 1, .mask = static_cast<std::uint64_t>(uniform(rng, 1, 8))};
    const Shape probe = random_shape(rng, 12.0);
    const Vec2 point(uniform(rng, 0, 12), uniform(rng, 0, 12));
    const Aabb box{point, point + Vec2(uniform(rng, 0, 3), uniform(rng, 0, 3))};
    const Vec2 origin(uniform(rng, -1, 13), uniform(rng, -1, 13));
    const double angle = uniform(rng, 0, 6.3);
    const Vec2 dir(2.0 * std::cos(angle), 2.0 * std::sin(angle));
    const Vec2 unit = dir / dir.norm();
    const Vec2 shift(uniform(rng, -4, 4), uniform(rng, -4, 4));
    std::vector<BodyId> hit, near, in_box;
    std::vector<RayHit> all;
    std::optional<BodyCastHit> cast;
    for (const BodyId id : world.bodies()) {
      if (world.is_sensor(id) || !through(q, world.filter(id))) continue;
      const Shape& s = world.shape(id);
      if (overlaps(probe, s)) hit.push_back(id);
      if (distance(probe, s).distance <= 0.4) near.push_back(id);
      if (overlaps(s, box)) in_box.push_back(id);
      const auto r = contains(s, origin) ? std::nullopt : ray_cast(s, origin, unit, 15.0);
      const ShapeId only = world.shapes(id)[0];
      if (r) all.push_back({id, only, r->distance, r->point, r->normal});
      const auto c = shape_cast(probe, shift, s);
      if (c && (!cast || c->fraction < cast->fraction)) cast = BodyCastHit{id, only, c->fraction, c->point, c->normal};
    }
    std::stable_sort(all.begin(), all.end(), [](const RayHit& a, const RayHit& b) { return a.distance < b.distance; });
    ASSERT_EQ(world.overlapping(probe, q), hit) << k;
    ASSERT_EQ(world.within(probe, 0.4, q), near) << k;
    ASSERT_EQ(world.overlapping(box, q), in_box) << k;
    const std::vector<RayHit> got = world.ray_cast_all(origin, dir, 15.0, q);
    ASSERT_EQ(got.size(), all.size()) << k;
    for (std::size_t i = 0; i < all.size(); ++i) {
      ASSERT_EQ(got[i].body, all[i].body) << k;
      ASSERT_EQ(got[i].distance, all[i].distance) << k;
    }
    const auto first = world.ray_cast(origin, dir, 15.0, q);
    ASSERT_EQ(first.has_value(), !all.empty()) << k;
    if (first) ASSERT_EQ(first->body, all.front().body) << k;
    const auto got_cast = world.cast(probe, shift, q);
    ASSERT_EQ(got_cast.has_value(), cast.has_value()) << k;
    if (got_cast) ASSERT_EQ(got_cast->body, cast->body) << k;
  }
}

TEST(WorldStatic, StaticBodiesCannotBeContinuous) {
  World world;
  const BodyId wall =
      world.add(Rect{{0, 0}, {1, 5}, 0}, {.user_id = 4, .filter = {}, .is_static = true, .sensor = false});
  const BodyId ball = world.add(Circle{{0.5, 0}, 1});
  world.update();
  const auto pairs = world.overlapping();
  try {
    world.set_continuous(wall);
    ADD_FAILURE() << "a static body was made continuous";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "body 0 is static: only moving bodies can be continuous");
  }
  world.set_continuous(ball);
  world.set_static(ball, true);  // stops being continuous
  world.set_pose(ball, Vec2(0.5, 0.2), 0.0);
  world.update();
  EXPECT_TRUE(world.impacts().empty());
  EXPECT_TRUE(world.overlapping().empty());  // two static bodies
  world.set_static(ball, false);
  world.update();
  EXPECT_EQ(world.overlapping().size(), pairs.size());
  EXPECT_THROW(world.set_static(BodyId{9, 1}, true), std::out_of_range);
}

// The same World on 1, 2 and 3 threads: every list it reports identical, in the same order, frame
// after frame, with static bodies, sensors, bullets, proximity and contacts (thousands of candidate
// pairs, so the narrow phase runs in many chunks).
TEST(WorldThreads, EveryThreadCountReportsTheSame) {
  std::vector<World> worlds;
  for (const unsigned threads : {1u, 2u, 3u}) {
    worlds.emplace_back(WorldOptions{
        .fat_margin = 0.1, .proximity_margin = 0.3, .contacts = true, .speculative_margin = 0.1, .threads = threads});
  }
  Rng rng(51);
  for (int k = 0; k < 1500; ++k) {
    const Shape shape = random_shape(rng, 40.0);
    const BodyDef def{.user_id = 0, .filter = {}, .is_static = k % 5 == 0, .sensor = k % 37 == 0};
    for (World& w : worlds) {
      const BodyId id = w.add(shape, def);
      if (k % 97 == 1 && !def.is_static) w.set_continuous(id);
    }
  }
  std::size_t candidates = 0;
  for (int frame = 0; frame < 10; ++frame) {
    std::vector<std::pair<Vec2, double>> moves;
    for (const BodyId id : worlds[0].bodies())
      moves.emplace_back(Vec2(uniform(rng, -0.3, 0.3), uniform(rng, -0.3, 0.3)), 0.05);
    for (World& w : worlds) {
      std::size_t m = 0;
      for (const BodyId id : w.bodies()) {
        if (!w.is_static(id)) w.move_by(id, moves[m].first, moves[m].second);
        ++m;
      }
      w.update();
    }
    candidates += worlds[0].last_frame().candidates;
    for (std::size_t t = 1; t < worlds.size(); ++t) {
      const World& a = worlds[0];
      const World& b = worlds[t];
      ASSERT_EQ(a.overlapping(), b.overlapping()) << frame;
      ASSERT_EQ(a.began(), b.began()) << frame;
      ASSERT_EQ(a.ended(), b.ended()) << frame;
      ASSERT_EQ(a.sensing(), b.sensing()) << frame;
      ASSERT_EQ(a.sensor_began(), b.sensor_began()) << frame;
      ASSERT_EQ(a.last_frame().filtered, b.last_frame().filtered) << frame;
      ASSERT_EQ(a.proximity().size(), b.proximity().size()) << frame;
      for (std::size_t i = 0; i < a.proximity().size(); ++i) {
        ASSERT_TRUE(a.proximity()[i].a == b.proximity()[i].a && a.proximity()[i].b == b.proximity()[i].b);
        ASSERT_EQ(a.proximity()[i].result.distance, b.proximity()[i].result.distance);
      }
      ASSERT_EQ(a.contacts().size(), b.contacts().size()) << frame;
      for (std::size_t i = 0; i < a.contacts().size(); ++i) {
        ASSERT_TRUE(a.contacts()[i].a == b.contacts()[i].a && a.contacts()[i].b == b.contacts()[i].b);
        ASSERT_EQ(a.contacts()[i].contact.separation, b.contacts()[i].contact.separation);
        ASSERT_EQ(a.contacts()[i].contact.normal, b.contacts()[i].contact.normal);
      }
      ASSERT_EQ(a.impacts().size(), b.impacts().size()) << frame;
      for (std::size_t i = 0; i < a.impacts().size(); ++i) {
        ASSERT_TRUE(a.impacts()[i].a == b.impacts()[i].a && a.impacts()[i].b == b.impacts()[i].b);
        ASSERT_EQ(a.impacts()[i].t, b.impacts()[i].t);
      }
    }
  }
  EXPECT_GT(candidates / 10, 2000u);  // many chunks of 256 pairs
  EXPECT_GT(worlds[0].contacts().size(), 100u);
  EXPECT_GT(worlds[0].sensing().size(), 10u);
}

// The pool calls every task exactly once per run, over many runs, with 1 to 4 threads.
TEST(WorldThreads, ThePoolRunsEveryTaskOnce) {
  for (const unsigned threads : {1u, 2u, 4u}) {
    detail::ThreadPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    std::vector<std::atomic<int>> calls(1000);
    for (int run = 0; run < 200; ++run) pool.run(run % 2 == 0 ? calls.size() : 7, [&](std::size_t k) { ++calls[k]; });
    for (std::size_t k = 0; k < calls.size(); ++k)
      ASSERT_EQ(calls[k].load(), k < 7 ? 200 : 100) << threads << " threads, task " << k;
  }
}

}  // namespace
}  // namespace collide2d
