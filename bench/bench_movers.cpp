// Character movers (bench/mover_level.h): 1,000 movers, one move() each a frame, in a level of
// 10,000 static shapes, the movers not in the World and not seeing each other; one thread. A
// capsule crowd, against Box2D v3's mover loop on the same level (bench/box2d_v3/movers.cpp, where
// a v3 source is given), and an ellipse crowd, which v3 cannot move. The time is a frame's (1,000
// moves) after 60 frames in which the movers land.
#include <collide2d/collide2d.h>

#include "bench/mover_course.h"
#include "bench/mover_level.h"

#include <benchmark/benchmark.h>

#include <numbers>
#include <string>
#include <vector>

namespace collide2d {
namespace {

using namespace bench;

struct Crowd {
  World world;
  std::vector<Shape> shapes;
  std::vector<Vec2> velocity;
  std::vector<Ground> ground;
  std::vector<MoverInput> input;
  int iterations = 0;

  explicit Crowd(const Shape& mover) {
    const std::vector<Shape> level = mover_level();
    for (const Shape& s : level) world.add(s, {.is_static = true});
    world.update();
    for (const Vec2& c : mover_starts(level)) {
      shapes.push_back(moved_to(mover, c));
      input.emplace_back(static_cast<int>(input.size()));
    }
    velocity.assign(shapes.size(), Vec2::Zero());
    ground.assign(shapes.size(), Ground{});
  }
  void frame() {
    for (std::size_t k = 0; k < shapes.size(); ++k) {
      velocity[k] = input[k].velocity(velocity[k], ground[k].on_ground);
      const MoveResult r = move(world, shapes[k], velocity[k], kFrame, {.max_iterations = kIterations}, ground[k]);
      shapes[k] = moved_to(shapes[k], r.position);
      velocity[k] = r.velocity;
      ground[k] = r.ground;
      iterations += r.iterations;
    }
  }
};

void run(benchmark::State& state, const Shape& mover) {
  Crowd crowd(mover);
  for (int k = 0; k < 60; ++k) crowd.frame();
  crowd.iterations = 0;
  double on_ground = 0.0;
  for (auto _ : state) {
    crowd.frame();
    for (const Ground& g : crowd.ground) on_ground += g.on_ground;
  }
  const double moves = static_cast<double>(state.iterations()) * kMovers;
  state.counters["iterations_per_move"] = crowd.iterations / moves;
  state.counters["on_ground"] = on_ground / moves;
}

const Shape kCapsule = Capsule{Vec2::Zero(), 0.3, 0.3, std::numbers::pi / 2};
const Shape kEllipse = Ellipse{Vec2::Zero(), 0.3, 0.6, 0.0};

// The mover suite once: its worst values as counters.
void course(benchmark::State& state, const Shape& mover) {
  for (auto _ : state)
    report_verdict(state, testing::run_course<testing::Collide2dMovers>(mover, testing::kCourseFrames));
}

const bool kCourseRegistered = [] {
  for (const testing::CourseMover& m : testing::course_movers())
    benchmark::RegisterBenchmark((std::string("mover_course/") + m.name + "/collide2d").c_str(), course, m.shape)
        ->Iterations(1)
        ->Repetitions(1);
  return true;
}();

BENCHMARK_CAPTURE(run, capsule, kCapsule)->Name("movers/capsule/collide2d")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, ellipse, kEllipse)->Name("movers/ellipse/collide2d")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace collide2d

BENCHMARK_MAIN();
