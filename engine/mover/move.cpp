// A character's move: the loop of Box2D v3's mover sample (collide, solve the planes, cast, at most
// a few times), with the rules a game's character needs on top (as Jolt's CharacterVirtual and
// Godot's move_and_slide have them). A floor holds the mover up vertically, so that it stands on a
// slope without sliding and walks along it at the commanded horizontal speed; a wall too steep to
// stand on also blocks horizontally, so that pushing into it never climbs it; after the move the
// mover follows the ground down by the snap distance and, blocked while on the ground, tries the
// step up, across and down.
#include <collide2d/mover.h>

#include <collide2d/query.h>

#include "engine/internal.h"
#include "engine/world_state.h"
#include "narrowphase/internal.h"
#include "shapes/internal.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace collide2d {
namespace {

// How far beyond the skin a surface still counts as touched: above the 1e-9 of the reach at which
// a cast stops short of the skin, so that a mover resting there keeps its floor.
constexpr double kBand = 1e-6;

// The cosine of the max slope, which a game's moves share: the last one's is kept.
double cosine(double angle) {
  thread_local double last_angle = 0.0, last_cosine = 1.0;
  if (angle != last_angle) last_angle = angle, last_cosine = Orientation::of(angle).c;
  return last_cosine;
}

void validate(const Vec2& velocity, double dt, const MoverOptions& o) {
  detail::require_finite(velocity.x(), "move velocity x");
  detail::require_finite(velocity.y(), "move velocity y");
  detail::require_margin(dt, "move dt");
  detail::require_margin(o.step_height, "mover step height");
  detail::require_margin(o.snap_distance, "mover snap distance");
  if (!(o.max_slope >= 0.0 && o.max_slope < std::numbers::pi / 2)) {
    throw std::invalid_argument("mover max slope must lie in [0, pi/2) (got " + detail::shortest(o.max_slope) + ')');
  }
  if (!(std::abs(o.up.squaredNorm() - 1.0) <= 1e-12)) {
    throw std::invalid_argument("mover up must be of unit length (got length " + detail::shortest(o.up.norm()) + ')');
  }
  if (o.max_iterations < 1) {
    throw std::invalid_argument("mover max iterations must be at least 1 (got " + std::to_string(o.max_iterations) +
                                ')');
  }
  if (!(o.soft_push_limit >= 0.0)) {
    throw std::invalid_argument("mover soft push limit must not be negative (got " +
                                detail::shortest(o.soft_push_limit) + ')');
  }
}

// One move's surroundings: the surfaces touched where the mover is, and the planes that keep it out
// of them. The floors hold the mover up by their exact separation where it is going, not by their
// planes: a plane is its surface linearised where the mover is, exact for a face but conservative
// for a corner or a curve, which it would make the mover climb (walking over the seam between two
// tiles, the next tile's corner is within the skin, and its plane would lift the mover over an
// edge it never comes near). The cast keeps the whole path the skin from every surface.
class Mover {
 public:
  Mover(const World& world, const Shape& mover, const MoverOptions& options, const Vec2& target)
      : world_(detail::state_of(world)),
        mover_(mover),
        o_(options),
        turn_(Orientation::of(angle_of(mover))),
        cos_slope_(cosine(options.max_slope)),
        hair_(detail::mover_floor_hair(mover)),
        base_(support(mover, Vec2(-options.up)).dot(options.up)),
        touch_query_{options.query.skin + kBand * reach_of(mover), options.query.filter, options.query.self},
        soft_query_{touch_query_.skin + (options.soft_categories != 0 ? travel(mover, target) : 0.0),
                    options.query.filter, options.query.self},
        cast_query_{options.query.skin,
                    {options.query.filter.category, options.query.filter.mask & ~options.soft_categories},
                    options.query.self} {
    // The move's neighbourhood: its path, grown by what the loop, a step and a snap can add to it.
    const double room = soft_query_.skin + travel(mover, target) + options.step_height + options.snap_distance;
    world_.gather(detail::grown(detail::swept(pose_of(mover), moved_to(mover, target)), room), options.query.filter,
                  near_);
  }

  Shape at(const Vec2& c) const { return moved_to(mover_, c); }

  // The fraction of `delta` the mover at c can move; soft surfaces do not stop it.
  double cast(const Vec2& c, const Vec2& delta) const {
    return world_.cast_mover(at(c), turn_, delta, cast_query_, &near_);
  }

  // The surfaces touched at c.
  void collide(const Vec2& c) {
    touching(c, touched_);
    ground_ = {};
    for (const MoverPlane& p : touched_) {
      if (stands_on(p, c) && (!ground_.on_ground || p.normal.dot(o_.up) > ground_.normal.dot(o_.up)))
        ground_ = {true, p.normal, p.body, p.shape, p.user_id};
    }
  }

  // From now on the floors touched keep the mover out by their planes too: stalled on a floor's
  // convex edge (a ridge's top) with the target beyond it, their planes lift the path over it.
  // Whether they did already.
  bool plane_floors() { return std::exchange(floor_planes_, true); }

  // The floor touched whose normal lies nearest up, if any.
  const Ground& ground() const { return ground_; }

  // The translation from c nearest `target` that the surfaces allow: the target held up by the
  // floors where it ends, then kept out of the planes of the other surfaces touched at c, and of a
  // floor's where they push it nearer that floor than the skin (a crease of a wall and a floor).
  Vec2 solve(const Vec2& c, const Vec2& target) {
    const double lifted = lift(c + target);
    lifted_ = lifted > 0.0;
    const Vec2 held = target + lifted * o_.up;
    planes_.clear();
    pending_.clear();
    for (const MoverPlane& p : touched_) {
      if (floor(p, c) && !floor_planes_) {
        pending_.push_back(&p);
      } else {
        add_planes(p);
      }
    }
    Vec2 delta = solve_planes(held, planes_).delta;
    if (delta != held) add_floors_ahead(c, c + held);
    // One floor a pass, the one facing nearest up: a tile's face, not the next tile's corner
    // beside it, whose plane the face's keeps it clear of, as one long box would.
    for (const MoverPlane** p; (p = nearest_up_crossed(c + delta)) != nullptr;) {
      add_planes(**p);
      *p = nullptr;
      delta = solve_planes(held, planes_).delta;
    }
    // Planes that moved the target (a soft push, a wall) may have moved it over a floor not touched
    // at c: the floors where it ends now hold it up too.
    if (delta != held) {
      const double more = lift(c + delta);
      lifted_ = lifted_ || more > 0.0;
      delta += more * o_.up;
    }
    return delta;
  }

  // The floors touched at the held target e and not at c, their planes moved to pass through c,
  // wait with those touched at c: the other planes may push the target off the floor at c onto
  // them (the next tile), where they hold it as one long floor would.
  void add_floors_ahead(const Vec2& c, const Vec2& e) {
    touching(e, ahead_);
    std::erase_if(ahead_, [&](const MoverPlane& p) {
      const auto same = [&](const MoverPlane& q) { return q.shape == p.shape; };
      return !floor(p, e) || std::any_of(touched_.begin(), touched_.end(), same);
    });
    for (MoverPlane& p : ahead_) {
      p.separation -= p.normal.dot(e - c);
      pending_.push_back(&p);
    }
  }

  // Of the floors not yet in the solve that the mover centred at e comes nearer than the skin, the
  // one whose normal lies nearest up.
  const MoverPlane** nearest_up_crossed(const Vec2& e) {
    const MoverPlane** best = nullptr;
    for (const MoverPlane*& p : pending_) {
      if (p == nullptr || (best != nullptr && !(p->normal.dot(o_.up) > (*best)->normal.dot(o_.up)))) continue;
      if (separation(*p, e) < o_.query.skin - hair_) best = &p;
    }
    return best;
  }

  // Moves c along delta as far as the cast allows, and says whether all of it was free. On the
  // ground (a floor touched at c, or one that held the target up) a translation rises first and
  // then goes across, or goes across and then comes down, so that a floor that steps up or down
  // by a hair (tiles of uneven height) or turns down (a ledge's rounded edge) is followed rather
  // than cut into: a straight path between two points the skin above a convex edge passes nearer.
  bool travel(Vec2& c, const Vec2& delta) const {
    const bool grounded = lifted_ || ground().on_ground;
    const Vec2 rise = (grounded ? delta.dot(o_.up) : 0.0) * o_.up, across = delta - rise;
    bool free = true;
    const bool up_first = rise.dot(o_.up) > 0.0;
    for (const Vec2& part : {up_first ? rise : across, up_first ? across : rise}) {
      if (part == Vec2::Zero()) continue;
      const double f = cast(c, part);
      c += f * part;
      free = free && f == 1.0;
    }
    return free;
  }

  // The velocity with what moves into the ground or a surface that pushed removed, the ground
  // holding it up.
  Vec2 clip(const Vec2& v) const {
    const Ground g = ground();
    const double rise = g.normal.dot(o_.up);
    Vec2 held = v;
    // A step's edge holds up only what falls.
    if (g.on_ground) held -= std::min(0.0, rise >= cos_slope_ ? g.normal.dot(v) / rise : v.dot(o_.up)) * o_.up;
    return clip_vector(held, planes_);
  }

 private:
  bool soft(const MoverPlane& p) const { return (world_.filter(p.shape).category & o_.soft_categories) != 0; }
  // Whether the mover stands on a surface touched: a floor, or a soft surface as level (another
  // character's head), which holds its fall as a floor does while its plane pushes it out softly.
  bool stands_on(const MoverPlane& p, const Vec2& c) const {
    if (!soft(p)) return floor(p, c);
    return p.separation <= touch_query_.skin && p.normal.dot(o_.up) >= cos_slope_;
  }
  // Whether a surface touched by the mover centred at c holds it up: a floor, or with a step height
  // the edge of a step, so that a rounded mover rides up onto it as onto a floor.
  bool floor(const MoverPlane& p, const Vec2& c) const {
    if (soft(p)) return false;
    const double rise = p.normal.dot(o_.up);
    return rise >= cos_slope_ || (o_.step_height > 0 && rise > 0 && step_edge(p, c));
  }

  // Whether the surface's point lies at most the step height above the mover's lowest point where
  // the move started, with a floor just beyond it: a ray down from over that point, a little
  // farther from the mover, meets a floor (a slope too steep to stand on meets itself).
  bool step_edge(const MoverPlane& p, const Vec2& c) const {
    if (!(p.point.dot(o_.up) - base_ <= o_.step_height)) return false;
    const Vec2 away = p.point - c, ahead = away - away.dot(o_.up) * o_.up;
    if (!(ahead.norm() > 0)) return false;
    const double probe = 1e-2 * reach_of(mover_);
    const Vec2 from = p.point + probe * (ahead.normalized() + o_.up);
    bool found = false;
    world_.ray_cast(from, Vec2(-o_.up), 2 * probe,
                    [&](const RayHit& hit) {
                      if (hit.body == o_.query.self) return -1.0;
                      found = hit.normal.dot(o_.up) >= cos_slope_;
                      return hit.distance;
                    },
                    cast_query_.filter, {});
    return found;
  }

  // The surfaces touched at c, and the soft ones the move may reach: the cast passes those, so
  // their planes, conservative while apart, keep the mover the skin from them.
  void touching(const Vec2& c, std::vector<MoverPlane>& out) const {
    out.clear();
    world_.collide_mover(
        at(c), turn_,
        [&](const MoverPlane& p) {
          if (p.separation <= touch_query_.skin || soft(p)) out.push_back(p);
          return true;
        },
        soft_query_, &near_);
  }

  // The exact separation of a surface from the mover centred at c.
  double separation(const MoverPlane& p, const Vec2& c) const {
    return world_.contact_with(p.shape, at(c), turn_).separation;
  }

  // How far up the mover centred at e must go to be the skin from every floor it touches there:
  // Newton's method on each floor's separation, convex in the height, which from below steps past
  // the height and from above comes down to it, never below.
  double lift(const Vec2& e) {
    touching(e, below_);
    double most = 0.0;
    for (const MoverPlane& p : below_) {
      if (!floor(p, e)) continue;
      double h = 0.0;
      for (int k = 0; k < 16; ++k) {
        const Contact c = world_.contact_with(p.shape, at(e + h * o_.up), turn_);
        const double rise = c.normal.dot(o_.up);
        if (!(rise > 0.0) || (h == 0.0 && c.separation >= o_.query.skin)) break;
        const double step = (o_.query.skin - c.separation) / rise;
        h = std::max(0.0, h + step);
        if (std::abs(step) <= hair_) break;
      }
      most = std::max(most, h);
    }
    return most;
  }

  // A surface's plane; a wall too steep to stand on that faces up also blocks horizontally, so
  // that pushing into it never climbs it.
  void add_planes(const MoverPlane& p) {
    const bool is_soft = soft(p);
    CollisionPlane plane = plane_of(p, o_.query.skin);
    if (is_soft) plane.push_limit = o_.soft_push_limit, plane.clip_velocity = false;
    planes_.push_back(plane);
    const double rise = p.normal.dot(o_.up);
    if (is_soft || !(rise > 0.0 && rise < cos_slope_)) return;
    const Vec2 level = p.normal - rise * o_.up;
    const double length = level.norm();
    planes_.push_back({.normal = level / length, .offset = plane.offset / length});
  }

  const detail::WorldState& world_;
  const Shape& mover_;
  const MoverOptions& o_;
  Orientation turn_;  // the mover's, kept for every query of the move
  double cos_slope_;
  double hair_;
  double base_;             // the height of the mover's lowest point where the move started
  MoverQuery touch_query_;  // the skin and a hair more: a cast stops that far above the skin
  MoverQuery soft_query_;   // that, and the move's length where there are soft surfaces
  MoverQuery cast_query_;
  Ground ground_;        // of the surfaces touched, found once a collide: a step's edge costs a ray
  bool lifted_ = false;  // whether the last solve's floors held the target up
  bool floor_planes_ = false;
  static double travel(const Shape& mover, const Vec2& target) { return (target - center_of(mover)).norm(); }

  // The lists, kept by the thread from move to move, so that a move allocates nothing.
  struct Lists {
    detail::WorldState::Nearby near;
    std::vector<MoverPlane> touched;         // where the mover is
    std::vector<MoverPlane> below;           // where a translation ends
    std::vector<MoverPlane> ahead;           // floors there, not touched where it starts
    std::vector<const MoverPlane*> pending;  // floors touched whose planes are not in the solve
    std::vector<CollisionPlane> planes;
  };
  static thread_local Lists lists_;
  std::vector<MoverPlane>& touched_ = lists_.touched;
  std::vector<MoverPlane>& below_ = lists_.below;
  std::vector<MoverPlane>& ahead_ = lists_.ahead;
  std::vector<const MoverPlane*>& pending_ = lists_.pending;
  std::vector<CollisionPlane>& planes_ = lists_.planes;
  detail::WorldState::Nearby& near_ = lists_.near;
};

thread_local Mover::Lists Mover::lists_;

// c moved to `landed` where the mover stands on a floor there, and whether it did; the surfaces
// touched are c's after.
bool land(Mover& m, Vec2& c, const Vec2& landed) {
  m.collide(landed);
  if (!m.ground().on_ground) {
    m.collide(c);
    return false;
  }
  c = landed;
  return true;
}

// Where a mover on the ground that the loop left short of `target` would get by stepping: up by
// the step height (less where a ceiling stops it), across the rest of the move's level part, and
// down as far as it went up; nothing where it gains nothing or meets nothing coming down.
std::optional<Vec2> step(Mover& m, const Vec2& c, const Vec2& target, double stuck, const MoverOptions& o) {
  const Vec2 rest = target - c, across = rest - rest.dot(o.up) * o.up;
  if (!(across.norm() > stuck)) return std::nullopt;
  const Vec2 rise = o.step_height * o.up;
  const Vec2 raised = c + m.cast(c, rise) * rise;
  const double f = m.cast(raised, across);
  if (!(f * across.norm() > stuck)) return std::nullopt;
  const Vec2 over = raised + f * across, fall = c - raised;
  const double g = m.cast(over, fall);
  if (g == 1.0) return std::nullopt;  // nothing within the height it rose
  return Vec2(over + g * fall);
}

}  // namespace

CollisionPlane plane_of(const MoverPlane& plane, double skin) {
  return {.normal = plane.normal, .offset = skin - plane.separation};
}

MoveResult move(const World& world, const Shape& mover, const Vec2& velocity, double dt, const MoverOptions& options,
                const Ground& ground) {
  validate(velocity, dt, options);
  const Vec2 start = center_of(mover);
  const bool carried = ground.on_ground && world.contains(ground.body);
  const Vec2 target = start + dt * velocity + (carried ? world.displacement(ground.body, start) : Vec2::Zero());
  detail::state_of(world).validate_mover(mover, options.query);
  validate(moved_to(mover, target));  // the range of the centre
  Mover m(world, mover, options, target);
  // Below this, a step of the loop has not moved the mover: it is blocked.
  const double stuck = 1e-3 * (dt * velocity).norm();
  MoveResult r;
  Vec2 c = start;
  bool stood = false;
  for (r.iterations = 1;; ++r.iterations) {
    m.collide(c);
    if (r.iterations == 1) stood = m.ground().on_ground;
    const Vec2 from = c;
    r.blocked = !m.travel(c, m.solve(c, target - c));
    if (!r.blocked || r.iterations == options.max_iterations) break;
    // A first cast may stop at once at a surface it did not touch before; the next one slides on
    // it, or goes over the floor's edge it stalled on.
    if ((c - from).norm() <= stuck && m.plane_floors() && r.iterations > 1) break;
  }
  if (const auto landed = stood && options.step_height > 0 ? step(m, c, target, stuck, options) : std::nullopt) {
    r.blocked = land(m, c, *landed) || r.blocked;
  } else {
    m.collide(c);
  }
  if (stood && !m.ground().on_ground && options.snap_distance > 0 && velocity.dot(options.up) <= 0.0) {
    const Vec2 down = -options.snap_distance * options.up;
    const double f = m.cast(c, down);
    if (f < 1.0) r.blocked = land(m, c, c + f * down) || r.blocked;
  }
  r.position = c;
  r.ground = m.ground();
  r.velocity = m.clip(velocity);
  return r;
}

}  // namespace collide2d
