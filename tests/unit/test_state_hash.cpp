// World::state_hash() against its definition in docs/world.md, computed here from the public lists
// in another way (every word first, then the fold); the same World on 1, 2 and 4 threads gives the
// same hashes frame by frame; a change of one pose by one ulp, or of one result, changes the hash.
#include <collide2d/world.h>
#include "world_testing.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace collide2d {
namespace {

using namespace testing;

// The words of docs/world.md's definition, in order.
class Words {
 public:
  std::vector<std::uint64_t> out;
  void real(double x) { out.push_back(std::bit_cast<std::uint64_t>(x)); }
  void point(const Vec2& p) { real(p.x()), real(p.y()); }
  void handle(std::uint32_t index, std::uint32_t generation) {
    out.push_back(static_cast<std::uint64_t>(generation) * 4294967296u + index);
  }
  void ids(const PairIds& p) {
    handle(p.a.index, p.a.generation), handle(p.b.index, p.b.generation);
    handle(p.shape_a.index, p.shape_a.generation), handle(p.shape_b.index, p.shape_b.generation);
  }
};

std::uint64_t hash_by_definition(const World& w) {
  Words s;
  s.out.push_back(w.bodies().size());
  for (const BodyId b : w.bodies()) {
    s.handle(b.index, b.generation);
    s.out.push_back(w.user_id(b));
    s.point(w.pose(b).position);
    s.real(w.pose(b).angle);
  }
  s.out.push_back(w.overlapping().size());
  for (const ShapePair& p : w.overlapping()) s.ids(p);
  s.out.push_back(w.proximity().size());
  for (const Proximity& p : w.proximity()) {
    s.ids(p), s.real(p.result.distance), s.point(p.result.point_a), s.point(p.result.point_b);
  }
  s.out.push_back(w.contacts().size());
  for (const BodyContact& c : w.contacts()) {
    s.ids(c), s.out.push_back(c.touching ? 1 : 0), s.real(c.contact.separation), s.point(c.contact.normal);
    s.point(c.contact.point_a), s.point(c.contact.point_b), s.out.push_back(c.contact.points().size());
    for (const ContactPoint& p : c.contact.points())
      s.point(p.point_a), s.point(p.point_b), s.real(p.separation), s.out.push_back(p.id);
  }
  s.out.push_back(w.impacts().size());
  for (const Impact& i : w.impacts()) s.ids(i), s.real(i.t), s.point(i.normal), s.point(i.point);
  s.out.push_back(w.sensing().size());
  for (const SensorPair& p : w.sensing()) {
    s.handle(p.sensor.index, p.sensor.generation), s.handle(p.visitor.index, p.visitor.generation);
    s.handle(p.sensor_shape.index, p.sensor_shape.generation),
        s.handle(p.visitor_shape.index, p.visitor_shape.generation);
  }
  std::uint64_t h = 14695981039346656037u;  // the FNV-1a offset basis
  for (const std::uint64_t word : s.out) {
    h = (h ^ word) * 1099511628211u;  // the FNV prime
    h ^= h >> 32;
  }
  return h;
}

// A World with every report on: proximity, contacts with a speculative margin, a bullet, a sensor.
World scene(unsigned threads, Rng& rng) {
  World w(
      {.fat_margin = 0.05, .proximity_margin = 0.3, .contacts = true, .speculative_margin = 0.1, .threads = threads});
  for (int k = 0; k < 150; ++k) w.add(random_shape(rng, 10.0), {.user_id = static_cast<std::uint64_t>(k + 1)});
  w.add(Circle{Vec2(0, 0), 3.0}, {.user_id = 500, .is_static = true, .sensor = true});
  w.set_continuous(w.add(Circle{Vec2(-12, 0), 0.1}, {.user_id = 600}));
  return w;
}

TEST(StateHash, FollowsItsDefinitionAndTheThreadCountChangesNothing) {
  std::vector<Rng> rngs(3, Rng(19));
  std::vector<World> worlds;
  for (const unsigned threads : {1u, 2u, 4u}) worlds.push_back(scene(threads, rngs[worlds.size()]));
  std::size_t sensed = 0, impacts = 0, contacts = 0;
  for (int frame = 0; frame < 30; ++frame) {
    for (std::size_t k = 0; k < worlds.size(); ++k) {
      Rng& rng = rngs[k];
      for (const BodyId id : worlds[k].bodies()) {
        if (worlds[k].is_static(id)) continue;
        const bool bullet = worlds[k].is_continuous(id);
        const double dx = uniform(rng, -0.1, 0.1), dy = uniform(rng, -0.1, 0.1);
        worlds[k].move_by(id, bullet ? Vec2(0.9, 0.0) : Vec2(dx, dy), 0.02);
      }
      worlds[k].update();
    }
    const std::uint64_t h = worlds[0].state_hash();
    ASSERT_EQ(h, hash_by_definition(worlds[0])) << "frame " << frame;
    ASSERT_EQ(worlds[1].state_hash(), h) << "frame " << frame;
    ASSERT_EQ(worlds[2].state_hash(), h) << "frame " << frame;
    sensed += worlds[0].sensing().size();
    impacts += worlds[0].impacts().size();
    contacts += worlds[0].contacts().size();
  }
  EXPECT_GT(sensed, 0u);
  EXPECT_GT(impacts, 0u);
  EXPECT_GT(contacts, 100u);
}

// One ulp of one pose changes the hash, before any update; so does an update that finds the pair.
TEST(StateHash, OneUlpOfOnePoseChangesIt) {
  World w;
  const BodyId a = w.add(Circle{Vec2(0, 0), 1.0});
  w.add(Circle{Vec2(3, 0), 1.0});
  w.update();
  const std::uint64_t before = w.state_hash();
  EXPECT_EQ(w.state_hash(), before);
  w.move_to(a, Vec2(std::nextafter(0.0, 1.0), 0), 0.0);
  const std::uint64_t moved = w.state_hash();
  EXPECT_NE(moved, before);
  w.move_to(a, Vec2(1, 0), 0.0);
  w.update();
  ASSERT_EQ(w.overlapping().size(), 1u);
  EXPECT_NE(w.state_hash(), moved);
  EXPECT_EQ(w.state_hash(), hash_by_definition(w));
}

}  // namespace
}  // namespace collide2d
