// The World: bodies that move every frame, the broad phase that finds candidate pairs, and the
// narrow phase that confirms them.
//
//   World world({.fat_margin = 0.1, .proximity_margin = 0.5});
//   BodyId id = world.add(Ellipse{Vec2(1, 2), 1.5, 0.4, 0.3}, {.user_id = 7});
//   world.add(Rect{Vec2(0, -1), Vec2(50, 1), 0.0}, {.is_static = true});  // the floor
//   world.add(Circle{Vec2(9, 0), 2.0}, {.sensor = true});                 // a trigger
//   world.set_pose(id, Vec2(1.1, 2.0), 0.35);          // or move_by(id, shift, turn)
//   world.update();                                   // once per frame
//   for (const BodyPair& p : world.overlapping()) ...  // confirmed overlaps; began()/ended() too
//   for (const Proximity& p : world.proximity()) ...   // apart but within the margin, with points
//   for (const BodyContact& c : world.contacts()) ...  // with contacts on: depth, normal, manifold
//
// Each body keeps the cosine and sine of its angle from its last pose (as Box2D keeps b2Rot), and its
// pairs' overlap tests and contacts use them and skip the shapes' validation (done when posed).
// What is computed is what was asked: each candidate pair from the broad phase whose tight boxes
// meet gets the overlap test only; a distance is computed only when a proximity margin is set, and
// only for candidate pairs that do not overlap; a contact (narrowphase/contact.h) only when contacts
// are switched on, for the overlapping pairs and, with a speculative margin, for the pairs whose
// tight boxes come within it. With a proximity or speculative margin m, the broad-phase boxes are
// the shapes' boxes grown by m / 2 (two shapes within m have boxes within m on each axis).
// The tight-box test settles the pairs that the fat margin alone brought in, and makes every
// reported overlap one whose boxes meet: a kernel's rounding (u times a needle's length) can then
// never report a pair that a box test excludes.
//
// Static bodies (BodyDef::is_static) are level geometry: never paired with each other, kept in a
// tree of their own (broadphase/aabb_tree.h) instead of the sweep and prune, so a level of 100,000
// of them costs its insertion once and not a sort every frame. Each moving body keeps the static
// bodies near its fat box (within half the box's larger side), and looks them up again only when
// the fat box leaves that neighbourhood or the statics changed: adding, removing, moving or
// re-kinding a static body costs one tree query per moving body at the next update. Either tree is
// rebuilt top-down at an update when a quarter or more of its bodies were added since the last
// rebuild (a level loaded, a wave spawned): queries then cost 2 to 10 times less than on the tree
// insertion builds (bench_queries). The moving bodies' tree is not re-shaped as they move: at each
// update the leaves whose fat box changed take their new box and their ancestors are refitted
// (re-inserting each moved leaf, as Box2D does, took 40% of a frame of 1,000 moving bodies), and
// the tree is rebuilt once its inner perimeters have grown 1.5 times since the last rebuild.
// Between set_pose() and update(), queries test the bodies moved out of their fat box one by one.
//
// Sensors (BodyDef::sensor) report the solid bodies that overlap them, in sensing() with began and
// ended lists of their own, and nothing else: a sensor never appears in the solid bodies' pairs,
// proximity, contacts, impacts or in queries, and sensors do not sense each other (Box2D v3's rules).
//
// Queries (each validates its input and returns body ids in increasing order) look up the boxes they
// meet in the moving bodies' tree and the static tree, then test the exact shapes: the bodies whose
// solid shape overlaps a shape or a box (the exact shape, not its bounding box), the bodies within
// a distance of a point or of a shape, and the bodies a ray hits, first or all (exact on circles and
// ellipses: the ray meets the curve, not a polygon). The sweep-and-prune strips are not used for
// them: a strip's endpoints answer "which boxes overlap along the sweep axis" well, but neither a
// ray nor a box far smaller than a strip, and a tree answers both in O(log n + hits).
//
// Continuous bodies (bullets): set_continuous(id) makes a body's step, from its pose at the last
// update to its pose now, count. Its broad-phase box covers the whole path (the segment between the
// two centres grown by the shape's farthest point, whatever it turns), and update() reports, for each
// of its candidate pairs that starts the step apart, the first time of impact within the step
// (narrowphase/time_of_impact.h; a body not flagged is taken at its current pose), in impacts():
// pair, time in [0, 1], normal from a to b, point. Bodies not flagged cost one flag test per pair.
// cast(shape, translation) is the shape cast against every body: the first hit, with its fraction,
// point and the body's outward normal.
//
// Filters (Filter, below): each body has one, and the World pairs two bodies only where
// should_pair() lets them and the pair predicate, if set, agrees (sensor pairs too); every query
// takes a QueryFilter.
//
// Errors: an invalid shape throws InvalidShape, a NaN or infinite pose, margin or query argument
// std::invalid_argument, an unknown body or a stale handle (its body removed) std::out_of_range,
// with a message that says which; the World is left exactly as it was.
#pragma once

#include <collide2d/aabb_tree.h>
#include <collide2d/broad_phase.h>
#include <collide2d/query.h>
#include <collide2d/time_of_impact.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

namespace collide2d {
namespace detail {
class ThreadPool;
}

// A body's handle: its slot in the World and the generation of that slot. remove() frees the slot
// for a later add() and moves its generation on, so a handle kept past remove() is refused with an
// error instead of reaching whichever body takes the slot next (as Box2D v3's b2BodyId does).
// Generations start at 1: a default BodyId{} names no body.
struct BodyId {
  std::uint32_t index = 0;
  std::uint32_t generation = 0;
  friend auto operator<=>(const BodyId&, const BodyId&) = default;
};

struct BodyPair {
  BodyId a;  // a.index < b.index
  BodyId b;
  friend auto operator<=>(const BodyPair&, const BodyPair&) = default;
};

// Which bodies may pair, with Box2D's semantics (b2Filter): two bodies of one non-zero group always
// pair when it is positive and never when it is negative; otherwise each one's category must meet
// the other's mask. The World checks it, and then the pair predicate if one is set, on every
// candidate pair before any narrow-phase work.
struct Filter {
  std::uint64_t category = 1;                   // the bits this body is
  std::uint64_t mask = ~std::uint64_t{0};       // the bits it pairs with
  std::int32_t group = 0;
  friend bool operator==(const Filter&, const Filter&) = default;
};
bool should_pair(const Filter& a, const Filter& b);

// Which bodies a query reports (Box2D v3's b2QueryFilter): those whose category meets the query's
// mask and whose mask meets the query's category. The default reports every body.
struct QueryFilter {
  std::uint64_t category = 1;
  std::uint64_t mask = ~std::uint64_t{0};
};

// What a body is, besides its shape.
struct BodyDef {
  std::uint64_t user_id = 0;
  Filter filter;
  bool is_static = false;  // level geometry: see the header comment
  bool sensor = false;     // reports what overlaps it, and is otherwise not solid
};

// A sensor and a solid body that overlaps it.
struct SensorPair {
  BodyId sensor;
  BodyId visitor;
  friend auto operator<=>(const SensorPair&, const SensorPair&) = default;
};

struct WorldOptions {
  double fat_margin = 0.0;        // broad-phase boxes grow by this, so small motions cost nothing
  double proximity_margin = 0.0;  // > 0: report non-overlapping pairs closer than this
  bool contacts = false;          // a contact for every overlapping pair (contacts())
  // With contacts: pairs apart by at most this get a contact too (speculative contacts, which let a
  // solver stop bodies before they meet); also the manifold margin of ContactOptions.
  double speculative_margin = 0.0;
  // Threads for update(), the calling one included; 0: every hardware thread. The sweep and prune's
  // strips and the narrow phase's chunks of candidate pairs run on them. The results are the same,
  // in the same order, for any count (the chunks are cut in order, each chunk's results kept apart,
  // then joined and sorted). With more than one thread the
  // pair predicate may be called from several threads at once.
  unsigned threads = 0;
};

struct Proximity {
  BodyId a;
  BodyId b;
  DistanceResult result;  // the distance and closest points, point_a on body a
};

struct BodyContact {
  BodyId a;  // a.index < b.index
  BodyId b;
  Contact contact;  // of a's shape with b's: the normal points from a to b
};

struct Impact {
  BodyId a;  // a.index < b.index
  BodyId b;
  double t = 0.0;              // the first time of contact within the step, in [0, 1]
  Vec2 normal = Vec2::UnitX();  // from a to b
  Vec2 point = Vec2::Zero();
};

struct BodyCastHit {
  BodyId body;
  double fraction = 0.0;        // of the translation, at the first contact
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::UnitX();  // the body's outward normal there, towards the cast shape
};

struct RayHit {
  BodyId body;
  double distance = 0.0;       // from the ray's origin to the hit point
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::Zero();  // outward unit normal of the body at the point (zero when the ray starts inside)
};

// What the last update did.
struct FrameStats {
  std::size_t candidates = 0;   // pairs from the broad phase
  std::size_t filtered = 0;     // of them, dropped by the filters or the pair predicate
  std::size_t overlapping = 0;  // confirmed by the narrow phase
  std::size_t proximity = 0;
  std::size_t contacts = 0;
  std::size_t impacts = 0;
  std::size_t sensing = 0;    // sensor pairs
  std::size_t requeried = 0;  // moving bodies whose static neighbours were looked up again
  double broad_seconds = 0.0;
  double narrow_seconds = 0.0;  // with the moving bodies' query tree, kept up to date alongside
};

class World {
 public:
  explicit World(const WorldOptions& options = {});
  ~World();
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;

  BodyId add(const Shape& shape, const BodyDef& def = {});
  // For a static body too, at the price the header comment gives.
  void set_pose(BodyId id, const Vec2& center, double angle);
  // A static body becoming moving or back; a continuous body stops being continuous when it
  // becomes static.
  void set_static(BodyId id, bool is_static);
  // Takes effect at the next update: pairs that no longer pass end there (ended()).
  void set_filter(BodyId id, const Filter& filter);
  // Called for the candidate pairs that pass both filters (a.index < b.index), before any
  // narrow-phase work; false drops the pair. An empty function passes every pair.
  void set_pair_predicate(std::function<bool(BodyId, BodyId)> predicate);
  void move_by(BodyId id, const Vec2& shift, double turn = 0.0);
  void remove(BodyId id);
  void set_proximity_margin(double margin);
  // A continuous body's step runs from its pose at the last update (or at this call) to its pose
  // at the next update. Static bodies cannot be continuous.
  void set_continuous(BodyId id, bool continuous = true);
  void update();

  bool contains(BodyId id) const;
  std::size_t size() const { return live_; }
  const Shape& shape(BodyId id) const;
  std::uint64_t user_id(BodyId id) const;
  const Filter& filter(BodyId id) const;
  bool is_static(BodyId id) const;
  bool is_sensor(BodyId id) const;
  std::vector<BodyId> bodies() const;

  // Results of the last update.
  const std::vector<BodyPair>& overlapping() const { return overlapping_; }
  const std::vector<BodyPair>& began() const { return began_; }
  const std::vector<BodyPair>& ended() const { return ended_; }
  const std::vector<Proximity>& proximity() const { return proximity_; }
  // With contacts on: the overlapping pairs and the speculative ones, sorted like overlapping().
  const std::vector<BodyContact>& contacts() const { return contacts_; }
  // The first times of impact of continuous bodies' pairs within the last step, sorted by pair.
  const std::vector<Impact>& impacts() const { return impacts_; }
  // Each sensor's visitors now, and those that entered or left at the last update; sorted.
  const std::vector<SensorPair>& sensing() const { return sensing_; }
  const std::vector<SensorPair>& sensor_began() const { return sensor_began_; }
  const std::vector<SensorPair>& sensor_ended() const { return sensor_ended_; }
  const FrameStats& last_frame() const { return stats_; }

  // Queries on the current poses (no update needed), over the bodies the filter lets through.
  std::vector<BodyId> overlapping(const Shape& shape, const QueryFilter& filter = {}) const;
  std::vector<BodyId> overlapping(const Aabb& box, const QueryFilter& filter = {}) const;
  std::vector<BodyId> within(const Vec2& point, double distance, const QueryFilter& filter = {}) const;
  std::vector<BodyId> within(const Shape& shape, double distance, const QueryFilter& filter = {}) const;
  // The first body hit by the ray from `origin` along `direction` (any non-zero length) within
  // `max_distance` of the origin; a body containing the origin is hit at distance 0.
  std::optional<RayHit> ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                                 const QueryFilter& filter = {}) const;
  // Every body the ray hits within `max_distance`, nearest first (by body index on a tie).
  std::vector<RayHit> ray_cast_all(const Vec2& origin, const Vec2& direction, double max_distance,
                                   const QueryFilter& filter = {}) const;
  // The first body the shape meets when translated by `translation` (the lowest body index on a
  // tie); a body it overlaps at the start is hit at fraction 0.
  std::optional<BodyCastHit> cast(const Shape& shape, const Vec2& translation, const QueryFilter& filter = {}) const;

 private:
  struct Body {
    Shape shape;
    Aabb box;                 // aabb(shape), kept with the pose
    Orientation orientation;  // of the shape's angle, kept with the pose
    std::uint64_t user_id = 0;
    Filter filter;
    std::uint32_t generation = 1;
    bool alive = false;
    bool is_static = false;
    bool sensor = false;
    bool continuous = false;
    ProxyId proxy = 0;          // moving: its sweep-and-prune proxy
    AabbTree::Leaf leaf = -1;   // its leaf in the moving or the static tree
    std::int32_t loose = -1;    // moving: its place in loose_ while its tree leaf is out of date
    Aabb queried;               // moving: the box its static neighbours were looked up in (kNowhere: none yet)
    std::vector<std::uint32_t> statics;  // moving: those neighbours (body indices)
    Shape start;  // continuous: the pose at the last update, where the step begins
  };
  static constexpr std::uint32_t kNoBody = ~std::uint32_t{0};
  // An empty box, which encloses no fat box: a body entering the sweep and prune looks up its static
  // neighbours at the next update.
  static inline const Aabb kNowhere{Vec2::Constant(std::numeric_limits<double>::infinity()),
                                    Vec2::Constant(-std::numeric_limits<double>::infinity())};

  std::vector<Body> bodies_;  // by BodyId::index
  std::vector<std::uint32_t> free_;
  std::size_t live_ = 0;
  SweepAndPrune broad_;                 // the moving bodies
  std::vector<std::uint32_t> body_of_;  // by sweep-and-prune proxy: its body, or kNoBody
  AabbTree moving_tree_;                // the moving bodies' fat boxes as of the last update
  double moving_perimeter_ = 0.0;       // its inner boxes' perimeters right after its last rebuild
  std::vector<std::uint32_t> loose_;    // moving bodies whose fat box changed since the last update
  std::vector<std::pair<AabbTree::Leaf, Aabb>> tree_boxes_;  // refresh_moving_tree()'s, kept
  AabbTree static_tree_;                // the static bodies' broad-phase boxes
  bool statics_changed_ = false;
  double proximity_margin_;
  bool contacts_on_;
  double speculative_margin_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> candidates_;  // this update's, a < b
  std::vector<BodyPair> overlapping_;
  std::vector<BodyPair> began_;
  std::vector<BodyPair> ended_;
  std::vector<Proximity> proximity_;
  std::vector<BodyContact> contacts_;
  std::vector<Impact> impacts_;
  std::vector<SensorPair> sensing_;
  std::vector<SensorPair> sensor_began_;
  std::vector<SensorPair> sensor_ended_;
  std::vector<BodyPair> now_;        // the narrow phase's pairs joined: storage kept between frames
  std::vector<SensorPair> sensed_;
  std::vector<std::uint32_t> continuous_;  // the continuous bodies' indices
  std::function<bool(BodyId, BodyId)> pair_predicate_;
  FrameStats stats_;

  Body& body(BodyId id);
  const Body& body(BodyId id) const;
  BodyId id_of(std::uint32_t index) const { return {index, bodies_[index].generation}; }
  Aabb broad_box(const Aabb& box) const;
  Aabb broad_box(const Body& b) const;
  void enter(std::uint32_t index);
  void leave(std::uint32_t index);
  void place(std::uint32_t index);
  void unloose(std::uint32_t index);
  void refresh_moving_tree();
  void find_candidates();
  // A candidate pair's overlap test, decided at once or left for the chunk's batch.
  enum class Verdict : std::uint8_t { skipped, apart, touching, batched };
  static constexpr std::size_t kPairsPerChunk = 256;
  // The pairs of one kind in a chunk, gathered for the batched overlap test (overlap_batch.h) as
  // body indices, A's body first. Each list holds a whole chunk from the start, so that no frame
  // grows it (as lists of shape copies, they grew whenever a chunk met a new largest count of a
  // kind: 16 allocations a frame at 100,000 moving bodies).
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
    std::tuple<Batch<Rect, Rect>, Batch<Rect, Circle>, Batch<Rect, Ellipse>, Batch<Circle, Circle>, Batch<Circle, Ellipse>,
               Batch<Ellipse, Ellipse>>
        batches;  // every pair kind, in kernel order
    void clear();
  };
  std::vector<Found> chunks_;  // kept from frame to frame, so that steady state allocates nothing
  std::unique_ptr<detail::ThreadPool> pool_;
  void narrow_phase();
  void narrow_chunk(std::size_t begin, std::size_t end, Found& out) const;
  Verdict overlap_verdict(std::uint32_t a, std::uint32_t b, Found& out) const;
  void narrow(std::uint32_t a, std::uint32_t b, bool touching, Found& out) const;
  void impact(std::uint32_t a, std::uint32_t b, Found& out) const;
  bool passes(std::uint32_t a, std::uint32_t b) const;
  template <class Test>
  std::vector<BodyId> select(const Aabb& box, const QueryFilter& filter, Test test) const;
  template <class OnHit>
  void rays(const Vec2& origin, const Vec2& direction, double max_distance, const QueryFilter& filter, OnHit on_hit) const;
};

}  // namespace collide2d
