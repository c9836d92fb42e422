// Private: the World's state and its work, behind the public World (include/collide2d/world.h).
// Its functions live by concern: bodies.cpp (storage, ids, poses, kinds), update.cpp (the broad
// phase, the narrow phase's chunks and batches), sensors.cpp, continuous.cpp (steps and impacts) and
// queries.cpp.
//
// Each body keeps the cosine and sine of its angle from its last pose (as Box2D keeps b2Rot), and
// its pairs' overlap tests and contacts use them and skip the validation done when it was posed.
// With a proximity or speculative margin m, the broad-phase boxes are the shapes' boxes grown by
// m / 2 (two shapes within m have boxes within m on each axis). A candidate pair's tight boxes must
// meet before its overlap test: that settles the pairs the fat margin alone brought in, and makes
// every reported overlap one whose boxes meet, so that a kernel's rounding (u times a needle's
// length) never reports a pair a box test excludes.
//
// Static bodies live in a tree of their own (AabbTree) instead of the sweep and prune, so a level
// of 100,000 of them costs its insertion once and not a sort every frame. Each moving body keeps
// the static bodies near its fat box (within half the box's larger side) and looks them up again
// only when the fat box leaves that neighbourhood or the statics changed. Either tree is rebuilt
// top-down at an update when a quarter or more of its bodies were added since the last rebuild.
// The moving bodies' tree is not re-shaped as they move: the leaves whose fat box changed take
// their new box and their ancestors are refitted (re-inserting each moved leaf, as Box2D does,
// costs far more), and it is rebuilt once its inner perimeters have grown 1.5 times since the last
// rebuild. Between set_pose() and update(), queries test the bodies moved out of their fat box one
// by one.
#pragma once

#include <collide2d/aabb_tree.h>
#include <collide2d/broad_phase.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/world.h>

#include "engine/thread_pool.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

namespace collide2d::detail {

class WorldState {
 public:
  explicit WorldState(const WorldOptions& options);

  // bodies.cpp
  BodyId add(const Shape& shape, const BodyDef& def);
  void set_pose(BodyId id, const Vec2& position, double angle);
  void move_to(BodyId id, const Vec2& position, double angle);
  void move_by(BodyId id, const Vec2& shift, double turn);
  void set_static(BodyId id, bool is_static);
  void set_filter(BodyId id, const Filter& filter);
  void set_pair_predicate(std::function<bool(BodyId, BodyId)> predicate);
  void remove(BodyId id);
  void set_proximity_margin(double margin);
  bool contains(BodyId id) const;
  std::size_t size() const { return live_; }
  Pose pose(BodyId id) const { return {center_of(body(id).shape), body(id).angle}; }
  const Shape& shape(BodyId id) const { return body(id).shape; }
  std::uint64_t user_id(BodyId id) const { return body(id).user_id; }
  const Filter& filter(BodyId id) const { return body(id).filter; }
  bool is_static(BodyId id) const { return body(id).is_static; }
  bool is_sensor(BodyId id) const { return body(id).sensor; }
  bool is_continuous(BodyId id) const { return body(id).continuous; }
  std::vector<BodyId> bodies() const;

  // continuous.cpp
  void set_continuous(BodyId id, bool continuous);

  // update.cpp
  void update();

  // queries.cpp: the callback forms, on which world.cpp builds the others.
  void overlapping(const Shape& shape, FunctionRef<bool(BodyId)> visit, const QueryFilter& filter) const;
  void overlapping(const Aabb& box, FunctionRef<bool(BodyId)> visit, const QueryFilter& filter) const;
  void within(const Vec2& point, double distance, FunctionRef<bool(BodyId)> visit, const QueryFilter& filter) const;
  void within(const Shape& shape, double distance, FunctionRef<bool(BodyId)> visit, const QueryFilter& filter) const;
  void ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                FunctionRef<double(const RayHit&)> visit, const QueryFilter& filter, const RayOptions& options) const;
  void cast(const Shape& shape, const Vec2& translation, FunctionRef<double(const BodyCastHit&)> visit,
            const QueryFilter& filter, const CastOptions& options) const;

  // The results of the last update.
  std::vector<BodyPair> overlapping_;
  std::vector<BodyPair> began_;
  std::vector<BodyPair> ended_;
  std::vector<Proximity> proximity_;
  std::vector<BodyContact> contacts_;
  std::vector<Impact> impacts_;
  std::vector<SensorPair> sensing_;
  std::vector<SensorPair> sensor_began_;
  std::vector<SensorPair> sensor_ended_;
  FrameStats stats_;

 private:
  struct Body {
    Shape shape;
    Aabb box;                 // aabb(shape), kept with the pose
    Orientation orientation;  // of the shape's angle, kept with the pose
    double angle = 0.0;       // the body's, as posed (a circle's shape keeps none)
    std::uint64_t user_id = 0;
    Filter filter;
    std::uint32_t generation = 1;
    bool alive = false;
    bool is_static = false;
    bool sensor = false;
    bool continuous = false;
    ProxyId proxy = 0;                   // moving: its sweep-and-prune proxy
    AabbTree::Leaf leaf = -1;            // its leaf in the moving or the static tree
    std::int32_t loose = -1;             // moving: its place in loose_ while its tree leaf is out of date
    Aabb queried;                        // moving: the box its static neighbours were looked up in (kNowhere: none yet)
    std::vector<std::uint32_t> statics;  // moving: those neighbours (body indices)
    Shape start;                         // continuous: the pose at the last update, where the step begins
  };
  static constexpr std::uint32_t kNoBody = ~std::uint32_t{0};
  // An empty box, which encloses no fat box: a body entering the sweep and prune looks up its static
  // neighbours at the next update.
  static inline const Aabb kNowhere{Vec2::Constant(std::numeric_limits<double>::infinity()),
                                    Vec2::Constant(-std::numeric_limits<double>::infinity())};

  // A candidate pair's overlap test, decided at once or left for the chunk's batch.
  enum class Verdict : std::uint8_t { skipped, apart, touching, batched };
  static constexpr std::size_t kPairsPerChunk = 256;
  // The pairs of one kind in a chunk, gathered for the batched overlap test (batch.h) as body
  // indices, A's body first. Each list holds a whole chunk from the start, so that no frame grows it.
  template <class A, class B>
  struct Batch {
    std::vector<std::uint32_t> places;  // in the chunk
    std::vector<std::uint32_t> a;
    std::vector<std::uint32_t> b;
    std::vector<std::uint8_t> verdicts;
    void add(std::uint32_t place, std::uint32_t a_body, std::uint32_t b_body);
    void run(const std::vector<Body>& bodies, std::vector<Verdict>& chunk_verdicts);
    void clear();
  };
  // What the narrow phase found in one chunk of the candidate pairs, and its scratch: each pair's
  // verdict, and the batches.
  struct Found {
    std::vector<BodyPair> overlapping;
    std::vector<SensorPair> sensing;
    std::vector<Proximity> proximity;
    std::vector<BodyContact> contacts;
    std::vector<Impact> impacts;
    std::size_t filtered = 0;
    std::vector<Verdict> verdicts;
    std::tuple<Batch<Rect, Rect>, Batch<Rect, Circle>, Batch<Rect, Ellipse>, Batch<Circle, Circle>,
               Batch<Circle, Ellipse>, Batch<Ellipse, Ellipse>>
        batches;  // every pair kind, in kernel order
    void clear();
  };

  std::vector<Body> bodies_;  // by BodyId::index
  std::vector<std::uint32_t> free_;
  std::size_t live_ = 0;
  SweepAndPrune broad_;                 // the moving bodies
  std::vector<std::uint32_t> body_of_;  // by sweep-and-prune proxy: its body, or kNoBody
  AabbTree moving_tree_;                // the moving bodies' fat boxes as of the last update
  double moving_perimeter_ = 0.0;       // its inner boxes' perimeters right after its last rebuild
  std::vector<std::uint32_t> loose_;    // moving bodies whose fat box changed since the last update
  std::vector<std::pair<AabbTree::Leaf, Aabb>> tree_boxes_;  // refresh_moving_tree()'s, kept
  AabbTree static_tree_;                                     // the static bodies' broad-phase boxes
  bool statics_changed_ = false;
  double proximity_margin_;
  bool contacts_on_;
  double speculative_margin_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> candidates_;  // this update's, a < b
  std::vector<BodyPair> now_;  // the narrow phase's pairs joined: storage kept between frames
  std::vector<SensorPair> sensed_;
  std::vector<std::uint32_t> continuous_;  // the continuous bodies' indices
  std::function<bool(BodyId, BodyId)> pair_predicate_;
  std::vector<Found> chunks_;  // kept from frame to frame, so that steady state allocates nothing
  std::unique_ptr<ThreadPool> pool_;

  // bodies.cpp
  Body& body(BodyId id);
  const Body& body(BodyId id) const;
  BodyId id_of(std::uint32_t index) const { return {index, bodies_[index].generation}; }
  // The record of bodies a and b (a < b) as of now: handles and user ids.
  BodyPair pair_of(std::uint32_t a, std::uint32_t b) const {
    return {id_of(a), id_of(b), bodies_[a].user_id, bodies_[b].user_id};
  }
  Aabb broad_box(const Aabb& box) const;
  Aabb broad_box(const Body& b) const;
  void enter(std::uint32_t index);
  void leave(std::uint32_t index);
  void place(std::uint32_t index);
  void pose(Body& b, const Vec2& position, double angle, const char* call);
  void unloose(std::uint32_t index);
  bool passes(std::uint32_t a, std::uint32_t b) const;

  // update.cpp
  void refresh_moving_tree();
  void find_candidates();
  void narrow_phase();
  void narrow_chunk(std::size_t begin, std::size_t end, Found& out) const;
  Verdict overlap_verdict(std::uint32_t a, std::uint32_t b, Found& out) const;
  void narrow(std::uint32_t a, std::uint32_t b, bool touching, Found& out) const;

  // sensors.cpp
  void sense(std::uint32_t a, std::uint32_t b, bool touching, Found& out) const;
  void update_sensing(std::size_t chunks);
  // update.cpp: marks the ended pairs of bodies removed since the previous update.
  void mark_removed();

  // continuous.cpp
  void impact(std::uint32_t a, std::uint32_t b, Found& out) const;
  void begin_steps();

  // queries.cpp
  template <class Test>
  void each(const Aabb& box, const QueryFilter& filter, Test test, FunctionRef<bool(BodyId)> visit) const;
  // Throws std::logic_error naming `call` while a query's callback runs: the trees it walks must
  // stay as they are.
  void require_not_querying(const char* call) const;
  // Callback queries running (several threads may query at once).
  mutable std::atomic<int> querying_{0};
};

// Shared by the files of the World.
void require_finite(double value, const char* what);
void require_margin(double value, const char* what);
Aabb grown(const Aabb& box, double by);
// The box that holds every pose of a step from `start` to `end` (continuous.cpp).
Aabb swept(const Shape& start, const Shape& end);

}  // namespace collide2d::detail
