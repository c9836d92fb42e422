// The World against an all-pairs narrow phase over many frames, its contacts and its records of the
// pairs, its handles, and its refusal of bad input.
#include <collide2d/world.h>
#include "world_testing.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace collide2d {
namespace {

using namespace testing;
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
        if (frame == 0) velocity[id.index] = uniform_point(rng, -0.1, 0.1);
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

// contacts_of() against a scan of contacts(): each body's contacts, in their order. normal_from()
// turns each normal away from the body asked about: the normal of the contact query with that
// body's shape first (with the World's margin and tolerance).
void expect_contacts_of_match_a_scan(const World& world, const ContactOptions& options, const std::string& what) {
  const std::vector<BodyContact>& all = world.contacts();
  for (const BodyId id : world.bodies()) {
    std::vector<std::uint32_t> scan;
    for (std::uint32_t k = 0; k < all.size(); ++k) {
      if (all[k].a == id || all[k].b == id) scan.push_back(k);
    }
    const std::span<const std::uint32_t> got = world.contacts_of(id);
    ASSERT_EQ(std::vector<std::uint32_t>(got.begin(), got.end()), scan) << what;
    for (const std::uint32_t k : got) {
      const BodyContact& c = all[k];
      const bool first = c.a == id;
      const Contact from_id =
          contact(world.shape(first ? c.shape_a : c.shape_b), world.shape(first ? c.shape_b : c.shape_a), options);
      ASSERT_EQ(normal_from(c, id), from_id.normal) << what;
    }
  }
}

// Contacts: off by default and then empty; on, exactly the overlapping pairs (and, with a
// speculative margin, the pairs whose contact separation is within it), each the contact the
// narrow phase gives for the pair with the World's margin and tolerance, in the order of
// overlapping(), over frames of motion.
TEST(World, ContactsMatchAllPairsWhenAskedFor) {
  int circle_ellipse = 0, loosened = 0;  // the contacts a tolerance moved off the exact ones
  for (const auto& [margin, tolerance] : {std::pair{0.0, 0.0}, std::pair{0.2, 0.0}, std::pair{0.2, 1e-3}}) {
    Rng rng(11);
    World world({.fat_margin = 0.05, .contacts = true, .speculative_margin = margin, .contact_tolerance = tolerance});
    World plain({.fat_margin = 0.05});
    for (int k = 0; k < 200; ++k) {
      const Shape s = random_shape(rng, 12.0);
      world.add(s);
      plain.add(s);
    }
    for (int frame = 0; frame < 20; ++frame) {
      for (const BodyId id : world.bodies()) {
        const Vec2 shift = uniform_point(rng, -0.1, 0.1);
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
          const Contact c = contact(a, b, {.margin = margin, .tolerance = tolerance});
          const bool touching = overlaps(a, b);
          loosened += tolerance > 0 && c.normal != contact(a, b, {.margin = margin}).normal;
          if (touching || (margin > 0 && c.separation <= margin)) {
            expected.push_back({ids[i], ids[j], world.shapes(ids[i])[0], world.shapes(ids[j])[0], world.user_id(ids[i]),
                                world.user_id(ids[j]), world.user_id(ids[i]), world.user_id(ids[j]), touching, c});
          }
        }
      }
      ASSERT_EQ(world.contacts().size(), expected.size()) << "frame " << frame;
      for (std::size_t k = 0; k < expected.size(); ++k) {
        const BodyContact& got = world.contacts()[k];
        ASSERT_EQ((BodyPair{got.a, got.b}), (BodyPair{expected[k].a, expected[k].b})) << "frame " << frame;
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
      expect_contacts_of_match_a_scan(world, {.margin = margin, .tolerance = tolerance},
                                      "frame " + std::to_string(frame));
      if (HasFatalFailure()) return;
      EXPECT_TRUE(plain.contacts_of(ids[0]).empty());
    }
    // A body removed since the update is refused; one that took its slot has no contacts yet.
    const BodyContact first = world.contacts().at(0);
    world.remove(first.a);
    const BodyId successor = world.add(Circle{Vec2(0, 0), 1.0});
    ASSERT_EQ(successor.index, first.a.index);
    EXPECT_THROW((void)world.contacts_of(first.a), std::out_of_range);
    EXPECT_TRUE(world.contacts_of(successor).empty());
    EXPECT_THROW((void)normal_from(first, successor), std::invalid_argument);
    EXPECT_GT(world.contacts().size(), world.overlapping().size() * (margin > 0 ? 1 : 0));
  }
  EXPECT_GT(circle_ellipse, 100);
  EXPECT_GT(loosened, 0);
  std::printf(
      "[measure] world contacts: %d circle-ellipse contacts checked, %d pair contacts off the exact at "
      "tolerance 1e-3\n",
      circle_ellipse, loosened);
}

// Every reported bit depends on the current poses and options alone: frame after frame of motion,
// a World updated from frame to frame reports what a World built from that frame's poses reports
// at its first update (static bodies, sensors, proximity and speculative contacts among them). The
// broad phase's counts (candidates, filtered) follow its fat boxes, which follow the motion: they
// are work done, not results, and may differ.
TEST(World, EveryFrameMatchesAWorldBuiltFromItsPoses) {
  const WorldOptions options{
      .fat_margin = 0.1, .proximity_margin = 0.3, .contacts = true, .speculative_margin = 0.1, .threads = 1};
  World warm(options);
  std::vector<BodyDef> defs;
  Rng rng(23);
  for (int k = 0; k < 600; ++k) {
    defs.push_back({.filter = {.group = k % 11 == 0 ? -1 : 0}, .is_static = k % 5 == 0, .sensor = k % 37 == 0});
    warm.add(random_shape(rng, 30.0), defs.back());
  }
  std::size_t contacts = 0, sensing = 0;
  for (int frame = 0; frame < 12; ++frame) {
    for (const BodyId id : warm.bodies()) {
      if (!warm.is_static(id)) warm.move_by(id, uniform_point(rng, -0.3, 0.3), 0.05);
    }
    warm.update();
    World cold(options);
    std::size_t k = 0;
    for (const BodyId id : warm.bodies()) cold.add(warm.shape(id), defs[k++]);
    cold.update();
    ASSERT_EQ(warm.overlapping(), cold.overlapping()) << frame;
    ASSERT_EQ(warm.sensing(), cold.sensing()) << frame;
    ASSERT_EQ(warm.proximity().size(), cold.proximity().size()) << frame;
    for (std::size_t i = 0; i < warm.proximity().size(); ++i) {
      const Proximity &w = warm.proximity()[i], &c = cold.proximity()[i];
      ASSERT_TRUE(w.a == c.a && w.b == c.b) << frame;
      ASSERT_EQ(w.result.distance, c.result.distance) << frame;
      ASSERT_EQ(w.result.point_a, c.result.point_a) << frame;
      ASSERT_EQ(w.result.point_b, c.result.point_b) << frame;
    }
    ASSERT_EQ(warm.contacts().size(), cold.contacts().size()) << frame;
    for (std::size_t i = 0; i < warm.contacts().size(); ++i) {
      const BodyContact &w = warm.contacts()[i], &c = cold.contacts()[i];
      ASSERT_TRUE(w.a == c.a && w.b == c.b && w.touching == c.touching) << frame;
      ASSERT_EQ(w.contact.separation, c.contact.separation) << frame;
      ASSERT_EQ(w.contact.normal, c.contact.normal) << frame;
      ASSERT_EQ(w.contact.point_a, c.contact.point_a) << frame;
      ASSERT_EQ(w.contact.point_b, c.contact.point_b) << frame;
      ASSERT_EQ(w.contact.manifold_size, c.contact.manifold_size) << frame;
      for (int m = 0; m < w.contact.manifold_size; ++m) {
        const ContactPoint &pw = w.contact.manifold[m], &pc = c.contact.manifold[m];
        ASSERT_TRUE(pw.point_a == pc.point_a && pw.point_b == pc.point_b) << frame;
        ASSERT_TRUE(pw.separation == pc.separation && pw.id == pc.id) << frame;
      }
    }
    contacts += warm.contacts().size();
    sensing += warm.sensing().size();
  }
  EXPECT_GT(contacts / 12, 100u);
  EXPECT_GT(sensing / 12, 5u);
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
  EXPECT_THROW(World({.contacts = true, .contact_tolerance = -1e-3}), std::invalid_argument);
  EXPECT_THROW(World({.contacts = true, .contact_tolerance = INFINITY}), std::invalid_argument);
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

}  // namespace
}  // namespace collide2d
