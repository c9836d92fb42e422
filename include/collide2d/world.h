/// @file
/// The World: bodies of one or more shapes that move every frame, the broad phase that finds
/// candidate pairs of shapes, and the narrow phase that confirms them.
///
///   World world({.fat_margin = 0.1, .proximity_margin = 0.5});
///   BodyId id = world.add(Ellipse{Vec2(1, 2), 1.5, 0.4, 0.3}, {.user_id = 7});
///   world.add(Rect{Vec2(0, -1), Vec2(50, 1), 0.0}, {.is_static = true});  // the floor
///   world.add(Circle{Vec2(9, 0), 2.0}, {.sensor = true});                 // a trigger
///   const ShapeDef ship[] = {{.shape = Ellipse{Vec2(0, 0), 2.0, 0.5, 0.0}},
///                            {.shape = Rect{Vec2(0, 1), Vec2(0.3, 1.0), 0.0}}};
///   world.add(Pose{Vec2(5, 5), 0.0}, ship);           // one body, two shapes placed in its frame
///   world.move_to(id, Vec2(1.1, 2.0), 0.35);           // or move_by(id, shift, turn); set_pose teleports
///   world.update();                                   // once per frame
///   for (const ShapePair& p : world.overlapping()) ... // confirmed overlaps; began()/ended() too
///
/// What is computed is what was asked: every candidate pair gets the overlap test; a distance only
/// with a proximity margin, for pairs apart; a contact only with contacts on. Pairs are of shapes
/// and name both shapes and both bodies; the shapes of one body never pair. Static bodies are level
/// geometry, kept in a tree of their own and never paired with each other. Sensor shapes report the
/// solid shapes that overlap them and are otherwise not solid. Continuous bodies sweep their step
/// and report their first time of impact. Queries test the exact shapes whose boxes they meet.
/// docs/world.md describes each.
///
/// Errors: an invalid shape throws InvalidShape; a NaN or infinite pose, margin or query argument
/// std::invalid_argument; an unknown body or a stale handle (its body removed) std::out_of_range; a
/// change to the World from inside a query's callback std::logic_error; each with a message that
/// says which, and each leaves the World exactly as it was.
#pragma once

#include <collide2d/area.h>
#include <collide2d/chain.h>
#include <collide2d/function_ref.h>
#include <collide2d/query.h>
#include <collide2d/shapes.h>

#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace collide2d {
class World;  ///< bodies, their pairs frame by frame, and queries on them (below)
namespace detail {
class WorldState;
// The World's state, for the library's own helpers built on it (move(), mover.h).
const WorldState& state_of(const World& world);
}  // namespace detail

/// A body's handle: its slot and the generation of that slot (as Box2D v3's b2BodyId). remove()
/// frees the slot and moves its generation on, so a handle kept past remove() is refused instead of
/// reaching whichever body takes the slot next. A default BodyId{} names no body.
struct BodyId {
  std::uint32_t index = 0;
  std::uint32_t generation = 0;
  friend auto operator<=>(const BodyId&, const BodyId&) = default;
};

/// A shape's handle: its slot and the generation of that slot, as BodyId. A body's shapes have
/// handles of their own; remove_shape() and remove() make them stale.
struct ShapeId {
  std::uint32_t index = 0;
  std::uint32_t generation = 0;
  friend auto operator<=>(const ShapeId&, const ShapeId&) = default;
};

/// Two bodies some of whose solid shapes overlap, as of an update (body_overlapping()). A is the
/// body of the lower slot (a.index < b.index): after a remove() and an add() the same two game
/// objects may come the other way round, and user_a and user_b tell them apart without a lookup. The
/// record is whole on its own: its handles may be stale (a body removed since), its user ids are as
/// they were at the update. Records compare by their handles alone.
struct BodyPair {
  BodyId a;
  BodyId b;
  std::uint64_t user_a = 0;  ///< a's user id
  std::uint64_t user_b = 0;  ///< b's user id
  /// In ended() only: the pair ended because a or b was removed since the previous update.
  bool removed = false;
  friend bool operator==(const BodyPair& p, const BodyPair& q) { return p.a == q.a && p.b == q.b; }
  friend std::strong_ordering operator<=>(const BodyPair& p, const BodyPair& q) {
    return p.a != q.a ? p.a <=> q.a : p.b <=> q.b;
  }
};

/// The ids a record of two shapes carries, as of an update: a shape of body a and one of body b, a
/// the body of the lower slot as in BodyPair, with the bodies' user ids and the shapes'. Whole on its
/// own as BodyPair is; records compare and order by their handles alone, bodies then shapes.
struct PairIds {
  BodyId a;
  BodyId b;
  ShapeId shape_a;                 ///< a's shape
  ShapeId shape_b;                 ///< b's shape
  std::uint64_t user_a = 0;        ///< body a's user id
  std::uint64_t user_b = 0;        ///< body b's user id
  std::uint64_t shape_user_a = 0;  ///< shape_a's user id
  std::uint64_t shape_user_b = 0;  ///< shape_b's user id
  friend bool operator==(const PairIds& p, const PairIds& q) {
    return p.a == q.a && p.b == q.b && p.shape_a == q.shape_a && p.shape_b == q.shape_b;
  }
  friend std::strong_ordering operator<=>(const PairIds& p, const PairIds& q) {
    if (p.a != q.a) return p.a <=> q.a;
    if (p.b != q.b) return p.b <=> q.b;
    return p.shape_a != q.shape_a ? p.shape_a <=> q.shape_a : p.shape_b <=> q.shape_b;
  }
};

/// Two solid shapes that overlap, as of an update.
struct ShapePair : PairIds {
  /// In ended() only: the pair ended because one of its shapes or bodies was removed since the
  /// previous update.
  bool removed = false;
};

/// Which shapes may pair, with Box2D's semantics (b2Filter): two shapes of one non-zero group always
/// pair when it is positive and never when it is negative; otherwise each one's category must meet
/// the other's mask.
struct Filter {
  std::uint64_t category = 1;              ///< the bits this body is
  std::uint64_t mask = ~std::uint64_t{0};  ///< the bits it pairs with
  std::int32_t group = 0;
  friend bool operator==(const Filter&, const Filter&) = default;
};
/// Whether two filters let their shapes pair.
bool should_pair(const Filter& a, const Filter& b);

/// Which shapes a query reports (Box2D v3's b2QueryFilter): those whose category meets the query's
/// mask and whose mask meets the query's category. The default reports every shape.
struct QueryFilter {
  std::uint64_t category = 1;
  std::uint64_t mask = ~std::uint64_t{0};
};

/// What a body is, besides its shapes; its filter and sensor flag are its shapes' defaults.
struct BodyDef {
  std::uint64_t user_id = 0;  ///< the caller's, returned by user_id()
  Filter filter{};
  /// Level geometry: never moves by itself, never pairs with a static body. A body with a segment
  /// must be static: add(), add_shape(), set_local_shape() and set_static() refuse otherwise.
  bool is_static = false;
  bool sensor = false;  ///< its shapes report the solid shapes that overlap them, and are not solid
  /// A copy of a body that another World owns, for a domain decomposition (docs/distributed.md):
  /// it pairs with the other bodies as they are, never with another ghost.
  bool ghost = false;
};

/// How World::add_chain() makes a chain's body: always static (a chain is level geometry), never a
/// sensor.
struct ChainDef {
  std::uint64_t user_id = 0;  ///< the caller's, returned by user_id()
  Filter filter{};
};

/// One shape of a body: `shape` is placed in the body's frame (its centre and angle are its offset
/// and angle from the body's origin). The fields left unset take the body's (BodyDef).
struct ShapeDef {
  Shape shape{};
  std::optional<std::uint64_t> user_id{};  ///< the caller's, returned by user_id(ShapeId)
  std::optional<Filter> filter{};
  std::optional<bool> sensor{};
};

/// A sensor shape and a solid shape of another body that overlaps it, as of an update: the bodies,
/// the shapes and their user ids; whole on its own as ShapePair is, ordered by bodies then shapes,
/// and compared by its handles alone.
struct SensorPair {
  BodyId sensor;   ///< the sensor shape's body
  BodyId visitor;  ///< the visiting shape's body
  ShapeId sensor_shape;
  ShapeId visitor_shape;
  std::uint64_t user_sensor = 0;         ///< the sensor body's user id
  std::uint64_t user_visitor = 0;        ///< the visitor body's user id
  std::uint64_t shape_user_sensor = 0;   ///< the sensor shape's user id
  std::uint64_t shape_user_visitor = 0;  ///< the visiting shape's user id
  /// In sensor_ended() only: the pair ended because one of its shapes or bodies was removed since
  /// the previous update.
  bool removed = false;
  /// With WorldOptions::overlap_areas: the part of the visiting shape inside the sensor shape, the
  /// sensor's boundary as A.
  OverlapArea overlap{};
  friend bool operator==(const SensorPair& p, const SensorPair& q) {
    return p.sensor == q.sensor && p.visitor == q.visitor && p.sensor_shape == q.sensor_shape &&
           p.visitor_shape == q.visitor_shape;
  }
  friend std::strong_ordering operator<=>(const SensorPair& p, const SensorPair& q) {
    if (p.sensor != q.sensor) return p.sensor <=> q.sensor;
    if (p.visitor != q.visitor) return p.visitor <=> q.visitor;
    return p.sensor_shape != q.sensor_shape ? p.sensor_shape <=> q.sensor_shape : p.visitor_shape <=> q.visitor_shape;
  }
};

/// A sensor shape and a body at least one of whose solid shapes overlaps it, as of an update: the
/// visit begins with the body's first shape in and ends with its last one out, so that a body of
/// several shapes enters and leaves once. Whole on its own as SensorPair is, ordered by bodies then
/// the sensor shape, and compared by its handles alone.
struct SensorVisit {
  BodyId sensor;   ///< the sensor shape's body
  BodyId visitor;  ///< the visiting body
  ShapeId sensor_shape;
  std::uint64_t user_sensor = 0;        ///< the sensor body's user id
  std::uint64_t user_visitor = 0;       ///< the visitor body's user id
  std::uint64_t shape_user_sensor = 0;  ///< the sensor shape's user id
  /// In body_sensor_ended() only: the visit ended because the sensor shape or either body was
  /// removed since the previous update.
  bool removed = false;
  /// With WorldOptions::overlap_areas: how much of the body lies inside the sensor shape (the sum
  /// over its shapes' pairs, so that a part where two of its own shapes overlap counts twice), and
  /// where (their centroids weighted by area; the sensor shape's centre when the area is 0).
  double area = 0.0;
  Vec2 centroid = Vec2::Zero();
  friend bool operator==(const SensorVisit& p, const SensorVisit& q) {
    return p.sensor == q.sensor && p.visitor == q.visitor && p.sensor_shape == q.sensor_shape;
  }
  friend std::strong_ordering operator<=>(const SensorVisit& p, const SensorVisit& q) {
    if (p.sensor != q.sensor) return p.sensor <=> q.sensor;
    return p.visitor != q.visitor ? p.visitor <=> q.visitor : p.sensor_shape <=> q.sensor_shape;
  }
};

/// How a World works.
struct WorldOptions {
  double fat_margin = 0.0;        ///< broad-phase boxes grow by this, so that small motions cost nothing
  double proximity_margin = 0.0;  ///< > 0: report pairs apart by less than this, in proximity()
  bool contacts = false;          ///< a contact for every overlapping pair, in contacts()
  /// With contacts: pairs apart by at most this get a contact too (speculative contacts, which let a
  /// solver stop bodies before they meet); also the manifold margin of ContactOptions.
  double speculative_margin = 0.0;
  /// Threads for update(), the calling one included; 0: every hardware thread. The results are the
  /// same, in the same order, for any count. With more than one, the pair predicate may be called
  /// from several threads at once.
  unsigned threads = 0;
  /// With contacts: ContactOptions::tolerance for every contact (0: exact).
  double contact_tolerance = 0.0;
  /// The exact overlap (area.h) of every touching pair's contact, and of every sensor pair: area,
  /// centroid and chord, for area-based contact forces and buoyancy. All zero where the pair shares
  /// no open region (touching only) or either shape is a segment or a chain's.
  bool overlap_areas = false;
};

/// Two solid shapes apart by less than the proximity margin.
struct Proximity : PairIds {
  DistanceResult result{};  ///< the distance and closest points, point_a on shape_a
};

/// The contact of an overlapping pair of shapes, or of a pair within the speculative margin.
struct BodyContact : PairIds {
  /// The solids overlap (touching included): the exact verdict of overlaps(), not the sign of a
  /// separation within rounding. False for a speculative contact.
  bool touching = true;
  Contact contact{};  ///< of shape_a with shape_b: the normal points from a to b
  /// With WorldOptions::overlap_areas and touching: the overlap of shape_a with shape_b (area.h);
  /// otherwise zero.
  OverlapArea overlap{};
};

/// The contact's normal pointing away from `body`, towards the pair's other body: as stored for body
/// a, reversed for body b. Throws std::invalid_argument for a body of neither side.
Vec2 normal_from(const BodyContact& c, BodyId body);

/// A continuous body's first contact with another body within the step: one per pair of bodies, the
/// earliest over their shapes' pairs, naming the two shapes that meet.
struct Impact : PairIds {
  double t = 0.0;               ///< the first time of contact within the step, in [0, 1]
  Vec2 normal = Vec2::UnitX();  ///< from a to b
  Vec2 point = Vec2::Zero();
};

/// A shape a query finds, and its body.
struct BodyShape {
  BodyId body;
  ShapeId shape;
};

/// The first shape a cast shape meets.
struct BodyCastHit {
  BodyId body;
  ShapeId shape;
  double fraction = 0.0;  ///< of the translation, at the first contact
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::UnitX();  ///< the body's outward normal there, towards the cast shape
};

/// What a mover's queries see (World::cast_mover(), World::collide_mover(), move() in mover.h).
struct MoverQuery {
  double skin = 0.01;  ///< the gap the mover keeps from surfaces, >= 0
  QueryFilter filter{};
  std::optional<BodyId> self;  ///< the mover's own body, where it is one: left out
};

/// A surface a mover touches: its nearest point to the mover while apart, its deepest while they
/// overlap (contact() of the surface's shape with the mover).
struct MoverPlane {
  BodyId body;
  ShapeId shape;
  std::uint64_t user_id = 0;    ///< the body's
  Vec2 point = Vec2::Zero();    ///< on the surface
  Vec2 normal = Vec2::UnitY();  ///< unit, from the surface towards the mover
  double separation = 0.0;      ///< of the mover from the surface; < 0 overlapping
};

/// A shape a ray meets.
struct RayHit {
  BodyId body;
  ShapeId shape;
  double distance = 0.0;  ///< from the ray's origin to the hit point
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::Zero();  ///< the shape's outward unit normal there; zero when the ray starts inside
};

/// How a ray treats a shape that contains its origin.
struct RayOptions {
  /// Report such a shape, hit at distance 0 with a zero normal, instead of skipping it.
  bool from_inside = false;
};

/// How a cast treats a shape that the cast shape overlaps at the start.
struct CastOptions {
  /// Skip such a shape instead of reporting it hit at fraction 0.
  /// A shape that starts in contact with the ground then finds the wall it moves towards.
  bool skip_initial_overlap = false;
};

/// What the last update did.
struct FrameStats {
  std::size_t candidates = 0;   ///< pairs of shapes from the broad phase
  std::size_t filtered = 0;     ///< of them, dropped by the filters or the pair predicate
  std::size_t overlapping = 0;  ///< confirmed by the narrow phase
  std::size_t proximity = 0;
  std::size_t contacts = 0;
  std::size_t impacts = 0;
  std::size_t sensing = 0;    ///< sensor pairs
  std::size_t requeried = 0;  ///< moving shapes whose static neighbours were looked up again
  double broad_seconds = 0.0;
  double narrow_seconds = 0.0;  ///< with the moving bodies' query tree, kept up to date alongside
};

/// Where a body is: the position and angle of its origin. A body added with one shape has its origin
/// at that shape's centre and angle.
struct Pose {
  Vec2 position = Vec2::Zero();
  double angle = 0.0;
};

/// Where a body at `pose` puts a shape placed in its frame, to the bit as the World places it.
/// The shape's centre and angle are its offset and angle from the body's origin: the offset turned
/// by `turn` and moved to the position, the angles added. `turn` is Orientation::of(pose.angle),
/// computed once for all of a body's shapes.
Shape placed(const Shape& local, const Pose& pose, const Orientation& turn);
/// The pose of a shape's own centre and angle: the origin of the body add(shape) makes of it.
Pose pose_of(const Shape& shape);

/// World::reach_box() of a shape where it is in a World with these options, computed without one:
/// `start` is a continuous shape's pose at the last update, nullopt for another.
Aabb reach_box(const Shape& shape, const std::optional<Pose>& start, const WorldOptions& options);

/// The lower-left corner of the intersection of two boxes that meet: the owner of their pair.
/// For two reach boxes (World::reach_box()) a point of both: the point that decides which region of a domain
/// decomposition reports their pair, so that each pair is reported by exactly one region.
Vec2 owner_point(const Aabb& a, const Aabb& b);

/// Bodies, their pairs frame by frame, and queries on them.
class World {
 public:
  /// Throws std::invalid_argument for a negative or non-finite margin.
  explicit World(const WorldOptions& options = {});
  ~World();
  /// A World moves; it is not copied.
  World(World&&) noexcept;
  World& operator=(World&&) noexcept;

  /// Adds a body of one shape, its origin at the shape's centre and angle; it pairs from the next
  /// update.
  BodyId add(const Shape& shape, const BodyDef& def = {});
  /// Adds a body at `pose` with the shapes (at least one), each placed in the body's frame.
  BodyId add(const Pose& pose, std::span<const ShapeDef> shapes, const BodyDef& def = {});
  /// Adds a chain (chain.h) of points in the world as one static body at the origin: one segment
  /// shape per chain segment in the chain's order (shapes(id)[k] is segment k of
  /// chain_segments()), each one-sided and smooth as chain.h says. Throws InvalidShape for the
  /// points as chain_segments() does.
  BodyId add_chain(std::span<const Vec2> points, bool loop, const ChainDef& def = {});
  /// Adds a shape to a body, placed in its frame; it pairs from the next update.
  ShapeId add_shape(BodyId body, const ShapeDef& shape);
  /// Removes a shape; its pairs end at the next update, and its handle is stale from now on. A
  /// body's last shape and a chain's segment are refused (std::invalid_argument): remove the body
  /// instead.
  void remove_shape(ShapeId id);
  /// Puts a body at a pose: a teleport, as Box2D's b2Body_SetTransform. A continuous body's step
  /// starts there, so nothing between the old pose and the new one is hit. Static bodies too (each
  /// moving shape then looks its static neighbours up again).
  void set_pose(BodyId id, const Vec2& position, double angle);
  /// Moves a body to a pose: a continuous body sweeps its way there, and the next update reports
  /// what it meets on the way (impacts()). For other bodies the same as set_pose().
  void move_to(BodyId id, const Vec2& position, double angle);
  /// move_to() the current pose shifted and turned.
  void move_by(BodyId id, const Vec2& shift, double turn = 0.0);
  /// Makes a body static or moving; a continuous body stops being continuous when it becomes static.
  void set_static(BodyId id, bool is_static);
  /// A new filter for the body and each of its shapes; pairs that no longer pass end at the next
  /// update, in ended().
  void set_filter(BodyId id, const Filter& filter);
  /// A new filter for one shape.
  void set_filter(ShapeId id, const Filter& filter);
  /// Makes a shape a sensor or solid; its pairs of the other kind end at the next update.
  void set_sensor(ShapeId id, bool sensor);
  /// Places a shape anew in its body's frame (its centre and angle are the offset and angle). On a
  /// continuous body the shape's step starts at its new place. A chain's segment is refused.
  void set_local_shape(ShapeId id, const Shape& local);
  /// A test of the caller's that drops a candidate pair where it returns false; empty passes all.
  /// Called for the candidate pairs of shapes that pass both filters, with their bodies
  /// (a.index < b.index), before any narrow-phase work.
  void set_pair_predicate(std::function<bool(BodyId, BodyId)> predicate);
  /// Removes a body and its shapes; their pairs end at the next update, and their handles are stale
  /// from now on.
  void remove(BodyId id);
  /// A new proximity margin (>= 0), from the next update.
  void set_proximity_margin(double margin);
  /// Makes a body continuous (or not): update() reports its first contacts within each step.
  /// Its step runs from its pose at the last update (or at this call, or at its last set_pose())
  /// to its pose at the next update, and update() reports its first contacts within it in
  /// impacts(). Each of its shapes moves from its place at the start to its place at the end along a
  /// straight line, turning at a steady rate about its own centre. Throws std::invalid_argument for
  /// a static body.
  void set_continuous(BodyId id, bool continuous = true);
  /// Makes a body a ghost (BodyDef::ghost) or not, from the next update.
  void set_ghost(BodyId id, bool ghost = true);
  /// Finds the pairs of this frame: once per frame, after the poses are set.
  void update();

  /// Whether the handle names a body (a shape) of this World.
  bool contains(BodyId id) const;
  bool contains(ShapeId id) const;
  /// Bodies in the World.
  std::size_t size() const;
  /// The threads each update() runs on: WorldOptions::threads, or the hardware's count where that is 0.
  unsigned threads() const;
  /// A body's pose, user id, filter, kind, first shape and shapes. Each throws std::out_of_range for an
  /// unknown or stale handle. The first shape is where it is (the only one of a body added with
  /// one); the shapes come in the order added.
  Pose pose(BodyId id) const;
  /// How far the body's motion over the last update carried a point on it: the change of its pose
  /// from the update before to the last one (before any move since), applied to the point; zero
  /// for a body that did not move between them (or a World not updated twice). A character on a
  /// moving platform moves with it by this (move() in mover.h). Throws std::out_of_range for an
  /// unknown or stale handle.
  Vec2 displacement(BodyId id, const Vec2& point) const;
  const Shape& shape(BodyId id) const;
  std::uint64_t user_id(BodyId id) const;
  const Filter& filter(BodyId id) const;
  bool is_static(BodyId id) const;
  bool is_sensor(BodyId id) const;  ///< the body's default for its shapes
  bool is_continuous(BodyId id) const;
  bool is_ghost(BodyId id) const;
  std::vector<ShapeId> shapes(BodyId id) const;
  /// A shape where it is, as placed in its body's frame, its body, user id, filter and kind.
  /// Each throws std::out_of_range for an unknown or stale handle.
  const Shape& shape(ShapeId id) const;
  Shape local_shape(ShapeId id) const;
  BodyId body(ShapeId id) const;
  /// The chain segment a shape is, with its ghosts, where it is; nullopt for a shape of no chain.
  std::optional<ChainSegment> chain_segment(ShapeId id) const;
  std::uint64_t user_id(ShapeId id) const;
  const Filter& filter(ShapeId id) const;
  bool is_sensor(ShapeId id) const;
  /// Every body, by index.
  std::vector<BodyId> bodies() const;

  /// The solid shape pairs that overlap at the last update, sorted; and those that began and ended
  /// then (an ended pair of a shape or body removed since the previous update has `removed` set).
  const std::vector<ShapePair>& overlapping() const;
  const std::vector<ShapePair>& began() const;
  const std::vector<ShapePair>& ended() const;
  /// The same by bodies: the pairs of bodies with at least one overlapping pair of shapes, sorted,
  /// and those that began and ended then.
  const std::vector<BodyPair>& body_overlapping() const;
  const std::vector<BodyPair>& body_began() const;
  const std::vector<BodyPair>& body_ended() const;
  /// Shape pairs apart by less than the proximity margin, sorted by pair.
  const std::vector<Proximity>& proximity() const;
  /// With contacts on: the overlapping shape pairs' contacts and, with a speculative margin, those of
  /// the pairs apart by at most the margin (touching false), sorted by pair; without a speculative
  /// margin, one for each pair of overlapping() in its order.
  const std::vector<BodyContact>& contacts() const;
  /// The continuous bodies' first contacts within the last step, one per pair of bodies, sorted.
  const std::vector<Impact>& impacts() const;
  /// Each sensor shape's visitors at the last update, and those that entered or left then; sorted.
  /// sensor_ended() marks the pairs of a shape or body removed since the previous update.
  const std::vector<SensorPair>& sensing() const;
  const std::vector<SensorPair>& sensor_began() const;
  const std::vector<SensorPair>& sensor_ended() const;
  /// The same by visiting bodies (SensorVisit): each sensor shape and each body with a solid shape
  /// inside it, once, sorted; and the visits that began and ended then.
  const std::vector<SensorVisit>& body_sensing() const;
  const std::vector<SensorVisit>& body_sensor_began() const;
  const std::vector<SensorVisit>& body_sensor_ended() const;
  /// With contacts on: the body's contacts at the last update, as indices into contacts() in its
  /// order, indexed by the update so that a lookup scans nothing. Empty for a body without contacts
  /// or added since. Throws std::out_of_range for an unknown body or a stale handle.
  std::span<const std::uint32_t> contacts_of(BodyId id) const;
  /// What the last update did and how long it took.
  const FrameStats& last_frame() const;
  /// A 64-bit digest of the bodies and of the last update's results, defined in docs/world.md.
  /// It reads the bodies as they are (ids, user ids, poses) and the pairs, proximity, contacts,
  /// impacts and sensor pairs, every number by its bits, and no timing: Worlds that hold the same
  /// state give the same value on any machine and thread count, so that lockstep peers compare it to
  /// find a desync. It may change between versions of collide2d (CHANGELOG.md says when).
  std::uint64_t state_hash() const;
  /// The last update's candidate pairs from the broad phase, in no order, a's body the lower slot.
  /// FrameStats::candidates of them, those the filters dropped among them. Built on each call, for
  /// debugging and replays (Recorder): read it before any shape is removed.
  std::vector<ShapePair> candidates() const;
  /// The box the broad phase keeps for the shape: its box grown by half the proximity or speculative
  /// margin and, for a moving shape, by the fat margin as of the last time it left its fat box (a
  /// continuous shape's box holds its whole step).
  Aabb broad_box(ShapeId id) const;
  /// The shape's box for the step the next update() takes, grown by half a margin.
  /// A continuous shape's holds the whole step; the margin is the larger of the proximity and the
  /// speculative margins. The boxes of any two shapes that the update reports together meet. A
  /// function of the shape where it is, a continuous shape's pose at the last update, and the
  /// margins (no fat margin), so that Worlds that hold the same body agree on it to the bit: a
  /// domain decomposition places bodies and pairs by it (owner_point()).
  Aabb reach_box(ShapeId id) const;

  /// Queries on the current poses (no update needed). Each comes in two forms. The callback form
  /// calls `visit` for each shape found, with its body, in the order the trees are walked, allocates
  /// nothing, and stops when `visit` says so; the World cannot be changed from inside `visit` (a
  /// call that would change it throws std::logic_error). The other form collects what was found and
  /// sorts it: each body once, by index.

  /// The bodies with a solid shape the filter lets through that overlaps `shape`.
  std::vector<BodyId> overlapping(const Shape& shape, const QueryFilter& filter = {}) const;
  /// visit(found) for each such shape until it returns false.
  void overlapping(const Shape& shape, FunctionRef<bool(const BodyShape&)> visit, const QueryFilter& filter = {}) const;
  /// The bodies with a solid shape that meets the box (which may be a segment or a point).
  std::vector<BodyId> overlapping(const Aabb& box, const QueryFilter& filter = {}) const;
  void overlapping(const Aabb& box, FunctionRef<bool(const BodyShape&)> visit, const QueryFilter& filter = {}) const;
  /// The bodies with a solid shape within `distance` (>= 0) of the point.
  std::vector<BodyId> within(const Vec2& point, double distance, const QueryFilter& filter = {}) const;
  void within(const Vec2& point, double distance, FunctionRef<bool(const BodyShape&)> visit,
              const QueryFilter& filter = {}) const;
  /// The bodies with a solid shape within `distance` (>= 0) of the shape.
  std::vector<BodyId> within(const Shape& shape, double distance, const QueryFilter& filter = {}) const;
  void within(const Shape& shape, double distance, FunctionRef<bool(const BodyShape&)> visit,
              const QueryFilter& filter = {}) const;

  /// The first shape the ray from `origin` along `direction` hits within `max_distance`.
  /// The direction has any non-zero length; the lowest body index, then shape index, on a tie. Exact on curves. A shape
  /// that contains the origin is skipped, as in Box2D v3, unless `options.from_inside`.
  std::optional<RayHit> ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                                 const QueryFilter& filter = {}, const RayOptions& options = {}) const;
  /// visit(hit) for the shapes the ray hits within its reach, nearest boxes first but not sorted.
  /// The reach starts at max_distance; visit returns what to do next, as Box2D v3's b2CastResultFcn
  /// in units of max_distance: a negative value goes on, 0 stops, a value in (0, reach) shortens the
  /// reach to it (return hit.distance to keep only nearer hits), a larger one goes on.
  void ray_cast(const Vec2& origin, const Vec2& direction, double max_distance,
                FunctionRef<double(const RayHit&)> visit, const QueryFilter& filter = {},
                const RayOptions& options = {}) const;
  /// Every shape the ray hits within `max_distance`, nearest first.
  /// By body index, then shape index, on a tie.
  std::vector<RayHit> ray_cast_all(const Vec2& origin, const Vec2& direction, double max_distance,
                                   const QueryFilter& filter = {}, const RayOptions& options = {}) const;

  /// The first shape the cast shape meets when translated by `translation`.
  /// The lowest body index, then shape index, on a tie. A shape it overlaps at the start is hit at fraction 0, unless
  /// `options.skip_initial_overlap`.
  std::optional<BodyCastHit> cast(const Shape& shape, const Vec2& translation, const QueryFilter& filter = {},
                                  const CastOptions& options = {}) const;
  /// visit(hit) for the shapes the translated shape meets, as ray_cast()'s callback form.
  /// In fractions of the translation: the reach starts at 1.
  void cast(const Shape& shape, const Vec2& translation, FunctionRef<double(const BodyCastHit&)> visit,
            const QueryFilter& filter = {}, const CastOptions& options = {}) const;

  /// The fraction of `translation` the mover can move (no turn), 1 where nothing stops it.
  /// The least over the solid shapes the query lets through of cast_mover() (mover.h) with its skin. A mover
  /// within the skin of a surface, or slightly inside it, moves along and away from it; a chain's
  /// segment stops only a mover that starts in front of it.
  double cast_mover(const Shape& mover, const Vec2& translation, const MoverQuery& query = {}) const;
  /// visit(plane) for each surface the mover touches, until visit returns false.
  /// Touches: each solid shape the query lets through within the skin of the mover or overlapping
  /// it. Against a chain's segment, its rules (chain.h) hold apart too: no plane from behind it, nor
  /// one whose normal leaves a vertex's cone.
  void collide_mover(const Shape& mover, FunctionRef<bool(const MoverPlane&)> visit,
                     const MoverQuery& query = {}) const;
  /// Every such plane, by body index, then shape index.
  std::vector<MoverPlane> collide_mover(const Shape& mover, const MoverQuery& query = {}) const;

 private:
  friend const detail::WorldState& detail::state_of(const World& world);
  std::unique_ptr<detail::WorldState> state_;
};

}  // namespace collide2d
