// A World split by regions of space (a domain decomposition), without any communication: what each
// process of a distributed run does with the bodies it is given (docs/distributed.md).
//
//   Slabs slabs({-10.0, 0.0, 10.0});            // four regions along x
//   RegionWorld region(options, slabs, 2);      // the region 0 <= x < 10
//   region.sync(records);                       // its bodies and ghosts, every frame
//   region.update();
//   const RegionReport& mine = region.report(); // the pairs this region reports
//
// A body belongs to the region that holds the lower-left corner of its reach box
// (World::reach_box()), and a region holds it as a ghost where its reach box meets the region
// otherwise. A pair is reported by the region that holds its owner point (owner_point()), where
// both of its bodies are held; each pair is reported by exactly one region, and the union of the
// regions' reports is the whole World's report, value for value.
#pragma once

#include <collide2d/world.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

namespace collide2d {

/// Space cut into slabs along x: region k holds bounds[k - 1] <= x < bounds[k], the first region
/// from -infinity, the last to +infinity.
class Slabs {
 public:
  /// `bounds` finite and increasing: bounds.size() + 1 regions. Throws std::invalid_argument.
  explicit Slabs(std::vector<double> bounds = {});
  /// `count` slabs that each hold about as many of the xs (not empty): bounds at their quantiles,
  /// a bound that would not rise above the one before it moved up by an ulp.
  static Slabs balanced(std::vector<double> xs, int count);
  int count() const { return static_cast<int>(bounds_.size()) + 1; }
  /// The region that holds x.
  int region_of(double x) const;
  /// The first and last region the box meets.
  std::pair<int, int> regions_of(const Aabb& box) const;
  const std::vector<double>& bounds() const { return bounds_; }

 private:
  std::vector<double> bounds_;
};

/// A body as each region that holds it sees it: one shape, and the caller's id, unique over all
/// regions (it is the body's user id in every region's World).
struct BodyRecord {
  std::uint64_t id = 0;
  Shape shape{};  ///< where it is now
  Pose start{};   ///< a continuous body's pose at the last update, where its step begins
  Filter filter{};
  bool is_static = false;
  bool sensor = false;
  bool continuous = false;
};

/// The pairs a region reports of one update: those whose owner point it holds. Each record names
/// its bodies by their ids (user_a < user_b; a record found the other way round is turned: its
/// points swapped, its normal negated) and is sorted by them (the segments of one chain that meet
/// the same body in the World's order); a sensor pair keeps its roles. The handles are the region
/// World's own.
struct RegionReport {
  std::vector<ShapePair> overlapping;
  std::vector<Proximity> proximity;
  std::vector<BodyContact> contacts;
  std::vector<Impact> impacts;
  std::vector<SensorPair> sensing;
};

/// One region's World: the bodies it owns and ghosts of the others that reach it, brought in step
/// with the records given each frame.
class RegionWorld {
 public:
  RegionWorld(const WorldOptions& options, Slabs slabs, int region);

  /// Makes the World hold exactly these bodies, where they are: `owned` as its own, `ghosts` as
  /// ghosts (BodyDef::ghost). A body new to the World is added at its step's start and moved on,
  /// so that a continuous one sweeps its whole step; one missing is removed. The same body in the
  /// same place in two regions' Worlds is the same to the bit.
  void sync(std::span<const BodyRecord> owned, std::span<const BodyRecord> ghosts);
  /// Adds a chain of level geometry (World::add_chain()) under the caller's id, outside sync():
  /// every region adds the same chains, replicated as static bodies are.
  BodyId add_chain(std::uint64_t id, std::span<const Vec2> points, bool loop, const ChainDef& def = {});
  /// A shape's place in its chain (0 for a shape of another body), which every region numbers alike.
  std::uint32_t part_of(ShapeId shape) const;
  /// A chain segment's reach box (it never changes), nullopt for a shape of another body.
  std::optional<Aabb> level_reach(ShapeId shape) const;
  /// Filters candidate pairs by the bodies' ids, the lower first; an empty function for none.
  /// As World::set_pair_predicate(), so that every region asks it the same question of a pair.
  void set_pair_predicate(std::function<bool(std::uint64_t, std::uint64_t)> predicate);
  /// The World's update, then its report.
  void update();
  const RegionReport& report() const { return report_; }
  const World& world() const { return world_; }
  /// The World's handle of a body it holds, by id; nullopt for one it does not hold.
  std::optional<BodyId> find(std::uint64_t id) const;
  const Slabs& slabs() const { return slabs_; }
  void set_slabs(Slabs slabs) { slabs_ = std::move(slabs); }

 private:
  // A body the World holds: its handles, and the last sync() that gave it.
  struct Held {
    BodyId body;
    ShapeId shape;
    std::uint64_t frame = 0;
  };
  void place(const BodyRecord& record, bool ghost);

  World world_;
  Slabs slabs_;
  int region_;
  std::uint64_t frame_ = 0;
  std::unordered_map<std::uint64_t, Held> bodies_;
  std::vector<BodyId> level_;                              // its chains
  std::unordered_map<std::uint32_t, std::uint32_t> part_;  // each chain segment's place, by slot
  std::vector<Aabb> reach_;                                // each shape's reach box for the update, by slot
  RegionReport report_;
};

/// The report of a whole World, as RegionWorld reports a region's: every pair, by ids. Reach boxes
/// are not needed for it; the union of the regions' reports equals it.
RegionReport whole_report(const World& world);

}  // namespace collide2d
