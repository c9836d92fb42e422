// Bodies of several shapes: their pairs against every pair of shapes under the World's rules through
// churn, their placement against the pose composed in 50 digits, their impacts, queries and refusals.
#include <collide2d/ray_cast.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>
#include "mp_reference.h"
#include "tools/random.h"
#include "world_reference.h"
#include "world_testing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace collide2d {
namespace {

using Rng = std::mt19937_64;

using tool::uniform;
using tool::uniform_point;
int pick(Rng& rng, int n) { return static_cast<int>(tool::uniform_index(rng, static_cast<std::size_t>(n))); }

// A shape in a body's frame: about its origin, half the time with an angle of its own.
Shape local_shape(Rng& rng) {
  const Vec2 offset = uniform_point(rng, -1.5, 1.5);
  const double size = uniform(rng, 0.2, 0.8), angle = pick(rng, 2) == 0 ? 0.0 : uniform(rng, -3, 3);
  switch (pick(rng, 3)) {
    case 0:
      return Circle{offset, size};
    case 1:
      return Ellipse{offset, size, size * uniform(rng, 0.2, 1.0), angle};
    default:
      return Rect{offset, Vec2(size, size * uniform(rng, 0.2, 1.0)), angle};
  }
}

Filter random_filter(Rng& rng) {
  return {.category = std::uint64_t{1} << pick(rng, 3),
          .mask = static_cast<std::uint64_t>(1 + pick(rng, 7)),
          .group = pick(rng, 5) - 2};
}

// A shape of a body: now and then with a user id, filter or sensor flag of its own.
ShapeDef shape_def(Rng& rng, std::uint64_t user) {
  ShapeDef d{.shape = local_shape(rng)};
  if (pick(rng, 3) == 0) d.user_id = user;
  if (pick(rng, 4) == 0) d.filter = random_filter(rng);
  if (pick(rng, 6) == 0) d.sensor = pick(rng, 2) == 0;
  return d;
}

BodyId add_body(World& world, Rng& rng, std::uint64_t user) {
  std::vector<ShapeDef> defs;
  for (int k = 1 + pick(rng, 4); k > 0; --k) defs.push_back(shape_def(rng, 1000 * user + k));
  const Pose pose{uniform_point(rng, 0, 20), uniform(rng, -3, 3)};
  return world.add(pose, defs, {.user_id = user, .is_static = pick(rng, 6) == 0, .sensor = pick(rng, 10) == 0});
}

using testing::expect_changes;

std::vector<BodyPair> bodies_of(const std::vector<ShapePair>& pairs) {
  std::vector<BodyPair> out;
  for (const ShapePair& p : pairs) {
    if (out.empty() || out.back() != BodyPair{p.a, p.b}) out.push_back({p.a, p.b});
  }
  return out;
}

// The visits of an all-pairs scan's sensor pairs: each (sensor shape, visiting body) once, in a set
// ordered as SensorVisit orders, with the user ids the World holds now.
std::vector<SensorVisit> visits_of(const World& world, const std::vector<SensorPair>& pairs) {
  std::set<std::tuple<BodyId, BodyId, ShapeId>> seen;
  for (const SensorPair& p : pairs) seen.insert({p.sensor, p.visitor, p.sensor_shape});
  std::vector<SensorVisit> out;
  for (const auto& [sensor, visitor, shape] : seen) {
    out.push_back({sensor, visitor, shape, world.user_id(sensor), world.user_id(visitor), world.user_id(shape)});
  }
  return out;
}

// Each record names both bodies and shapes, with the user ids of the update.
void expect_whole(const World& world, const ShapePair& p, const std::string& what) {
  ASSERT_LT(p.a.index, p.b.index) << what;
  ASSERT_EQ(world.body(p.shape_a), p.a) << what;
  ASSERT_EQ(world.body(p.shape_b), p.b) << what;
  ASSERT_EQ(p.user_a, world.user_id(p.a)) << what;
  ASSERT_EQ(p.user_b, world.user_id(p.b)) << what;
  ASSERT_EQ(p.shape_user_a, world.user_id(p.shape_a)) << what;
  ASSERT_EQ(p.shape_user_b, world.user_id(p.shape_b)) << what;
}

// One World step of churn: shapes added to and removed from live bodies, bodies of several shapes
// removed and added, filters, sensor flags and placements changed per shape.
void churn(World& world, Rng& rng, std::uint64_t& next_user) {
  const std::vector<BodyId> ids = world.bodies();
  for (std::size_t k = 0; k < ids.size(); k += 5) {
    const BodyId id = ids[k];
    const std::vector<ShapeId> shapes = world.shapes(id);
    switch (pick(rng, 6)) {
      case 0:
        world.add_shape(id, shape_def(rng, 7000 + k));
        break;
      case 1:
        if (shapes.size() > 1) world.remove_shape(shapes[pick(rng, static_cast<int>(shapes.size()))]);
        break;
      case 2:
        world.remove(id);
        add_body(world, rng, next_user++);
        break;
      case 3:
        world.set_filter(shapes[pick(rng, static_cast<int>(shapes.size()))], random_filter(rng));
        break;
      case 4:
        world.set_sensor(shapes.back(), !world.is_sensor(shapes.back()));
        break;
      default:
        world.set_local_shape(shapes.front(), local_shape(rng));
    }
  }
}

TEST(WorldShapes, PairsMatchAllShapePairsThroughChurn) {
  for (const double margin : {0.0, 0.25}) {
    Rng rng(51);
    World world({.fat_margin = 0.05, .proximity_margin = margin});
    std::uint64_t next_user = 1;
    for (int k = 0; k < 90; ++k) add_body(world, rng, next_user++);
    std::vector<ShapePair> previous;
    std::vector<SensorPair> sensed;
    std::vector<SensorVisit> visits;
    std::size_t compound_pairs = 0, body_pairs_kept = 0;
    std::ptrdiff_t compound_visits = 0;
    for (int frame = 0; frame < 30; ++frame) {
      const std::string what = "margin " + std::to_string(margin) + " frame " + std::to_string(frame);
      for (const BodyId id : world.bodies()) {
        if (!world.is_static(id)) world.move_by(id, uniform_point(rng, -0.2, 0.2), 0.05);
      }
      if (frame % 5 == 2) churn(world, rng, next_user);
      world.update();
      const reference::AllPairs expected = reference::all_pairs(world, margin);
      ASSERT_EQ(world.overlapping(), expected.overlapping) << what;
      ASSERT_EQ(world.sensing(), expected.sensing) << what;
      std::vector<ShapePair> near;
      for (const Proximity& p : world.proximity()) near.push_back({p.a, p.b, p.shape_a, p.shape_b});
      ASSERT_EQ(near, expected.near) << what;
      expect_changes(previous, world.overlapping(), world.began(), world.ended(), what);
      expect_changes(bodies_of(previous), bodies_of(world.overlapping()), world.body_began(), world.body_ended(), what);
      expect_changes(sensed, world.sensing(), world.sensor_began(), world.sensor_ended(), what);
      ASSERT_EQ(world.body_overlapping(), bodies_of(world.overlapping())) << what;
      // Body-level sensor events: a body enters with its first shape and leaves with its last.
      const std::vector<SensorVisit> now = visits_of(world, expected.sensing);
      ASSERT_EQ(world.body_sensing(), now) << what;
      for (std::size_t k = 0; k < now.size(); ++k) {
        ASSERT_EQ(world.body_sensing()[k].user_visitor, now[k].user_visitor) << what;
        ASSERT_EQ(world.body_sensing()[k].shape_user_sensor, now[k].shape_user_sensor) << what;
      }
      expect_changes(visits, now, world.body_sensor_began(), world.body_sensor_ended(), what);
      for (const SensorVisit& v : world.body_sensor_ended()) {
        ASSERT_EQ(v.removed, !world.contains(v.sensor) || !world.contains(v.visitor) || !world.contains(v.sensor_shape))
            << what;
      }
      compound_visits += std::count_if(now.begin(), now.end(), [&](const SensorVisit& v) {
        return std::count_if(expected.sensing.begin(), expected.sensing.end(), [&](const SensorPair& p) {
                 return p.sensor_shape == v.sensor_shape && p.visitor == v.visitor;
               }) > 1;
      });
      if (HasFatalFailure()) return;
      for (const ShapePair& p : world.overlapping()) {
        expect_whole(world, p, what);
        compound_pairs += world.shapes(p.a).size() > 1 || world.shapes(p.b).size() > 1;
      }
      for (const ShapePair& p : world.ended()) {
        ASSERT_EQ(p.removed, !world.contains(p.shape_a) || !world.contains(p.shape_b)) << what;
      }
      body_pairs_kept += world.overlapping().size() - world.body_overlapping().size();
      previous = world.overlapping();
      sensed = world.sensing();
      visits = now;
    }
    EXPECT_GT(compound_pairs, 500u);
    EXPECT_GT(compound_visits, 5);    // visits of more than one shape of a body
    EXPECT_GT(body_pairs_kept, 50u);  // pairs of bodies touching by more than one pair of shapes
  }
}

// A shape's centre is the body's position plus its offset turned by the body's angle, to rounding
// (against the same composed in 50 digits), and its world angle is the body's plus its own, to the
// bit; a shape at the origin with no angle takes the body's pose as it is.
TEST(WorldShapes, ShapesArePlacedInTheirBodysFrame) {
  using reference::Real;
  Rng rng(52);
  World world;
  double worst = 0.0;
  for (int k = 0; k < 500; ++k) {
    const std::vector<ShapeDef> defs = {{.shape = local_shape(rng)}, {.shape = Rect{Vec2::Zero(), Vec2(1, 2), 0.0}}};
    const BodyId id = world.add(Pose{uniform_point(rng, -50, 50), 0.0}, defs);
    const Vec2 position = uniform_point(rng, -1e3, 1e3);
    const double angle = uniform(rng, -10, 10);
    world.move_to(id, position, angle);
    const std::vector<ShapeId> shapes = world.shapes(id);
    const Shape& placed = world.shape(shapes[0]);
    const Vec2 offset = center_of(defs[0].shape);
    const Real c = cos(Real(angle)), s = sin(Real(angle));
    const Real x = Real(position.x()) + c * offset.x() - s * offset.y();
    const Real y = Real(position.y()) + s * offset.x() + c * offset.y();
    const double error =
        std::hypot(center_of(placed).x() - static_cast<double>(x), center_of(placed).y() - static_cast<double>(y));
    worst = std::max(worst, error / position.norm());
    if (!std::holds_alternative<Circle>(placed)) EXPECT_EQ(angle_of(placed), angle + angle_of(defs[0].shape));
    EXPECT_EQ(center_of(world.local_shape(shapes[0])), offset);
    EXPECT_EQ(reach_of(world.local_shape(shapes[0])), reach_of(defs[0].shape));
    const Shape& at_origin = world.shape(shapes[1]);
    EXPECT_EQ(center_of(at_origin), position);
    EXPECT_EQ(angle_of(at_origin), angle);
  }
  EXPECT_LT(worst, 4 * std::numeric_limits<double>::epsilon());
}

// Ships of four shapes as bodies of four shapes, and as four bodies of one shape posed by hand with
// placed() (one negative group a ship, so that a ship's shapes do not pair): the same pairs of
// ships' shapes every frame.
TEST(WorldShapes, ABodyOfSeveralShapesPairsAsItsShapesPosedByHand) {
  Rng rng(53);
  const Shape ship[] = {Ellipse{Vec2(0, 0), 0.8, 0.3, 0.0}, Rect{Vec2(0, 0.6), Vec2(0.25, 0.4), 0.3},
                        Circle{Vec2(0.9, 0), 0.25}, Rect{Vec2(-0.7, 0), Vec2(0.3, 0.2), 0.0}};
  std::vector<ShapeDef> defs;
  for (const Shape& s : ship) defs.push_back({.shape = s});
  World compound, lockstep;
  std::vector<Pose> poses;
  std::vector<BodyId> bodies, parts;
  for (int k = 0; k < 300; ++k) {
    poses.push_back({uniform_point(rng, 0, 25), uniform(rng, -3, 3)});
    bodies.push_back(compound.add(poses.back(), defs));
    for (const Shape& s : ship)
      parts.push_back(
          lockstep.add(placed(s, poses.back(), Orientation::of(poses.back().angle)), {.filter = {.group = -(k + 1)}}));
  }
  std::size_t pairs = 0;
  for (int frame = 0; frame < 30; ++frame) {
    for (std::size_t k = 0; k < poses.size(); ++k) {
      poses[k].position += uniform_point(rng, -0.2, 0.2);
      poses[k].angle += uniform(rng, -0.1, 0.1);
      compound.move_to(bodies[k], poses[k].position, poses[k].angle);
      const Orientation turn = Orientation::of(poses[k].angle);
      for (std::size_t j = 0; j < 4; ++j) {
        const Shape s = placed(ship[j], poses[k], turn);
        lockstep.set_pose(parts[4 * k + j], center_of(s), angle_of(s));
      }
    }
    compound.update();
    lockstep.update();
    // Both as (ship, part, ship, part); a body's shapes are listed in the order added.
    std::vector<std::array<std::uint32_t, 4>> got, expected;
    for (const ShapePair& p : compound.overlapping()) {
      const auto part = [&](BodyId b, ShapeId s) {
        const std::vector<ShapeId> shapes = compound.shapes(b);
        return static_cast<std::uint32_t>(std::find(shapes.begin(), shapes.end(), s) - shapes.begin());
      };
      got.push_back({p.a.index, part(p.a, p.shape_a), p.b.index, part(p.b, p.shape_b)});
    }
    for (const ShapePair& p : lockstep.overlapping())
      expected.push_back({p.a.index / 4, p.a.index % 4, p.b.index / 4, p.b.index % 4});
    std::sort(got.begin(), got.end());
    std::sort(expected.begin(), expected.end());
    ASSERT_EQ(got, expected) << "frame " << frame;
    pairs += got.size();
  }
  EXPECT_GT(pairs, 1000u);
}

// A continuous body of two shapes swept past a wall and a post: one impact per pair of bodies, the
// earliest of its shapes' pairs, naming the shapes that meet, as time_of_impact finds each pair.
TEST(WorldShapes, ImpactsKeepEachPairOfBodiesEarliest) {
  World world;
  const ShapeDef twin[] = {{.shape = Circle{Vec2(0, 1), 0.25}, .user_id = 1},
                           {.shape = Rect{Vec2(0.5, -1), Vec2(0.25, 0.25), 0.0}, .user_id = 2}};
  const BodyId bullet = world.add(Pose{Vec2(0, 0), 0.0}, twin);
  const BodyId wall = world.add(Rect{Vec2(10, 0), Vec2(0.1, 5), 0.0}, {.is_static = true});
  const BodyId post = world.add(Circle{Vec2(6, -1), 0.3});
  world.set_continuous(bullet);
  const std::vector<ShapeId> parts = world.shapes(bullet);
  const std::vector<Shape> start = {world.shape(parts[0]), world.shape(parts[1])};
  world.move_to(bullet, Vec2(20, 0), 0.0);
  world.update();
  ASSERT_EQ(world.impacts().size(), 2u);
  for (const Impact& i : world.impacts()) {
    const BodyId other = i.a == bullet ? i.b : i.a;
    const ShapeId mine = i.a == bullet ? i.shape_a : i.shape_b;
    double earliest = 2.0;
    ShapeId first;
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const Shape& end = world.shape(parts[k]);
      const Motion m{center_of(end) - center_of(start[k]), 0.0};
      const TimeOfImpact r = time_of_impact(start[k], m, world.shape(other), Motion{});
      if (r.status == ToiStatus::hit && r.t < earliest) earliest = r.t, first = parts[k];
    }
    EXPECT_EQ(i.t, earliest);
    EXPECT_EQ(mine, first);
  }
  EXPECT_EQ(world.impacts()[0].b == post ? world.impacts()[0].shape_a : world.impacts()[1].shape_a, parts[1]);
  EXPECT_TRUE(world.impacts()[0].b == wall || world.impacts()[1].b == wall);
}

// The queries' lists hold each body once; their callbacks and the rays name each shape.
TEST(WorldShapes, QueriesReportBodiesAndShapes) {
  World world;
  const ShapeDef pair[] = {{.shape = Circle{Vec2(-1, 0), 0.5}}, {.shape = Circle{Vec2(1, 0), 0.5}}};
  const BodyId twin = world.add(Pose{Vec2(0, 0), 0.0}, pair);
  const BodyId other = world.add(Circle{Vec2(0, 3), 0.5});
  const Shape probe = Rect{Vec2(0, 0), Vec2(2, 4), 0.0};
  EXPECT_EQ(world.overlapping(probe), (std::vector<BodyId>{twin, other}));
  std::vector<ShapeId> seen;
  world.overlapping(probe, [&](const BodyShape& found) {
    EXPECT_EQ(world.body(found.shape), found.body);
    seen.push_back(found.shape);
    return true;
  });
  std::sort(seen.begin(), seen.end());
  std::vector<ShapeId> all = world.shapes(twin);
  all.push_back(world.shapes(other)[0]);
  EXPECT_EQ(seen, all);
  const std::vector<RayHit> hits = world.ray_cast_all(Vec2(-5, 0), Vec2(1, 0), 10.0);
  ASSERT_EQ(hits.size(), 2u);
  EXPECT_EQ(hits[0].shape, world.shapes(twin)[0]);
  EXPECT_EQ(hits[1].shape, world.shapes(twin)[1]);
  EXPECT_EQ(hits[0].distance, 3.5);
  EXPECT_EQ(hits[1].distance, 5.5);
  const auto cast = world.cast(Circle{Vec2(5, 0), 0.5}, Vec2(-5, 0));
  ASSERT_TRUE(cast.has_value());
  EXPECT_EQ(cast->shape, world.shapes(twin)[1]);
  EXPECT_LE(cast->fraction, 0.6);  // just before contact, within the time of impact's tolerance
  EXPECT_GT(cast->fraction, 0.6 - 1e-9);
}

TEST(WorldShapes, BadCallsAreRefusedAndChangeNothing) {
  World world;
  const ShapeDef one[] = {{.shape = Circle{Vec2(0, 0), 1}}};
  const BodyId body = world.add(Pose{Vec2(1, 2), 0.5}, one);
  const ShapeId only = world.shapes(body)[0];
  const auto message = [](auto call) -> std::string {
    try {
      call();
    } catch (const std::exception& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message([&] { world.remove_shape(only); }),
            "remove_shape: shape " + std::to_string(only.index) + " is its body's last; remove the body instead");
  EXPECT_EQ(message([&] { world.add(Pose{}, std::span<const ShapeDef>()); }),
            "add needs at least one shape for the body");
  const ShapeDef bad[] = {{.shape = Circle{Vec2(0, 0), 1}}, {.shape = Circle{Vec2(0, 0), -1}}};
  EXPECT_EQ(message([&] { world.add(Pose{}, bad); }), "circle radius must be positive (got -1)");
  EXPECT_EQ(message([&] {
              world.add(Pose{Vec2(std::nan(""), 0), 0}, one);
            }),
            "add position x must be finite (got nan)");
  EXPECT_EQ(message([&] { world.add_shape(body, bad[1]); }), "circle radius must be positive (got -1)");
  EXPECT_EQ(message([&] { world.set_local_shape(only, bad[1].shape); }), "circle radius must be positive (got -1)");
  EXPECT_EQ(world.size(), 1u);
  EXPECT_EQ(world.shapes(body), std::vector<ShapeId>{only});
  EXPECT_EQ(center_of(world.shape(only)), Vec2(1, 2));
  const ShapeId second = world.add_shape(body, {.shape = Rect{Vec2(1, 0), Vec2(1, 1), 0.0}});
  world.remove_shape(second);
  EXPECT_EQ(message([&] { world.set_sensor(second, true); }),
            "stale shape " + std::to_string(second.index) + " (generation " + std::to_string(second.generation) +
                "): that shape was removed; its slot is at generation " + std::to_string(second.generation + 1));
  EXPECT_THROW(world.user_id(ShapeId{99, 1}), std::out_of_range);
  world.remove(body);
  EXPECT_FALSE(world.contains(only));
}

}  // namespace
}  // namespace collide2d
