// WorldOptions::overlap_areas: the overlap of each touching contact and sensor pair, against
// overlap_area() on the shapes the World holds and against constructions whose overlap is known
// exactly (a box half under a water line, circles wholly inside a sensor).
#include <collide2d/area.h>
#include <collide2d/world.h>
#include "world_testing.h"

#include <gtest/gtest.h>

#include <numbers>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace collide2d {
namespace {

using namespace testing;

bool has_area(const Shape& s) { return !std::holds_alternative<Segment>(s); }

// What the World should report for shapes a and b: overlap_area() where both are solids sharing an
// open region, all zero otherwise.
OverlapArea expected_overlap(const World& world, ShapeId a, ShapeId b) {
  const Shape& x = world.shape(a);
  const Shape& y = world.shape(b);
  if (!has_area(x) || !has_area(y)) return {};
  const OverlapArea o = overlap_area(x, y);
  return o.area > 0 ? o : OverlapArea{};
}

void expect_same(const OverlapArea& got, const OverlapArea& want, const std::string& what) {
  EXPECT_EQ(got.area, want.area) << what;
  EXPECT_EQ(got.centroid, want.centroid) << what;
  EXPECT_EQ(got.crossings, want.crossings) << what;
  EXPECT_EQ(got.chord[0], want.chord[0]) << what;
  EXPECT_EQ(got.chord[1], want.chord[1]) << what;
}

// A World of moving solids and sensors of every kind (capsules, sharp and rounded polygons, bodies
// of two shapes) over a floor chain: every touching contact carries its
// pair's overlap, every speculative one none, every sensor pair the sensor's overlap with its
// visitor, and every visit the sum over its pairs.
World busy_world(unsigned threads) {
  Rng rng(11);
  World world(
      {.fat_margin = 0.05, .contacts = true, .speculative_margin = 0.1, .threads = threads, .overlap_areas = true});
  for (int k = 0; k < 300; ++k) world.add(random_shape(rng, 12.0), {.sensor = k % 10 == 0});
  const Vec2 floor[] = {{-2, 0.9}, {-1, 0.5}, {6, 0.2}, {13, 0.6}, {14, 1.0}};
  world.add_chain(floor, false);
  const Vec2 corners[] = {{-0.4, -0.3}, {0.5, -0.2}, {0.3, 0.4}, {-0.3, 0.3}};
  const ShapeDef pair[] = {{.shape = Circle{Vec2(0, 0), 0.6}}, {.shape = Rect{Vec2(0.5, 0), Vec2(0.5, 0.3), 0.4}}};
  for (int k = 0; k < 20; ++k) {
    world.add(Pose{uniform_point(rng, 0, 12), 0.3}, pair);
    world.add(Capsule{uniform_point(rng, 0, 12), 0.5, 0.2, uniform(rng, 0, 6.3)}, {.sensor = k % 5 == 0});
    world.add(Pose{uniform_point(rng, 0, 12), uniform(rng, 0, 6.3)},
              std::span<const ShapeDef>({ShapeDef{.shape = ConvexPolygon::of(corners, k % 2 ? 0.1 : 0.0)}}));
  }
  return world;
}

TEST(WorldAreas, EachTouchingContactAndSensorPairCarriesItsOverlap) {
  World world = busy_world(1);
  Rng rng(3);
  std::size_t measured = 0, sensed = 0;
  for (int frame = 0; frame < 5; ++frame) {
    for (const BodyId id : world.bodies())
      if (!world.is_static(id)) world.move_by(id, uniform_point(rng, -0.1, 0.1), 0.05);
    world.update();
    const std::string what = "frame " + std::to_string(frame);
    for (const BodyContact& c : world.contacts()) {
      expect_same(c.overlap, c.touching ? expected_overlap(world, c.shape_a, c.shape_b) : OverlapArea{}, what);
      measured += c.overlap.area > 0;
    }
    for (const SensorPair& p : world.sensing()) {
      expect_same(p.overlap, expected_overlap(world, p.sensor_shape, p.visitor_shape), what);
      sensed += p.overlap.area > 0;
    }
    for (const SensorVisit& v : world.body_sensing()) {
      double area = 0;
      Vec2 moment = Vec2::Zero();
      for (const SensorPair& p : world.sensing()) {
        if (p.sensor_shape != v.sensor_shape || p.visitor != v.visitor) continue;
        area += p.overlap.area;
        moment += p.overlap.area * p.overlap.centroid;
      }
      EXPECT_EQ(v.area, area) << what;
      if (area > 0) EXPECT_EQ(v.centroid, Vec2(moment / area)) << what;
    }
    if (HasFailure()) return;
  }
  EXPECT_GT(measured, 50u);
  EXPECT_GT(sensed, 10u);
}

TEST(WorldAreas, SameForAnyThreadCount) {
  World one = busy_world(1), two = busy_world(2);
  one.update();
  two.update();
  ASSERT_EQ(one.contacts().size(), two.contacts().size());
  for (std::size_t k = 0; k < one.contacts().size(); ++k)
    expect_same(one.contacts()[k].overlap, two.contacts()[k].overlap, "contact " + std::to_string(k));
  EXPECT_EQ(one.state_hash(), two.state_hash());
}

// A 2 x 2 box whose centre sits on the water line of a wide sensor: half of it, 2, lies under the
// line, centred 0.5 below the box's centre. A box turned by a right angle is the same box.
TEST(WorldAreas, BoxHalfUnderWater) {
  World world({.overlap_areas = true});
  const BodyId water = world.add(Rect{Vec2(0, -5), Vec2(50, 5), 0.0}, {.sensor = true});
  const BodyId box = world.add(Rect{Vec2(3, 0), Vec2(1, 1), std::numbers::pi / 2});
  world.update();
  ASSERT_EQ(world.body_sensing().size(), 1u);
  const SensorVisit& v = world.body_sensing()[0];
  EXPECT_EQ(v.sensor, water);
  EXPECT_EQ(v.visitor, box);
  EXPECT_NEAR(v.area, 2.0, 1e-15);
  EXPECT_NEAR(v.centroid.x(), 3.0, 1e-15);
  EXPECT_NEAR(v.centroid.y(), -0.5, 1e-15);
  const OverlapArea& o = world.sensing()[0].overlap;
  EXPECT_EQ(o.crossings, 2);
  // The water's boundary enters the box at one end of the water line and leaves at the other.
  EXPECT_NEAR(std::abs(o.chord[0].x() - o.chord[1].x()), 2.0, 1e-15);
  EXPECT_NEAR(o.chord[0].y(), 0.0, 1e-15);
  EXPECT_NEAR(o.chord[1].y(), 0.0, 1e-15);
}

// A body of two circles, both wholly inside a sensor: its area is both circles' and its centroid
// their centres weighted by area.
TEST(WorldAreas, CompoundBodyInsideASensor) {
  World world({.overlap_areas = true});
  world.add(Circle{Vec2(0, 0), 10.0}, {.sensor = true});
  const ShapeDef two[] = {{.shape = Circle{Vec2(-2, 0), 1.0}}, {.shape = Circle{Vec2(3, 1), 2.0}}};
  world.add(Pose{Vec2(1, 1), 0.0}, two);
  world.update();
  ASSERT_EQ(world.body_sensing().size(), 1u);
  const SensorVisit& v = world.body_sensing()[0];
  const double pi = std::numbers::pi;
  EXPECT_NEAR(v.area, 5 * pi, 4e-15 * 5 * pi);
  EXPECT_NEAR(v.centroid.x(), (pi * -1 + 4 * pi * 4) / (5 * pi), 1e-14);
  EXPECT_NEAR(v.centroid.y(), (pi * 1 + 4 * pi * 2) / (5 * pi), 1e-14);
}

TEST(WorldAreas, OffByDefaultAndZeroWhereOnlyTouching) {
  World off({.contacts = true});
  off.add(Circle{Vec2(0, 0), 1.0});
  off.add(Circle{Vec2(1, 0), 1.0});
  off.add(Circle{Vec2(0, 0), 3.0}, {.sensor = true});
  off.update();
  ASSERT_EQ(off.contacts().size(), 1u);
  EXPECT_EQ(off.contacts()[0].overlap.area, 0.0);
  ASSERT_FALSE(off.body_sensing().empty());
  EXPECT_EQ(off.body_sensing()[0].area, 0.0);
  EXPECT_EQ(off.sensing()[0].overlap.area, 0.0);

  // Two unit boxes side by side touch along an edge and share no open region.
  World on({.contacts = true, .overlap_areas = true});
  on.add(Rect{Vec2(0, 0), Vec2(1, 1), 0.0});
  on.add(Rect{Vec2(2, 0), Vec2(1, 1), 0.0});
  on.update();
  ASSERT_EQ(on.contacts().size(), 1u);
  EXPECT_TRUE(on.contacts()[0].touching);
  expect_same(on.contacts()[0].overlap, OverlapArea{}, "touching boxes");
}

}  // namespace
}  // namespace collide2d
