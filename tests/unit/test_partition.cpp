// A World split into slabs along x, one RegionWorld each, against the whole World over frames with
// churn: bodies added and removed, crossing boundaries back and forth, a body wider than a region,
// bodies on a boundary, filters, sensors, statics, and continuous bullets that cross several regions
// within one step. The regions' reports together must be the whole World's, record for record and
// value for value, with every slab count tried, one of the slabs empty; and ghosts never pair.
#include <collide2d/partition.h>
#include "contact_testing.h"
#include "split_scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

namespace collide2d {
namespace {

using testing::kSplitOptions;
using testing::SplitScene;

// Each body to the regions that hold it: its own (the slab of its reach box's lower-left corner)
// and, as a ghost, every other its reach box meets; a static body to every region, as its own.
void deal(const SplitScene& scene, const Slabs& slabs, std::vector<RegionWorld>& regions) {
  std::vector<std::vector<BodyRecord>> owned(regions.size()), ghosts(regions.size());
  for (const auto& [id, body] : scene.bodies) {
    const BodyRecord r = scene.record(id);
    if (r.is_static) {
      for (auto& list : owned) list.push_back(r);
      continue;
    }
    const Aabb reach = scene.world.reach_box(scene.world.shapes(body).front());
    const Aabb alone = reach_box(r.shape, r.continuous ? std::optional(r.start) : std::nullopt, kSplitOptions);
    EXPECT_EQ(alone.min, reach.min);  // the same box computed without the World
    EXPECT_EQ(alone.max, reach.max);
    const auto [first, last] = slabs.regions_of(reach);
    for (int k = first; k <= last; ++k) (k == first ? owned : ghosts)[static_cast<std::size_t>(k)].push_back(r);
  }
  for (std::size_t k = 0; k < regions.size(); ++k) regions[k].sync(owned[k], ghosts[k]);
}

template <class Record>
std::vector<std::pair<std::uint64_t, std::uint64_t>> ids(const std::vector<Record>& list) {
  std::vector<std::pair<std::uint64_t, std::uint64_t>> out;
  for (const Record& r : list) out.emplace_back(r.user_a, r.user_b);
  return out;
}

// A report's lists in one order whatever World made them: by ids, then (for the segments of one
// chain that meet the same body) by the values, which are the same to the bit.
void put_in_order(RegionReport& r) {
  const auto key = [](const auto& x, double value, const Vec2& point) {
    return std::tuple(x.user_a, x.user_b, value, point.x(), point.y());
  };
  const auto order = [](auto& list, auto by) {
    std::sort(list.begin(), list.end(), [&](const auto& p, const auto& q) { return by(p) < by(q); });
  };
  order(r.overlapping, [](const ShapePair& p) { return std::pair(p.user_a, p.user_b); });
  order(r.proximity, [&](const Proximity& p) { return key(p, p.result.distance, p.result.point_a); });
  order(r.contacts, [&](const BodyContact& c) { return key(c, c.contact.separation, c.contact.point_a); });
  order(r.impacts, [&](const Impact& i) { return key(i, i.t, i.point); });
  order(r.sensing, [](const SensorPair& p) { return std::pair(p.user_sensor, p.user_visitor); });
}

// The regions' reports joined against the whole World's, both in one order.
void expect_union(const std::vector<RegionWorld>& regions, RegionReport whole, const std::string& what) {
  RegionReport all;
  for (const RegionWorld& r : regions) {
    const RegionReport& m = r.report();
    all.overlapping.insert(all.overlapping.end(), m.overlapping.begin(), m.overlapping.end());
    all.proximity.insert(all.proximity.end(), m.proximity.begin(), m.proximity.end());
    all.contacts.insert(all.contacts.end(), m.contacts.begin(), m.contacts.end());
    all.impacts.insert(all.impacts.end(), m.impacts.begin(), m.impacts.end());
    all.sensing.insert(all.sensing.end(), m.sensing.begin(), m.sensing.end());
  }
  put_in_order(all);
  put_in_order(whole);
  ASSERT_EQ(ids(all.overlapping), ids(whole.overlapping)) << what;
  ASSERT_EQ(ids(all.proximity), ids(whole.proximity)) << what;
  for (std::size_t k = 0; k < all.proximity.size(); ++k) {
    const DistanceResult &x = all.proximity[k].result, &y = whole.proximity[k].result;
    EXPECT_EQ(x.distance, y.distance) << what;
    EXPECT_EQ(x.point_a, y.point_a) << what;
    EXPECT_EQ(x.point_b, y.point_b) << what;
  }
  ASSERT_EQ(ids(all.contacts), ids(whole.contacts)) << what;
  for (std::size_t k = 0; k < all.contacts.size(); ++k) {
    EXPECT_EQ(all.contacts[k].touching, whole.contacts[k].touching) << what;
    testing::expect_same_contact(all.contacts[k].contact, whole.contacts[k].contact, what);
  }
  ASSERT_EQ(ids(all.impacts), ids(whole.impacts)) << what;
  for (std::size_t k = 0; k < all.impacts.size(); ++k) {
    EXPECT_EQ(all.impacts[k].t, whole.impacts[k].t) << what;
    EXPECT_EQ(all.impacts[k].normal, whole.impacts[k].normal) << what;
    EXPECT_EQ(all.impacts[k].point, whole.impacts[k].point) << what;
  }
  ASSERT_EQ(all.sensing.size(), whole.sensing.size()) << what;
  for (std::size_t k = 0; k < all.sensing.size(); ++k) {
    EXPECT_EQ(all.sensing[k].user_sensor, whole.sensing[k].user_sensor) << what;
    EXPECT_EQ(all.sensing[k].user_visitor, whole.sensing[k].user_visitor) << what;
  }
}

TEST(Partition, RegionsTogetherReportTheWholeWorld) {
  const std::vector<std::vector<double>> layouts = {
      {}, {0.0}, {-7.0, 7.0}, {-10.0, 0.0, 10.0}, {-10.0, 0.0, 10.0, 60.0}};
  for (const std::vector<double>& bounds : layouts) {
    SplitScene scene;
    const Slabs slabs(bounds);
    std::vector<RegionWorld> regions;
    for (int k = 0; k < slabs.count(); ++k) {
      regions.emplace_back(kSplitOptions, slabs, k);
      regions.back().add_chain(scene.chain_id, scene.chain, false);
    }
    std::size_t pairs = 0, impacts = 0, sensing = 0, ghosts = 0;
    for (int frame = 0; frame < 16; ++frame) {
      if (frame > 0) scene.step();
      deal(scene, slabs, regions);
      scene.world.update();
      for (RegionWorld& r : regions) r.update();
      const RegionReport whole = whole_report(scene.world);
      expect_union(regions, whole, std::to_string(slabs.count()) + " slabs, frame " + std::to_string(frame));
      if (::testing::Test::HasFatalFailure()) return;
      pairs += whole.overlapping.size() + whole.proximity.size();
      impacts += whole.impacts.size();
      sensing += whole.sensing.size();
      for (const RegionWorld& r : regions) {
        for (const BodyId b : r.world().bodies()) ghosts += r.world().is_ghost(b) ? 1 : 0;
      }
    }
    // The scene exercises what it claims: pairs, bullets' impacts, sensors and, split, ghosts.
    EXPECT_GT(pairs, 500u);
    EXPECT_GT(impacts, 10u);
    EXPECT_GT(sensing, 5u);
    if (slabs.count() > 1) EXPECT_GT(ghosts, 100u);
    EXPECT_TRUE(regions.size() < 5 || regions[4].world().size() == scene.world.size() - [&] {
      std::size_t moving = 0;
      for (const auto& [id, b] : scene.bodies) moving += scene.world.is_static(b) ? 0 : 1;
      return moving;
    }()) << "the last slab holds the statics alone";
  }
}

TEST(Partition, GhostsNeverPairWithGhosts) {
  World world;
  const BodyId a = world.add(Circle{Vec2(0, 0), 1}, {.ghost = true});
  const BodyId b = world.add(Circle{Vec2(1, 0), 1}, {.ghost = true});
  const BodyId c = world.add(Circle{Vec2(-1, 0), 1});
  world.update();
  ASSERT_EQ(world.overlapping().size(), 2u);
  EXPECT_EQ(world.overlapping()[0].b, c);
  EXPECT_EQ(world.overlapping()[1].b, c);
  world.set_ghost(b, false);
  world.update();
  EXPECT_EQ(world.overlapping().size(), 3u);
  EXPECT_TRUE(world.is_ghost(a));
  EXPECT_FALSE(world.is_ghost(b));
}

TEST(Partition, SlabsRefuseBoundsOutOfOrder) {
  EXPECT_THROW(Slabs({1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(Slabs({0.0, NAN}), std::invalid_argument);
  EXPECT_THROW(RegionWorld(WorldOptions{}, Slabs({0.0}), 2), std::invalid_argument);
  const Slabs slabs({-1.0, 1.0});
  EXPECT_EQ(slabs.region_of(-1.0), 1);  // a bound belongs to the slab above it
  EXPECT_EQ(slabs.region_of(std::nextafter(-1.0, -2.0)), 0);
  EXPECT_EQ(slabs.region_of(1e300), 2);
  EXPECT_EQ(slabs.regions_of(Aabb{Vec2(-5, 0), Vec2(5, 1)}), std::pair(0, 2));
}

}  // namespace
}  // namespace collide2d
