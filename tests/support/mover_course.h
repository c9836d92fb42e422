// The mover suite's scripted level, its random inputs and its referee, for any library's movers
// (tests/unit/test_mover_course.cpp runs collide2d's movers of every shape on it;
// bench/box2d_v3/mover_course.cpp runs Box2D v3's capsule mover). From left to right: a flat floor
// under a low ceiling with a platform sliding over it, 100 tiles edge to edge, a chain of 100
// segments, slopes of 10 to 70 degrees as polygons and as a chain, a staircase, and a lift that
// crushes what it carries into the ceiling over its shaft; walls at both ends. Six movers walk, jump,
// fall and slide at random at once, soft to each other. Each run races three twins of the level: as
// laid, with one box and one segment in place of the tiles and the chain, and with the tile tops
// raised by up to 1e-9. The referee judges every move with collide2d's exact contact(), the same
// for every library.
#pragma once

#include <collide2d/mover.h>
#include <collide2d/query.h>
#include <collide2d/shapes.h>
#include <collide2d/world.h>

#include "tools/random.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

namespace collide2d::testing {

constexpr double kCourseDt = 1.0 / 60, kCourseGravity = 20, kCourseJump = 6, kCourseSkin = 0.01;
constexpr double kCourseMaxSlope = std::numbers::pi / 4, kCoursePushLimit = 0.25;
constexpr int kCourseMovers = 6, kCourseIterations = 5, kCourseFrames = 10000;
constexpr std::uint64_t kCourseSoft = 2;  // the movers' category; the level's is 1

// Where the tiles lie, their tops at 0.
constexpr std::pair<double, double> kTiles{20, 45};

// How the twin lays the tiles and the chain of 100.
enum class Seams { many, one, jittered };

// What a mover stands on, in the level's terms.
enum class Part { none, level, platform, lift, mover };

struct Level {
  std::vector<Shape> statics;
  std::vector<std::vector<Vec2>> chains;  // open chains: the first and last points are ghosts
  Shape platform = Rect{Vec2::Zero(), Vec2(1.5, 0.15), 0.0};
  Shape lift = Rect{Vec2::Zero(), Vec2(2.0, 0.25), 0.0};
  Rect flat_floor{Vec2(5, -1), Vec2(15, 1), 0.0};  // the clear floor of the progress check
  static constexpr std::size_t kFlatFloor = 0;     // its index in statics

  static Vec2 platform_at(int frame) { return Vec2(-4 + 3 * std::sin(0.4 * frame * kCourseDt), 0.5); }
  // The lift's top runs from -0.5 to 2.5, half a unit under the shaft's ceiling.
  static Vec2 lift_at(int frame) { return Vec2(126, 0.75 - 1.5 * std::cos(0.6 * frame * kCourseDt)); }
};

inline std::vector<Vec2> chain_right_to_left(std::vector<Vec2> points) {  // solid side below
  std::reverse(points.begin(), points.end());
  return points;
}

// A triangle hill on the floor at x0, `height` high, its sides `degrees` steep.
inline Shape hill(double x0, double degrees, double height) {
  const double run = height / std::tan(degrees * std::numbers::pi / 180);
  const std::vector<Vec2> points{Vec2(x0, 0), Vec2(x0 + 2 * run, 0), Vec2(x0 + run, height)};
  return ConvexPolygon::of(points);
}

inline Level level(Seams seams) {
  Level l;
  l.statics = {l.flat_floor,  // first: kFlatFloor
               Rect{Vec2(-11, 5), Vec2(1, 10), 0.0},
               Rect{Vec2(129, 5), Vec2(1, 10), 0.0},      // walls
               Rect{Vec2(5, 2.15), Vec2(3, 0.25), 0.0},   // the low ceiling, 1.9 over the floor
               Rect{Vec2(81, -1), Vec2(11, 1), 0.0},      // floor under the polygon slopes
               Rect{Vec2(117, -1), Vec2(7, 1), 0.0},      // floor under the staircase
               Rect{Vec2(126, -1.5), Vec2(2, 0.5), 0.0},  // the lift shaft's bottom
               Rect{Vec2(126, 3.25), Vec2(2, 0.25), 0.0}};
  for (const auto& [x0, degrees] : {std::pair{71.0, 10.0}, {81.0, 30.0}, {85.0, 50.0}, {88.0, 70.0}})
    l.statics.push_back(hill(x0, degrees, 0.8));
  for (int k = 1; k <= 5; ++k) l.statics.push_back(Rect{Vec2(117, 0.2 * k - 0.1), Vec2(5 - 0.6 * k, 0.1), 0.0});
  if (seams == Seams::one) {
    l.statics.push_back(Rect{Vec2(32.5, -0.5), Vec2(12.5, 0.5), 0.0});
    l.chains.push_back(chain_right_to_left({Vec2(43, 0), Vec2(45, 0), Vec2(70, 0), Vec2(72, 0)}));
  } else {
    std::mt19937_64 rng(55);
    for (int i = 0; i < 100; ++i) {
      const double top = seams == Seams::jittered ? tool::uniform(rng, 0, 1e-9) : 0.0;
      l.statics.push_back(Rect{Vec2(20.125 + 0.25 * i, -0.5 + top / 2), Vec2(0.125, 0.5 + top / 2), 0.0});
    }
    std::vector<Vec2> points{Vec2(43, 0)};
    for (int i = 0; i <= 100; ++i) points.push_back(Vec2(45 + 0.25 * i, 0));
    points.push_back(Vec2(72, 0));
    l.chains.push_back(chain_right_to_left(points));
  }
  std::vector<Vec2> hills{Vec2(90, 0), Vec2(92, 0)};
  double x = 93;
  for (const double degrees : {20, 40, 60}) {
    const double run = 0.8 / std::tan(degrees * std::numbers::pi / 180);
    hills.insert(hills.end(), {Vec2(x, 0), Vec2(x + run, 0.8), Vec2(x + 2 * run, 0)});
    x += 2 * run + 3;
  }
  hills.insert(hills.end(), {Vec2(110, 0), Vec2(112, 0)});
  l.chains.push_back(chain_right_to_left(hills));
  return l;
}

// The suite's movers of every kind, about a unit tall, named.
struct CourseMover {
  const char* name;
  Shape shape;
};
inline std::vector<CourseMover> course_movers() {
  return {{"capsule", Capsule{Vec2::Zero(), 0.25, 0.25, std::numbers::pi / 2}},
          {"circle", Circle{Vec2::Zero(), 0.5}},
          {"ellipse", Ellipse{Vec2::Zero(), 0.3, 0.5, 0.0}},
          {"rect", Rect{Vec2::Zero(), Vec2(0.3, 0.5), 0.0}},
          {"polygon", ConvexPolygon::regular(6, 0.5).at(Vec2::Zero(), 0.1)},
          {"rounded_polygon", ConvexPolygon::box(0.2, 0.4, 0.1).at(Vec2::Zero())}};
}

inline std::array<Vec2, kCourseMovers> course_spawns() {
  return {Vec2(-2, 3), Vec2(15, 3), Vec2(33, 3), Vec2(57, 3), Vec2(85, 3), Vec2(117, 3)};
}

// A mover's random inputs: a walking speed held for a while (a fifth of the time none), and jumps.
class Inputs {
 public:
  explicit Inputs(std::uint64_t seed) : rng_(seed) {}
  struct Input {
    double walk = 0;
    bool jump = false;
  };
  Input next() {
    if (--hold_ <= 0) {
      hold_ = static_cast<int>(tool::uniform(rng_, 20, 120));
      walk_ = tool::uniform(rng_, 0, 1) < 0.2 ? 0.0 : tool::uniform(rng_, -6, 6);
    }
    return {walk_, tool::uniform(rng_, 0, 1) < 0.03};
  }

 private:
  std::mt19937_64 rng_;
  int hold_ = 0;
  double walk_ = 0;
};

// The velocity a game asks of its mover this frame: walking and air control, gravity, a jump from
// the ground.
inline Vec2 commanded(const Vec2& velocity, const Inputs::Input& in, bool on_ground) {
  Vec2 v(in.walk, velocity.y() - kCourseGravity * kCourseDt);
  if (in.jump && on_ground) v.y() = kCourseJump;
  return v;
}

// A mover's state after a move, as its library reports it.
struct MoverState {
  Shape shape;
  Vec2 velocity = Vec2::Zero();
  bool on_ground = false;
  Vec2 ground_normal = Vec2::UnitY();
  Part ground = Part::none;
  bool blocked = false;  // the move ended against a surface
};

// The worst of each check over a run, and how many moves each judged.
struct Verdict {
  double depth = INFINITY;  // the least separation from a solid after a move (not crushed)
  double blocked_low = INFINITY, blocked_high = -INFINITY;  // a blocked move's separation less the skin
  double seam = 0;  // the greatest distance of the laid twin from the one with one box and segment
  // Standing on the tiles, the lowest point's height less the skin: within the tops' jitter.
  double bump_low = INFINITY, bump_high = -INFINITY;
  double progress = 0;     // on the clear flat floor, |walked - commanded|
  double slide = 0;        // standing still on a slope below the max slope
  double drift = 0;        // standing still on the platform or the lift, |moved - its move|
  double soft = INFINITY;  // the least separation between two movers
  long moves = 0, blocked = 0, clear = 0, on_tiles = 0, standing = 0, riding = 0, crushed = 0, fell = 0;
};

inline double course_size(const Shape& mover) {
  const Aabb b = aabb(mover);
  return (b.max - b.min).maxCoeff();
}

inline Aabb grown(Aabb b, double by) {
  b.min -= Vec2(by, by);
  b.max += Vec2(by, by);
  return b;
}

// The checks of one twin's moves; the seam checks compare twins (compare_twins()).
class Referee {
 public:
  explicit Referee(const Level& l) : level_(l) {
    solids_ = l.statics;
    for (const auto& chain : l.chains)
      for (std::size_t i = 1; i + 2 < chain.size(); ++i) solids_.push_back(Segment::between(chain[i], chain[i + 1]));
    for (const Shape& s : solids_) boxes_.push_back(aabb(s));
  }

  // Sets the moving bodies where this frame puts them, and the displacement of this frame.
  void frame(int f) {
    platform_ = moved_to(level_.platform, Level::platform_at(f));
    lift_ = moved_to(level_.lift, Level::lift_at(f));
    platform_moved_ = Level::platform_at(f) - Level::platform_at(f - 1);
    lift_moved_ = Level::lift_at(f) - Level::lift_at(f - 1);
  }

  // Judges mover k's move from `before` with velocity `v`; true if it was crushed (excluded, and
  // the caller respawns it). `movers` holds every mover's shape now.
  bool judge(std::size_t k, const MoverState& before, const Vec2& v, const Inputs::Input& in, const MoverState& after,
             const std::vector<Shape>& movers) {
    Verdict& w = verdict;
    ++w.moves;
    const Shape& s = after.shape;
    const Vec2 start = center_of(before.shape), end = center_of(s);
    const double size = course_size(s), scale = std::max(end.cwiseAbs().maxCoeff(), size);
    const double reach = v.norm() * kCourseDt + kCourseSkin + 0.05;
    if (end.y() < -5) ++w.fell;
    Nearest near = nearest(s, reach);
    if (near.crushed) {
      ++w.crushed;
      return true;
    }
    w.depth = std::min(w.depth, near.separation);
    bool crowded = false;
    for (std::size_t j = 0; j < movers.size(); ++j) {
      if (j == k) continue;
      const double gap = contact(movers[j], s).separation;
      w.soft = std::min(w.soft, gap);
      crowded = crowded || gap < reach;
    }
    if (after.blocked && !crowded && !near.moving) {
      ++w.blocked;
      w.blocked_low = std::min(w.blocked_low, near.separation - kCourseSkin);
      w.blocked_high = std::max(w.blocked_high, near.separation - kCourseSkin);
    }
    if (after.on_ground && after.ground == Part::level && after.ground_normal == Vec2::UnitY() && !crowded &&
        aabb(s).min.x() > kTiles.first && aabb(s).max.x() < kTiles.second) {
      ++w.on_tiles;
      const double bump = support(s, Vec2(0, -1)).y() - kCourseSkin;
      w.bump_low = std::min(w.bump_low, bump);
      w.bump_high = std::max(w.bump_high, bump);
    }
    const bool still = before.on_ground && after.on_ground && in.walk == 0 && !in.jump && !crowded;
    const bool on_level = before.ground == Part::level && after.ground == Part::level;
    if (on_level && in.walk != 0 && !in.jump && !crowded && near.only_flat_floor) {
      ++w.clear;
      w.progress = std::max(w.progress, std::abs(end.x() - start.x() - in.walk * kCourseDt) / scale);
      w.progress = std::max(w.progress, std::abs(end.y() - start.y()) / scale);
    }
    if (still && !near.moving && before.ground == Part::level && before.ground_normal.y() < 1 - 1e-9 &&
        before.ground_normal.y() > std::cos(kCourseMaxSlope)) {
      ++w.standing;
      w.slide = std::max(w.slide, (end - start).norm() / scale);
    }
    // A ride the level hinders (a ceiling over the lift, a ledge it passes) is no drift.
    const bool riding = before.ground == Part::platform || before.ground == Part::lift;
    if (still && riding && after.ground == before.ground && !after.blocked && !near.level) {
      ++w.riding;
      const Vec2 carried = before.ground == Part::platform ? platform_moved_ : lift_moved_;
      w.drift = std::max(w.drift, (end - start - carried).norm() / scale);
    }
    return false;
  }

  Verdict verdict;

 private:
  struct Nearest {
    double separation = INFINITY;
    bool moving = false;          // a moving body within reach
    bool level = false;           // a level shape within reach
    bool only_flat_floor = true;  // nothing but the flat floor within reach
    bool crushed = false;
  };

  // The least separation from the solids, and what lies within `reach`; crushed where the mover
  // overlaps a solid while two within the skin, one of them moving, push it opposite ways.
  Nearest nearest(const Shape& s, double reach) const {
    Nearest n;
    const Aabb box = grown(aabb(s), reach);
    struct Touch {
      Vec2 normal;
      bool moving;
    };
    std::vector<Touch> touching;
    const auto judge_one = [&](const Shape& solid, bool moving, bool flat_floor) {
      const Contact c = contact(solid, s);
      n.separation = std::min(n.separation, c.separation);
      if (c.separation < reach) {
        n.moving = n.moving || moving;
        n.level = n.level || !moving;
        n.only_flat_floor = n.only_flat_floor && flat_floor;
      }
      if (c.separation < 2 * kCourseSkin) touching.push_back({c.normal, moving});
    };
    for (std::size_t i = 0; i < solids_.size(); ++i)
      if (intersects(boxes_[i], box)) judge_one(solids_[i], false, i == Level::kFlatFloor);
    judge_one(platform_, true, false);
    judge_one(lift_, true, false);
    for (const Touch& a : touching)
      for (const Touch& b : touching)
        n.crushed = n.crushed || ((a.moving || b.moving) && a.normal.dot(b.normal) < -0.5);
    n.crushed = n.crushed && n.separation < -1e-9;
    return n;
  }

  const Level& level_;
  std::vector<Shape> solids_;
  std::vector<Aabb> boxes_;
  Shape platform_, lift_;
  Vec2 platform_moved_ = Vec2::Zero(), lift_moved_ = Vec2::Zero();
};

// Runs the course for `frames` frames on three twins of Movers (its constructor takes the level and
// the mover's shape; place(frame) moves the platform and the lift and updates; state(k) and
// move(k, velocity) report MoverState; respawn(k, centre)), and returns the laid twin's verdict with
// the seam distance and the jittered twin's bumps.
template <class Movers>
Verdict run_course(const Shape& mover, int frames) {
  const std::array<Level, 3> levels{level(Seams::many), level(Seams::one), level(Seams::jittered)};
  std::array<Movers, 3> twins{Movers(levels[0], mover), Movers(levels[1], mover), Movers(levels[2], mover)};
  std::vector<Referee> referees(levels.begin(), levels.end());
  std::vector<Inputs> inputs;
  for (int k = 0; k < kCourseMovers; ++k) inputs.emplace_back(1000 + k);
  Verdict& v = referees[0].verdict;
  std::array<std::vector<Shape>, 3> shapes;
  for (int f = 1; f <= frames; ++f) {
    for (std::size_t t = 0; t < 3; ++t) {
      twins[t].place(f);
      referees[t].frame(f);
    }
    for (std::size_t k = 0; k < kCourseMovers; ++k) {
      const Inputs::Input in = inputs[k].next();
      bool crushed = false;
      std::array<Vec2, 3> at;
      for (std::size_t t = 0; t < 3; ++t) {
        const MoverState before = twins[t].state(k);
        const Vec2 velocity = commanded(before.velocity, in, before.on_ground);
        const MoverState after = twins[t].move(k, velocity);
        shapes[t].clear();
        for (std::size_t j = 0; j < kCourseMovers; ++j) shapes[t].push_back(twins[t].state(j).shape);
        crushed = referees[t].judge(k, before, velocity, in, after, shapes[t]) || crushed;
        at[t] = center_of(after.shape);
      }
      const double scale = std::max(at[1].cwiseAbs().maxCoeff(), course_size(mover));
      v.seam = std::max(v.seam, (at[0] - at[1]).norm() / scale);
      if (crushed)
        for (Movers& twin : twins) twin.respawn(k, course_spawns()[k]);
    }
  }
  v.bump_low = referees[2].verdict.bump_low;
  v.bump_high = referees[2].verdict.bump_high;
  v.bump_low = referees[2].verdict.bump_low;
  v.bump_high = referees[2].verdict.bump_high;
  return v;
}

// collide2d's movers on one twin of the level, each also a body the others see as soft.
class Collide2dMovers {
 public:
  Collide2dMovers(const Level& level, const Shape& mover) {
    for (const Shape& s : level.statics) world_.add(s, {.is_static = true});
    for (const auto& chain : level.chains) world_.add_chain(chain, false);
    platform_ = world_.add(moved_to(level.platform, Level::platform_at(0)));
    lift_ = world_.add(moved_to(level.lift, Level::lift_at(0)));
    for (const Vec2& at : course_spawns()) {
      states_.push_back({moved_to(mover, at)});
      bodies_.push_back(world_.add(states_.back().shape, {.filter = {.category = kCourseSoft}}));
      ground_.emplace_back();
    }
    world_.update();
  }

  void place(int frame) {
    world_.move_to(platform_, Level::platform_at(frame), 0.0);
    world_.move_to(lift_, Level::lift_at(frame), 0.0);
    world_.update();
  }

  const MoverState& state(std::size_t k) const { return states_[k]; }

  const MoverState& move(std::size_t k, const Vec2& velocity) {
    const MoverOptions options{.query = {.skin = kCourseSkin, .self = bodies_[k]},
                               .max_slope = kCourseMaxSlope,
                               .step_height = 0.25,
                               .snap_distance = 0.3,
                               .max_iterations = kCourseIterations,
                               .soft_categories = kCourseSoft,
                               .soft_push_limit = kCoursePushLimit};
    const MoveResult r = collide2d::move(world_, states_[k].shape, velocity, kCourseDt, options, ground_[k]);
    ground_[k] = r.ground;
    MoverState& s = states_[k];
    s.shape = moved_to(s.shape, r.position);
    s.velocity = r.velocity;
    s.on_ground = r.ground.on_ground;
    s.ground_normal = r.ground.normal;
    s.blocked = r.blocked;
    s.ground = !r.ground.on_ground                          ? Part::none
               : r.ground.body == platform_                 ? Part::platform
               : r.ground.body == lift_                     ? Part::lift
               : std::ranges::count(bodies_, r.ground.body) ? Part::mover
                                                            : Part::level;
    world_.move_to(bodies_[k], r.position, angle_of(s.shape));
    return s;
  }

  void respawn(std::size_t k, const Vec2& at) {
    states_[k] = {moved_to(states_[k].shape, at)};
    ground_[k] = {};
    world_.move_to(bodies_[k], at, angle_of(states_[k].shape));
  }

 private:
  World world_;
  BodyId platform_, lift_;
  std::vector<BodyId> bodies_;
  std::vector<MoverState> states_;
  std::vector<Ground> ground_;
};

}  // namespace collide2d::testing
