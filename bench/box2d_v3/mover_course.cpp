// The mover suite (tests/support/mover_course.h) on Box2D v3's capsule mover, beside collide2d's
// movers, in bench_movers where a v3 source is given: each run is the suite's 10,000 frames once,
// its worst values the counters (the docs' table of checks). v3's game is its geometric mover
// sample's: a ray down from the capsule's lower centre (the pogo) finds the ground, a spring holds
// the capsule at its rest length over it (here 0.1 m over the capsule's bottom, kPogoClearance) and
// no gravity pulls while it is on the ground; then the sample's loop (bench/box2d_v3/mover_loop.h;
// its casts past the other movers, whose planes are soft: the push limit, no clip) and
// b2ClipVector. The suite's
// game adds the walk, the jump and the carry of the platform or lift the pogo stands on.
#include "bench/mover_course.h"
#include "bench/box2d_v3/bodies.h"
#include "bench/box2d_v3/mover_loop.h"

#include <box2d/box2d.h>
#include <box2d/collision.h>

#include <benchmark/benchmark.h>

#include <cfloat>
#include <cmath>
#include <numbers>
#include <vector>

namespace collide2d {
namespace {

using namespace testing;
using bench::report_verdict;

constexpr float kPogoHertz = 5.0f, kPogoDamping = 0.8f;  // as the sample's
// How far the pogo holds the capsule over the ground (the sample's 0.6 m): near standing on it,
// yet clear of it after a landing; a capsule that ends within v3's linear slop of a floor sticks
// there, its casts along the floor stopping at once.
constexpr double kPogoClearance = 0.1;

class V3Movers {
 public:
  V3Movers(const Level& level, const Shape& mover) : capsule_(std::get<Capsule>(mover)) {
    b2WorldDef def = b2DefaultWorldDef();
    def.gravity = b2Vec2{0.0f, 0.0f};
    def.workerCount = 1;
    world_ = b2CreateWorld(&def);
    for (const Shape& s : level.statics) box2d_v3::add_body(world_, s, b2_staticBody);
    for (const auto& chain : level.chains) add_chain(chain);
    platform_ = box2d_v3::add_body(world_, moved_to(level.platform, Level::platform_at(0)), b2_kinematicBody);
    lift_ = box2d_v3::add_body(world_, moved_to(level.lift, Level::lift_at(0)), b2_kinematicBody);
    for (const Vec2& at : course_spawns()) {
      states_.push_back({moved_to(mover, at)});
      bodies_.push_back(box2d_v3::add_body(world_, states_.back().shape, b2_kinematicBody, {.category = kCourseSoft}));
    }
    pogo_velocity_.assign(bodies_.size(), 0.0f);
  }
  ~V3Movers() { b2DestroyWorld(world_); }
  V3Movers(const V3Movers&) = delete;
  V3Movers& operator=(const V3Movers&) = delete;

  void place(int frame) {
    b2Body_SetTransform(platform_, box2d_v3::to_float(Level::platform_at(frame)), b2Rot_identity);
    b2Body_SetTransform(lift_, box2d_v3::to_float(Level::lift_at(frame)), b2Rot_identity);
    frame_ = frame;
  }

  const MoverState& state(std::size_t k) const { return states_[k]; }

  const MoverState& move(std::size_t k, const Vec2& commanded) {
    MoverState& s = states_[k];
    self_ = bodies_[k];
    b2Vec2 at = box2d_v3::to_float(center_of(s.shape));
    b2Vec2 velocity = box2d_v3::to_float(commanded);
    const bool jumped = commanded.y() == kCourseJump;
    pogo(s, at, jumped);
    if (s.on_ground) velocity.y = 0.0f;
    const Vec2 carry = s.ground == Part::platform ? Vec2(Level::platform_at(frame_) - Level::platform_at(frame_ - 1))
                       : s.ground == Part::lift   ? Vec2(Level::lift_at(frame_) - Level::lift_at(frame_ - 1))
                                                  : Vec2(Vec2::Zero());
    const b2Vec2 rise{0.0f, static_cast<float>(kCourseDt) * pogo_velocity_[k]};
    const b2Vec2 target =
        b2Add(b2Add(at, b2MulSV(static_cast<float>(kCourseDt), velocity)), b2Add(rise, box2d_v3::to_float(carry)));
    const b2QueryFilter filter = b2DefaultQueryFilter();
    const b2QueryFilter cast_filter{filter.categoryBits, filter.maskBits & ~kCourseSoft};
    const auto half = static_cast<float>(capsule_.half_length), radius = static_cast<float>(capsule_.radius);
    const float fraction = box2d_v3::mover_loop(world_, at, target, half, radius, filter, cast_filter, keep_plane, this,
                                                planes_, kCourseIterations)
                               .fraction;
    const b2Vec2 v = b2ClipVector(velocity, planes_.planes.data(), planes_.count);
    s.shape = moved_to(s.shape, Vec2(at.x, at.y));
    s.velocity = Vec2(v.x, v.y);
    s.blocked = fraction < 1.0f;
    b2Body_SetTransform(bodies_[k], at, b2Body_GetRotation(bodies_[k]));
    return s;
  }

  void respawn(std::size_t k, const Vec2& at) {
    states_[k] = {moved_to(states_[k].shape, at)};
    pogo_velocity_[k] = 0.0f;
    b2Body_SetTransform(bodies_[k], box2d_v3::to_float(at), b2Body_GetRotation(bodies_[k]));
  }

 private:
  void add_chain(const std::vector<Vec2>& points) {
    b2BodyDef body = b2DefaultBodyDef();
    const b2BodyId id = b2CreateBody(world_, &body);
    std::vector<b2Vec2> floats;
    for (const Vec2& p : points) floats.push_back(box2d_v3::to_float(p));
    b2ChainDef def = b2DefaultChainDef();
    def.points = floats.data();
    def.count = static_cast<int>(floats.size());
    b2CreateChain(id, &def);
  }

  static bool keep_plane(b2ShapeId shape, const b2PlaneResult* result, void* context) {
    auto* m = static_cast<V3Movers*>(context);
    const b2BodyId body = b2Shape_GetBody(shape);
    if (!result->hit || B2_ID_EQUALS(body, m->self_)) return true;
    const bool soft = b2Shape_GetFilter(shape).categoryBits == kCourseSoft;
    m->planes_.add({result->plane, soft ? static_cast<float>(kCoursePushLimit) : FLT_MAX, 0.0f, !soft});
    return true;
  }

  Part part_of(b2BodyId body) const {
    if (B2_ID_EQUALS(body, platform_)) return Part::platform;
    if (B2_ID_EQUALS(body, lift_)) return Part::lift;
    for (const b2BodyId& b : bodies_)
      if (B2_ID_EQUALS(body, b)) return Part::mover;
    return Part::level;
  }

  // The sample's pogo: the ground the ray down from the capsule's lower centre meets within the
  // rest length (twice that while on the ground, to follow it down), and the spring's velocity.
  void pogo(MoverState& s, const b2Vec2& at, bool jumped) {
    const float rest = static_cast<float>(capsule_.radius + kPogoClearance);
    const float length = s.on_ground ? 2.0f * rest : rest;
    const b2Vec2 origin{at.x, at.y - static_cast<float>(capsule_.half_length)};
    hit_ = {};
    b2World_CastRay(world_, origin, b2Vec2{0.0f, -length}, b2DefaultQueryFilter(), keep_hit, this);
    const bool ground = hit_.hit && hit_.normal.y > std::cos(kCourseMaxSlope);
    s.on_ground = !jumped && (s.on_ground ? ground : ground && s.velocity.y() <= 0.01);
    float& spring = pogo_velocity_[&s - states_.data()];
    if (!s.on_ground) {
      s.ground = Part::none;
      spring = 0.0f;
      return;
    }
    s.ground = part_of(hit_.body);
    s.ground_normal = Vec2(hit_.normal.x, hit_.normal.y);
    spring =
        b2SpringDamper(kPogoHertz, kPogoDamping, hit_.fraction * length - rest, spring, static_cast<float>(kCourseDt));
  }

  struct Hit {
    b2Vec2 normal{};
    b2BodyId body{};
    float fraction = 1.0f;
    bool hit = false;
  };

  // The nearest hit of the ray past the mover's own body.
  static float keep_hit(b2ShapeId shape, b2Pos, b2Vec2 normal, float fraction, void* context) {
    auto* m = static_cast<V3Movers*>(context);
    const b2BodyId body = b2Shape_GetBody(shape);
    if (B2_ID_EQUALS(body, m->self_)) return -1.0f;
    m->hit_ = {normal, body, fraction, true};
    return fraction;
  }

  Capsule capsule_;
  b2WorldId world_;
  b2BodyId platform_, lift_, self_{};
  std::vector<b2BodyId> bodies_;
  std::vector<MoverState> states_;
  box2d_v3::MoverPlanes planes_;
  std::vector<float> pogo_velocity_;
  Hit hit_;
  int frame_ = 0;
};

const Shape kCapsule = Capsule{Vec2::Zero(), 0.25, 0.25, std::numbers::pi / 2};

void box2d_v3_course(benchmark::State& state) {
  for (auto _ : state) report_verdict(state, run_course<V3Movers>(kCapsule, kCourseFrames));
}

BENCHMARK(box2d_v3_course)->Name("mover_course/capsule/box2d_v3")->Iterations(1)->Repetitions(1);

}  // namespace
}  // namespace collide2d
