// The mover suite (tests/support/mover_course.h): movers of every shape on the scripted level for
// 10,000 frames of random inputs, each frame the platform and the lift move, update(), then each
// mover's move(); every move judged with contact(). Sizes are the mover's; a relative figure is
// relative to max(|position|, size).
#include <collide2d/mover.h>
#include <collide2d/world.h>

#include <gtest/gtest.h>

#include "mover_course.h"

#include <array>
#include <numbers>
#include <vector>

namespace collide2d {
namespace {

using namespace testing;

// collide2d's movers on one twin of the level, each also a body the others see as soft.
class Movers {
 public:
  Movers(const Level& level, const Shape& mover) {
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

Verdict run(const Shape& mover) {
  const Verdict v = run_course<Movers>(mover, 10000);
  std::printf("moves %ld blocked %ld clear %ld tiles %ld standing %ld riding %ld crushed %ld fell %ld\n", v.moves,
              v.blocked, v.clear, v.on_tiles, v.standing, v.riding, v.crushed, v.fell);
  std::printf("depth %.3g band [%.3g, %.3g] seam %.3g bump [%.3g %.3g] progress %.3g slide %.3g drift %.3g soft %.3g\n",
              v.depth, v.blocked_low, v.blocked_high, v.seam, v.bump_low, v.bump_high, v.progress, v.slide, v.drift,
              v.soft);
  return v;
}

void expect_exact(const Verdict& v, double size) {
  for (const long judged : {v.blocked, v.clear, v.on_tiles, v.standing, v.riding}) EXPECT_GT(judged, 100);
  EXPECT_GT(v.crushed, 0);  // the lift crushes, and the crushed frames are told apart
  EXPECT_EQ(v.fell, 0);
  EXPECT_GE(v.depth, -1e-9 * size);
  EXPECT_GE(v.blocked_low, -1e-9 * size);
  EXPECT_LE(v.blocked_high, 1e-9 * size);
  EXPECT_LE(v.seam, 1e-12);
  EXPECT_GE(v.bump_low, -1e-12);
  EXPECT_LE(v.bump_high, 1e-9 + 1e-12);
  EXPECT_LE(v.progress, 1e-12);
  EXPECT_LE(v.slide, 2e-12);  // the floor's lift stops within 1e-12 of the centre's magnitude
  EXPECT_LE(v.drift, 1e-12);
  EXPECT_GE(v.soft, -size / 2);  // never halfway into each other
}

TEST(MoverCourse, Capsule) { expect_exact(run(Capsule{Vec2::Zero(), 0.25, 0.25, std::numbers::pi / 2}), 1.0); }
TEST(MoverCourse, Circle) { expect_exact(run(Circle{Vec2::Zero(), 0.5}), 1.0); }
TEST(MoverCourse, Ellipse) { expect_exact(run(Ellipse{Vec2::Zero(), 0.3, 0.5, 0.0}), 1.0); }
TEST(MoverCourse, Rect) { expect_exact(run(Rect{Vec2::Zero(), Vec2(0.3, 0.5), 0.0}), 1.0); }
TEST(MoverCourse, Polygon) { expect_exact(run(ConvexPolygon::regular(6, 0.5).at(Vec2::Zero(), 0.1)), 1.0); }
TEST(MoverCourse, RoundedPolygon) { expect_exact(run(ConvexPolygon::box(0.2, 0.4, 0.1).at(Vec2::Zero())), 1.0); }

}  // namespace
}  // namespace collide2d
