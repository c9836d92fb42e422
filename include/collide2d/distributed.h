// The World over MPI ranks (docs/distributed.md), built where Open MPI is found (the CMake target
// collide2d::distributed): space split into slabs along x, one per rank; each rank adds its own
// bodies by ids unique over all ranks, and every pair, contact, impact and sensor event of an update
// is reported by exactly one rank, so that the union over the ranks is what one World reports.
//
//   DistributedWorld world(MPI_COMM_WORLD, {.world = {.contacts = true}});
//   world.add(id, Circle{Vec2(x, y), r});       // this rank's bodies
//   world.update();                             // collective
//   for (const ShapePair& p : world.report().overlapping) ...  // this rank's share, by ids
#pragma once

#include <collide2d/partition.h>

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace collide2d {

/// How a DistributedWorld works; the same on every rank (the constructor checks).
struct DistributedOptions {
  WorldOptions world{};
  /// The slab bounds to start with, ranks - 1 of them, increasing; empty: 0 for two ranks, and for
  /// more, bounds 100 apart centred on 0.
  std::vector<double> bounds{};
  /// Frames between moves of the bounds to the bodies' distribution; 0: never.
  /// Each slab then holds about as many bodies. No result depends on the bounds.
  int rebalance_every = 0;
};

/// Two bodies by their ids, the lower first.
struct IdPair {
  std::uint64_t a = 0;
  std::uint64_t b = 0;
  friend auto operator<=>(const IdPair&, const IdPair&) = default;
};

/// A sensor and a body that overlaps it, by their ids.
struct IdSensorPair {
  std::uint64_t sensor = 0;
  std::uint64_t visitor = 0;
  friend auto operator<=>(const IdSensorPair&, const IdSensorPair&) = default;
};

/// What this rank's last update sent and held.
struct DistributedStats {
  std::size_t owned = 0;       ///< moving bodies this rank owns
  std::size_t ghosts = 0;      ///< copies of other ranks' bodies it holds
  std::size_t migrated = 0;    ///< bodies it handed to another rank
  std::size_t bytes_sent = 0;  ///< in the update's messages to other ranks
  double seconds = 0.0;        ///< the whole update, exchanges included
};

/// A World split over the ranks of an MPI communicator, one slab along x per rank (the file comment).
class DistributedWorld {
 public:
  /// Collective over `comm` (which MPI_Init made; this class never calls it). Throws
  /// std::invalid_argument where the options differ between ranks or the bounds do not fit the
  /// rank count.
  DistributedWorld(MPI_Comm comm, const DistributedOptions& options = {});
  ~DistributedWorld();
  DistributedWorld(const DistributedWorld&) = delete;
  DistributedWorld& operator=(const DistributedWorld&) = delete;

  /// Adds a body of one shape, which this rank owns until it migrates.
  /// It migrates at an update where its reach box's lower-left corner lies in another rank's slab.
  /// `id` is unique over all ranks: an update that finds one id handed to a rank twice throws
  /// std::logic_error on every rank (the bodies are then half exchanged: make a new
  /// DistributedWorld). A static body is copied to every rank at the next update. Throws
  /// std::invalid_argument for an id in use on this rank, and as World::add().
  void add(std::uint64_t id, const Shape& shape, const BodyDef& def = {}, bool continuous = false);
  /// Adds a chain of level geometry (World::add_chain()). Chains are replicated, not exchanged:
  /// every rank adds the same chains, under the same ids, in the same order.
  void add_chain(std::uint64_t id, std::span<const Vec2> points, bool loop, const ChainDef& def = {});
  /// Moves a body this rank owns (a continuous one sweeps there). Throws std::out_of_range for a
  /// body it does not own.
  void move_to(std::uint64_t id, const Vec2& position, double angle);
  /// Removes a body this rank owns.
  void remove(std::uint64_t id);
  /// Whether this rank owns the moving body, and the ids of the moving bodies it owns, sorted.
  bool owns(std::uint64_t id) const;
  std::vector<std::uint64_t> owned() const;
  /// A body this rank owns: its shape where it is.
  const Shape& shape(std::uint64_t id) const;
  /// Filters candidate pairs by the bodies' ids, as World::set_pair_predicate(): the same function
  /// of the two ids on every rank (the next update checks that every rank has one, or none).
  void set_pair_predicate(std::function<bool(std::uint64_t, std::uint64_t)> predicate);

  /// Collective: hands bodies that crossed into another slab to its rank, sends each moving body to
  /// every other slab its reach box meets as a ghost, updates this rank's World, and settles the
  /// pairs that began and ended with the ranks that reported them the frame before.
  void update();
  /// This rank's share of the last update (RegionReport), by ids.
  const RegionReport& report() const;
  /// The pairs this rank reported that began at the last update, and those that ended then.
  /// Ended: reported the update before, and no longer (also where a body was removed). The same
  /// for sensor pairs.
  const std::vector<IdPair>& began() const;
  const std::vector<IdPair>& ended() const;
  const std::vector<IdSensorPair>& sensor_began() const;
  const std::vector<IdSensorPair>& sensor_ended() const;

  /// Collective queries on the bodies where the last update left them; every rank gets the answer.
  /// The ids of the bodies whose solid shapes overlap the shape or meet the box, sorted; the
  /// first body a ray meets and its distance, or that a shape moved by `translation` meets and the
  /// fraction (the lowest id on a tie).
  std::vector<std::uint64_t> overlapping(const Shape& shape);
  std::vector<std::uint64_t> overlapping(const Aabb& box);
  std::optional<std::pair<std::uint64_t, double>> ray_cast(const Vec2& origin, const Vec2& direction,
                                                           double max_distance);
  std::optional<std::pair<std::uint64_t, double>> cast(const Shape& shape, const Vec2& translation);

  /// This rank's World: the bodies it owns, its ghosts, the statics and the chains.
  const World& world() const;
  int rank() const;
  int ranks() const;
  const Slabs& slabs() const;
  const DistributedStats& stats() const;
  /// Collective: the totals over the ranks of this update's report, as one World would count them.
  FrameStats totals();
  /// Collective: every rank's sensor pairs of the last update, sorted by ids.
  std::vector<IdSensorPair> sensing_everywhere();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace collide2d
