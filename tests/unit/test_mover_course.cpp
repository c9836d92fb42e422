// The mover suite (tests/support/mover_course.h): movers of every shape on the scripted level for
// 10,000 frames of random inputs, each frame the platform and the lift move, update(), then each
// mover's move(); every move judged with contact(). Sizes are the mover's; a relative figure is
// relative to max(|position|, size).
#include <gtest/gtest.h>

#include "mover_course.h"

#include <cstdio>
#include <string>

namespace collide2d {
namespace {

using namespace testing;

Verdict run(const Shape& mover) {
  const Verdict v = run_course<Collide2dMovers>(mover, kCourseFrames);
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

class MoverCourse : public ::testing::TestWithParam<CourseMover> {};

TEST_P(MoverCourse, KeepsEveryCheck) { expect_exact(run(GetParam().shape), course_size(GetParam().shape)); }

INSTANTIATE_TEST_SUITE_P(EveryShape, MoverCourse, ::testing::ValuesIn(course_movers()),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace collide2d
