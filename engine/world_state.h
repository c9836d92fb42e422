// Private: the World's state and its work, behind the public World (include/collide2d/world.h).
// Its functions live by concern: bodies.cpp (storage, ids, poses, kinds), update.cpp (the broad
// phase, the narrow phase's chunks and batches), sensors.cpp, continuous.cpp (steps and impacts) and
// queries.cpp.
//
// A body is a pose and a list of shapes; each shape (a ShapeEntry, named by a ShapeId) is what the broad
// and the narrow phase work on. A shape keeps itself where it is in the world, and the cosine and
// sine of its world angle (as Box2D keeps b2Rot), from its body's last pose: its pairs' overlap
// tests and contacts use them and skip the validation done when it was posed. A shape placed at its
// body's origin with no angle of its own takes the body's pose as it is, so that a body of one shape
// added as a shape is posed to the bit as that shape alone.
// With a proximity or speculative margin m, the broad-phase boxes are the shapes' boxes grown by
// m / 2 (two shapes within m have boxes within m on each axis). A candidate pair's tight boxes must
// meet before its overlap test: that settles the pairs the fat margin alone brought in, and makes
// every reported overlap one whose boxes meet, so that a kernel's rounding (u times a needle's
// length) never reports a pair a box test excludes.
//
// Static bodies' shapes live in a tree of their own (AabbTree) instead of the sweep and prune, so a
// level of 100,000 of them costs its insertion once and not a sort every frame. Each moving shape
// keeps the static shapes near its fat box (within half the box's larger side) and looks them up
// again only when the fat box leaves that neighbourhood or the statics changed. Either tree is
// rebuilt top-down at an update when a quarter or more of its shapes were added since the last
// rebuild. The moving shapes' tree serves queries alone (the sweep and prune finds their pairs), so
// the World's first query builds it, and a World never queried holds none. It is not re-shaped as
// they move: the leaves whose fat box changed take their new box and their ancestors are refitted
// (re-inserting each moved leaf, as Box2D does, costs far more), and it is rebuilt once its inner
// perimeters have grown 1.5 times since the last rebuild. Between set_pose() and update(), queries
// test the shapes moved out of their fat box one by one.
#pragma once

#include <collide2d/aabb_tree.h>
#include <collide2d/broad_phase.h>
#include <collide2d/chain.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>

#include "engine/internal.h"
#include "engine/pages.h"
#include "engine/thread_pool.h"
#include "narrowphase/internal.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace collide2d::detail {

class WorldState {
 public:
  explicit WorldState(const WorldOptions& options);

  // bodies.cpp
  BodyId add(const Pose& pose, std::span<const ShapeDef> shapes, const BodyDef& def);
  BodyId add_chain(std::span<const Vec2> points, bool loop, const ChainDef& def);
  ShapeId add_shape(BodyId id, const ShapeDef& def);
  void remove_shape(ShapeId id);
  void set_pose(BodyId id, const Vec2& position, double angle);
  void move_to(BodyId id, const Vec2& position, double angle);
  void move_by(BodyId id, const Vec2& shift, double turn);
  void set_static(BodyId id, bool is_static);
  void set_filter(BodyId id, const Filter& filter);
  void set_filter(ShapeId id, const Filter& filter);
  void set_sensor(ShapeId id, bool sensor);
  void set_local_shape(ShapeId id, const Shape& local);
  void set_pair_predicate(std::function<bool(BodyId, BodyId)> predicate);
  void remove(BodyId id);
  void set_proximity_margin(double margin);
  bool contains(BodyId id) const;
  bool contains(ShapeId id) const;
  std::size_t size() const { return live_; }
  unsigned threads() const { return pool_->threads(); }
  Pose pose(BodyId id) const { return body(id).pose(); }
  const Shape& shape(BodyId id) const { return entries_[body(id).first].shape; }
  std::uint64_t user_id(BodyId id) const { return body(id).user_id; }
  const Filter& filter(BodyId id) const { return body(id).filter; }
  bool is_static(BodyId id) const { return body(id).is_static; }
  bool is_sensor(BodyId id) const { return body(id).sensor; }
  bool is_continuous(BodyId id) const { return body(id).continuous; }
  bool is_ghost(BodyId id) const { return body(id).ghost; }
  bool overlap_areas() const { return overlap_areas_; }
  std::vector<ShapeId> shapes(BodyId id) const;
  const Shape& shape(ShapeId id) const { return entry(id).shape; }
  // A shape at its body's origin is its world shape moved there (at_origin()): only the others
  // keep theirs.
  Shape local_shape(ShapeId id) const {
    const ShapeEntry& p = entry(id);
    return p.at_origin ? placed_at(p.shape, Vec2::Zero(), 0.0) : locals_[p.local];
  }
  BodyId body_of(ShapeId id) const { return entry(id).body; }
  std::optional<ChainSegment> chain_segment(ShapeId id) const;
  std::uint64_t user_id(ShapeId id) const { return entry(id).user_id; }
  const Filter& filter(ShapeId id) const { return entry(id).filter; }
  bool is_sensor(ShapeId id) const { return entry(id).sensor; }
  std::vector<BodyId> bodies() const;

  // continuous.cpp
  void set_continuous(BodyId id, bool continuous);
  void set_ghost(BodyId id, bool ghost);

  // update.cpp
  void update();

  // bodies.cpp
  Vec2 displacement(BodyId id, const Vec2& point) const;

  // queries.cpp: the callback forms, on which world.cpp builds the others.
  void overlapping(const Shape& shape, FunctionRef<bool(const BodyShape&)> visit, const QueryFilter& filter) const;
  void overlapping(const Aabb& box, FunctionRef<bool(const BodyShape&)> visit, const QueryFilter& filter) const;
  void within(const Vec2& point, double distance, FunctionRef<bool(const BodyShape&)> visit,
              const QueryFilter& filter) const;
  void within(const Shape& shape, double distance, FunctionRef<bool(const BodyShape&)> visit,
              const QueryFilter& filter) const;
  void ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                FunctionRef<double(const RayHit&)> visit, const QueryFilter& filter, const RayOptions& options) const;
  void cast(const Shape& shape, const Vec2& translation, FunctionRef<double(const BodyCastHit&)> visit,
            const QueryFilter& filter, const CastOptions& options) const;
  void validate_mover(const Shape& mover, const MoverQuery& query) const;
  double cast_mover(const Shape& mover, const Vec2& translation, const MoverQuery& query) const;
  void collide_mover(const Shape& mover, FunctionRef<bool(const MoverPlane&)> visit, const MoverQuery& query) const;
  // A move's neighbourhood (move(), engine/mover/move.cpp): the solid shapes whose boxes meet `box`
  // and that `filter` lets through, so that the move's queries whose boxes lie within it walk no
  // tree.
  struct Nearby {
    Aabb box;
    std::vector<std::uint32_t> shapes;
  };
  void gather(const Aabb& box, const QueryFilter& filter, Nearby& out) const;
  // The same with the mover's kept orientation and its neighbourhood, nothing validated, and a
  // shape's exact contact with a shape of kept orientation.
  double cast_mover(const Shape& mover, const Orientation& turn, const Vec2& translation, const MoverQuery& query,
                    const Nearby* near = nullptr) const;
  void collide_mover(const Shape& mover, const Orientation& turn, FunctionRef<bool(const MoverPlane&)> visit,
                     const MoverQuery& query, const Nearby* near = nullptr) const;
  Contact contact_with(ShapeId id, const Shape& other, const Orientation& turn) const;

  // update.cpp
  std::vector<ShapePair> candidates() const;
  // bodies.cpp
  Aabb broad_box(ShapeId id) const;
  Aabb reach_box(ShapeId id) const { return broad_box(entry(id)); }

  // The results of the last update.
  std::vector<ShapePair> overlapping_;
  std::vector<ShapePair> began_;
  std::vector<ShapePair> ended_;
  std::vector<BodyPair> body_overlapping_;
  std::vector<BodyPair> body_began_;
  std::vector<BodyPair> body_ended_;
  std::vector<Proximity> proximity_;
  std::vector<BodyContact> contacts_;
  std::vector<Impact> impacts_;
  std::vector<SensorPair> sensing_;
  std::vector<SensorPair> sensor_began_;
  std::vector<SensorPair> sensor_ended_;
  std::vector<SensorVisit> body_sensing_;
  std::vector<SensorVisit> body_sensor_began_;
  std::vector<SensorVisit> body_sensor_ended_;
  FrameStats stats_;
  std::uint64_t updates_ = 0;  // update() calls so far

  // update.cpp
  std::span<const std::uint32_t> contacts_of(BodyId id) const;

 private:
  static constexpr std::uint32_t kNone = ~std::uint32_t{0};
  // A body: its pose, what it is, and its shapes as a list through ShapeEntry::next. The pose's
  // position and angle lie apart, where a Pose would pad its angle to 16 bytes.
  struct Body {
    Vec2 position = Vec2::Zero();
    double angle = 0.0;
    std::uint64_t user_id = 0;
    Filter filter;
    std::uint32_t generation = 1;
    bool alive = false;
    bool is_static = false;
    bool sensor = false;  // its shapes' default
    bool continuous = false;
    bool ghost = false;
    std::uint32_t first = kNone;  // its first shape
    std::uint32_t last = kNone;   // its last shape, where the next one joins
    std::uint32_t count = 0;      // its shapes
    // Its pose where each of its two latest runs of moves began, and the count of updates then
    // ([1] the latest): what displacement() reads, kept by its moves so that an update copies no pose.
    struct Moved {
      std::uint64_t after = ~std::uint64_t{0};
      Pose from;
    };
    std::array<Moved, 2> moved{};

    Pose pose() const { return {position, angle}; }
  };
  // A shape of a body, where the broad and the narrow phase work: what a pair's test and record read
  // first, together, then what posing and the broad phase keep. Its flags are bits and its place in
  // the broad phase one word, so that it fills 208 bytes.
  struct ShapeEntry {
    Shape shape;              // where it is in the world
    Aabb box;                 // aabb(shape), kept with the pose
    Orientation orientation;  // of the shape's world angle, kept with the pose
    Filter filter;
    bool sensor : 1 = false;
    bool is_static : 1 = false;   // its body's kind, kept here for the pair loops
    bool continuous : 1 = false;  // its body's
    bool ghost : 1 = false;       // its body's
    bool chain : 1 = false;       // a chain's segment, its ghosts in ghosts_
    bool alive : 1 = false;
    bool at_origin : 1 = true;  // local centre and angle zero: the shape takes the body's pose as it is
    std::uint32_t generation = 1;
    BodyId body;                     // its body, whose handle and user id stay as they are while the shape lives
    std::uint32_t step = kNone;      // continuous: its place in continuous_
    std::uint32_t local = kNone;     // not at its body's origin: its shape in the body's frame in locals_
    std::uint32_t next = kNone;      // its body's next shape
    std::int32_t stale_at = -1;      // moving: its place in stale_leaves_ while its tree leaf is out of date
    std::uint64_t body_user_id = 0;  // kept here, as the handle, so that a record reads the shapes alone
    std::uint64_t user_id = 0;
    union {
      ProxyId proxy = 0;    // moving: its sweep-and-prune proxy
      AabbTree::Leaf leaf;  // static: its leaf in the static tree
    };
    std::uint32_t statics = kNone;  // moving: its static neighbours' list in static_lists_, if any,
    FloatBox queried = kNowhere;    // looked up in this box, kept in float (kNowhere: none yet)
  };
  // An empty box, which encloses no fat box: a shape entering the sweep and prune looks up its static
  // neighbours at the next update.
  static constexpr float kFar = std::numeric_limits<float>::infinity();
  static constexpr FloatBox kNowhere{{kFar, kFar}, {-kFar, -kFar}};

  // A candidate pair's overlap test, decided at once or left for the chunk's batch.
  enum class Verdict : std::uint8_t { skipped, apart, touching, batched };
  static constexpr std::size_t kPairsPerChunk = 256;
  // The pairs of one kind in a chunk, gathered for the batched overlap test (batch.h) as shape
  // indices, A's first. Each list holds a whole chunk from the start, so that no frame grows it.
  template <class A, class B>
  struct Batch {
    std::vector<std::uint32_t> places;  // in the chunk
    std::vector<std::uint32_t> a;
    std::vector<std::uint32_t> b;
    std::vector<std::uint8_t> verdicts;
    void add(std::uint32_t place, std::uint32_t a_part, std::uint32_t b_part);
    void run(const Pages<ShapeEntry>& parts, std::vector<Verdict>& chunk_verdicts);
    void clear();
  };
  template <class Pairs>
  struct BatchTuple;
  template <class... P>
  struct BatchTuple<std::tuple<P...>> {
    using type = std::tuple<Batch<typename P::First, typename P::Second>...>;
  };
  template <class Pairs>
  using BatchesOf = typename BatchTuple<Pairs>::type;
  // What the narrow phase found in one chunk of the candidate pairs; its overlapping pairs as shape
  // indices (a's body first), whose ids the join fills in. Each chunk's on cache lines of its own,
  // as each thread's scratch below: threads writing neighbouring records would pass the lines back
  // and forth on every pair.
  struct alignas(64) ChunkResults {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> overlapping;
    std::size_t first_pair = 0;  // where the join puts the first in frame_pairs_
    std::vector<SensorPair> sensing;
    std::vector<Proximity> proximity;
    std::vector<BodyContact> contacts;
    std::vector<Impact> impacts;
    std::size_t filtered = 0;
    void clear();
  };
  // A thread's scratch for the chunk it works on: each pair's verdict, and the batches. One for each
  // thread rather than each chunk, as a chunk needs it only while it runs.
  struct alignas(64) ChunkScratch {
    std::vector<Verdict> verdicts;
    BatchesOf<BatchedPairs<Kinds>> batches;  // one for each pair of kinds with a batch, in rank order
    void clear();
  };

  Pages<Body> bodies_;  // by BodyId::index
  std::vector<std::uint32_t> free_bodies_;
  std::size_t live_ = 0;
  Pages<ShapeEntry> entries_;  // by ShapeId::index
  std::vector<Shape> locals_;  // the shapes not at their body's origin, in its frame (ShapeEntry::local)
  std::vector<std::uint32_t> free_locals_;
  // The moving shapes' static neighbours (shape indices), a list for each shape that has some
  // (ShapeEntry::statics); a freed list keeps its room for the next.
  std::vector<std::vector<std::uint32_t>> static_lists_;
  std::vector<std::uint32_t> free_static_lists_;
  std::vector<std::uint32_t> free_entries_;
  std::vector<std::array<Vec2, 2>> ghosts_;  // by ShapeId::index, for a chain's segments: its ghosts
  SweepAndPrune broad_;                      // the moving shapes
  std::vector<std::uint32_t> part_of_;       // by sweep-and-prune proxy: its shape, or kNone
  // The moving shapes' fat boxes as of the last update (or of the first query, which builds it),
  // each shape's leaf by its proxy; built once under the mutex, as queries may run at once.
  mutable AabbTree moving_tree_;
  mutable std::vector<AabbTree::Leaf> moving_leaves_;
  mutable std::atomic<bool> moving_tree_on_{false};
  mutable std::mutex moving_tree_mutex_;
  mutable double moving_perimeter_ = 0.0;    // its inner boxes' perimeters right after its last rebuild
  std::vector<std::uint32_t> stale_leaves_;  // moving shapes whose fat box changed since the last update
  std::vector<std::pair<AabbTree::Leaf, Aabb>> tree_boxes_;  // refresh_moving_tree()'s, kept
  AabbTree static_tree_;                                     // the static shapes' broad-phase boxes
  bool statics_changed_ = false;
  double proximity_margin_;
  bool contacts_on_;
  double speculative_margin_;
  double contact_tolerance_;
  bool overlap_areas_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> candidates_;  // this update's, a's body < b's
  std::vector<ShapePair> frame_pairs_;  // the narrow phase's pairs joined: storage kept between frames
  std::vector<BodyPair> frame_body_pairs_;
  std::vector<SensorPair> sensed_;
  std::vector<SensorVisit> frame_visits_;
  // contacts_of(): body slot i's contacts are contact_list_[contact_start_[i], contact_start_[i + 1]).
  std::vector<std::uint32_t> contact_start_;
  std::vector<std::uint32_t> contact_list_;
  // A continuous body's shape and its pose at the last update, where its step begins: kept apart
  // from ShapeEntry, which the many shapes not continuous would otherwise carry it in.
  struct Step {
    std::uint32_t entry;
    Pose start;
  };
  std::vector<Step> continuous_;  // in the order the shapes became continuous
  std::function<bool(BodyId, BodyId)> pair_predicate_;
  std::vector<ChunkResults> chunks_;   // kept from frame to frame, so that steady state allocates nothing
  std::vector<ChunkScratch> scratch_;  // by the pool's worker
  std::unique_ptr<ThreadPool> pool_;

  // bodies.cpp
  Body& body(BodyId id);
  const Body& body(BodyId id) const;
  ShapeEntry& entry(ShapeId id);
  const ShapeEntry& entry(ShapeId id) const;
  BodyId body_id(std::uint32_t index) const { return {index, bodies_[index].generation}; }
  ShapeId shape_id(std::uint32_t index) const { return {index, entries_[index].generation}; }
  // The ids of shapes a and b (a's body < b's) as of now: handles and user ids.
  PairIds ids_of(std::uint32_t a, std::uint32_t b) const {
    const ShapeEntry& x = entries_[a];
    const ShapeEntry& y = entries_[b];
    return {x.body, y.body, shape_id(a), shape_id(b), x.body_user_id, y.body_user_id, x.user_id, y.user_id};
  }
  std::uint32_t new_entry(std::uint32_t body, const ShapeDef& def);
  void free_entry(std::uint32_t index);
  // A slot a shape holds (kNone: none) back among the free ones.
  static void release_slot(std::uint32_t& slot, std::vector<std::uint32_t>& free);
  void release_local(ShapeEntry& p);                       // its slot in locals_, if it has one
  std::vector<std::uint32_t>& static_list(ShapeEntry& p);  // its list in static_lists_, emptied or new
  void release_statics(ShapeEntry& p);                     // its list in static_lists_, if it has one
  Aabb broad_box(const Aabb& box) const;
  Aabb broad_box(const ShapeEntry& p) const;
  void enter(std::uint32_t index);
  void leave(std::uint32_t index);
  void refresh_box(std::uint32_t index);
  void place_body(Body& b, const Vec2& position, double angle, const char* call, bool teleport);
  void place_entry(std::uint32_t index, const Pose& at, const Orientation& turn);
  void set_local(std::uint32_t index, const Shape& local);
  void drop_stale(std::uint32_t index);
  bool passes(std::uint32_t a, std::uint32_t b) const;
  // A chain's segment where it is, with its ghosts.
  ChainSegment chain_of(std::uint32_t index) const {
    return {std::get<Segment>(entries_[index].shape), ghosts_[index][0], ghosts_[index][1]};
  }
  // The contact of shapes a and b, as of a chain's rules where either is a chain's segment.
  Contact pair_contact(std::uint32_t a, std::uint32_t b, const ContactOptions& options) const;
  // The overlap of shapes a and b with overlap areas on, all zero where they share no open region or
  // either is a segment: so that it reads the same with the pair turned (engine/distributed).
  OverlapArea pair_overlap(std::uint32_t a, std::uint32_t b) const;
  // f(index) for each shape of the body.
  template <class F>
  void each_entry(const Body& b, F f) const {
    for (std::uint32_t k = b.first; k != kNone; k = entries_[k].next) f(k);
  }

  // update.cpp
  void refresh_moving_tree();
  void need_moving_tree() const;  // queries.cpp
  void find_candidates();
  void narrow_phase();
  void narrow_chunk(std::size_t begin, std::size_t end, ChunkResults& out, ChunkScratch& scratch) const;
  Verdict overlap_verdict(std::uint32_t a, std::uint32_t b, ChunkResults& out, ChunkScratch& scratch) const;
  void narrow(std::uint32_t a, std::uint32_t b, bool touching, ChunkResults& out) const;
  void update_body_pairs();
  void index_contacts();

  // sensors.cpp
  void sense(std::uint32_t a, std::uint32_t b, bool touching, ChunkResults& out) const;
  void update_sensing(std::size_t chunks);
  // update.cpp: marks the ended pairs of shapes or bodies removed since the previous update.
  void mark_removed();

  // continuous.cpp: the shape's step, which starts where it is now; its step ended.
  void join_steps(std::uint32_t index);
  void leave_steps(std::uint32_t index);
  const Pose& start_of(const ShapeEntry& p) const { return continuous_[p.step].start; }
  void impact(std::uint32_t a, std::uint32_t b, ChunkResults& out) const;
  void keep_earliest_impacts();
  void begin_steps();

  // queries.cpp
  template <class Test>
  void each(const Aabb& box, const QueryFilter& filter, Test test, FunctionRef<bool(const BodyShape&)> visit,
            const Nearby* near = nullptr) const;
  // Throws std::logic_error naming `call` while a query's callback runs: the trees it walks must
  // stay as they are.
  void require_not_querying(const char* call) const;
  // Callback queries running (several threads may query at once).
  mutable std::atomic<int> querying_{0};
};

// Shared by the files of the World.
// Whether a shape placed in a body's frame sits at its origin with no angle of its own.
inline bool at_origin(const Shape& local) { return center_of(local) == Vec2::Zero() && angle_of(local) == 0.0; }
Aabb grown(const Aabb& box, double by);
// The box that holds every pose of a step from `start` to the shape `end` (continuous.cpp).
Aabb swept(const Pose& start, const Shape& end);

}  // namespace collide2d::detail
