// The mover's cast of one pair, cast_mover(): on constructions whose answer is exact (a circle
// falling onto a floor, sliding at the skin, leaving a surface it starts inside, a box sliding over
// boxes edge to edge), and on random pairs of every mover kind against every target kind, against
// bisection on the exact separation of contact() for the first time it falls below the floor.
#include <collide2d/mover.h>
#include <collide2d/query.h>
#include <collide2d/time_of_impact.h>

#include <gtest/gtest.h>

#include "mover_testing.h"
#include "refusals.h"
#include "tools/random.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace collide2d {
namespace {

using testing::expect_refused;
using testing::random_kind;
using tool::uniform;
using Rng = std::mt19937_64;

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// The floor of mover.h's contract.
double floor_of(const Shape& mover, const Shape& target, double skin) {
  const double hair = 1e-12 * std::max(reach_of(mover), center_of(mover).cwiseAbs().maxCoeff());
  return std::min(contact(target, mover).separation, skin) - hair;
}

double separation_at(const Shape& mover, const Vec2& translation, const Shape& target, double t) {
  return contact(target, at_time(mover, {translation, 0.0}, t)).separation;
}

TEST(MoverCast, FallsOntoAFloorAndStopsAtTheSkin) {
  const Shape floor = Rect{Vec2(0, -1), Vec2(10, 1), 0.0};  // top face at y = 0
  const Shape ball = Circle{Vec2(0.25, 2.0), 0.5};
  const double skin = 0.01;
  const double f = cast_mover(ball, Vec2(0, -3), floor, skin);
  // The centre stops at 0.5 + skin above the top, within the cast's stop of 1e-9 of the reach.
  EXPECT_NEAR(2.0 - 3 * f, 0.51, 1e-9 * 0.5 + 1e-15);
  EXPECT_GE(2.0 - 3 * f, 0.51 - 2e-12 - 1e-15);  // the hair: 1e-12 of the centre's height
}

TEST(MoverCast, SlidesAtTheSkinAndLeavesFreely) {
  const Shape floor = Rect{Vec2(0, -1), Vec2(10, 1), 0.0};
  const double skin = 0.01;
  const Shape resting = Circle{Vec2(-3, 0.51), 0.5};
  EXPECT_EQ(cast_mover(resting, Vec2(6, 0), floor, skin), 1.0);
  EXPECT_EQ(cast_mover(resting, Vec2(6, 1), floor, skin), 1.0);
  // Down by far less than the hair below the skin: still free.
  EXPECT_EQ(cast_mover(resting, Vec2(6, -1e-14), floor, skin), 1.0);
  // Down by more: it stops where it has gone the hair deeper.
  const double f = cast_mover(resting, Vec2(0, -1e-9), floor, skin);
  EXPECT_LT(f, 1.0);
  EXPECT_LE(f * 1e-9, 1e-12 * 3 + 1e-9 * 0.5);
}

TEST(MoverCast, StartingInsideMovesAlongAndAwayButNotDeeper) {
  const Shape floor = Rect{Vec2(0, -1), Vec2(10, 1), 0.0};
  const Shape sunk = Circle{Vec2(0, 0.4), 0.5};  // 0.1 deep
  EXPECT_EQ(cast_mover(sunk, Vec2(3, 0), floor, 0.01), 1.0);
  EXPECT_EQ(cast_mover(sunk, Vec2(-3, 0.2), floor, 0.01), 1.0);
  EXPECT_LE(cast_mover(sunk, Vec2(0, -0.2), floor, 0.01) * 0.2, 1e-9 * 0.5 + 1e-12);
}

// Boxes edge to edge as a tile floor: a box sliding over them at the skin never stops on a seam,
// wherever the seam falls under it; a tile 1e-9 higher stops it within its skin.
TEST(MoverCast, NeverStopsOnTheSeamBetweenTiles) {
  const double skin = 0.01;
  Rng rng(5);
  for (int k = 0; k < 2000; ++k) {
    const double seam = uniform(rng, -2, 2), rise = k % 2 == 0 ? 0.0 : 1e-9;
    const Shape tile = Rect{Vec2(seam + 0.5, -0.5 + rise), Vec2(0.5, 0.5), 0.0};  // right of the seam
    const Shape box = Rect{Vec2(seam - 0.3 - uniform(rng, 0.0, 1.0), 0.25 + skin), Vec2(0.3, 0.25), 0.0};
    const Vec2 move(uniform(rng, 1.5, 3.0), 0.0);  // reaches the tile
    const double f = cast_mover(box, move, tile, skin);
    if (rise == 0.0) {
      ASSERT_EQ(f, 1.0) << k;
      continue;
    }
    const double s = separation_at(box, move, tile, f);
    ASSERT_LT(f, 1.0) << k;
    ASSERT_GE(s, floor_of(box, tile, skin) - 64 * kU * 4) << k;
    ASSERT_LE(s, skin + 1e-9 * 0.4) << k;
  }
}

// The first time the separation falls below the floor, by bisection on contact(): the separation
// is convex in the fraction, so it stays at or above the floor on [0, t] and below it after.
double first_below(const Shape& mover, const Vec2& move, const Shape& target, double floor) {
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 80; ++k) {
    const double mid = (lo + hi) / 2;
    (separation_at(mover, move, target, mid) >= floor ? lo : hi) = mid;
  }
  return hi;
}

TEST(MoverCast, RandomPairsOfEveryKindAgainstBisection) {
  Rng rng(11);
  int stopped = 0, inside = 0;
  for (int k = 0; k < 6000; ++k) {
    const int mover_kind = k % 6, target_kind = (k / 6) % 7;
    const Shape target = random_kind(rng, target_kind, Vec2(uniform(rng, -5, 5), uniform(rng, -5, 5)), 1.0);
    const Shape mover =
        random_kind(rng, mover_kind, center_of(target) + tool::uniform_point(rng, -3, 3), uniform(rng, 0.2, 0.8));
    // Half the moves head for the target.
    const Vec2 move = k % 2 == 0 ? tool::uniform_point(rng, -4, 4)
                                 : Vec2(uniform(rng, 0.5, 2.0) * (center_of(target) - center_of(mover)));
    const double skin = uniform(rng, 0.0, 0.1);
    const double f = cast_mover(mover, move, target, skin);
    const double floor = floor_of(mover, target, skin);
    const double scale = center_of(mover).cwiseAbs().maxCoeff() + center_of(target).cwiseAbs().maxCoeff() + 8;
    const double slack = 64 * kU * scale, stop = 1e-9 * reach_of(mover);
    const std::string what =
        std::to_string(k) + " kinds " + std::to_string(mover_kind) + "-" + std::to_string(target_kind);
    ASSERT_GE(f, 0.0) << what;
    ASSERT_LE(f, 1.0) << what;
    const double s = separation_at(mover, move, target, f);
    ASSERT_GE(s, floor - slack) << what;  // never past the floor
    if (f < 1.0) ASSERT_LE(s, floor + stop + slack) << what;
    if (separation_at(mover, move, target, 1.0) < floor - slack) {
      const double t = first_below(mover, move, target, floor);
      ASSERT_LE(f, t + 1e-12) << what;  // the first time, to the rounding of the separation
      ++stopped;
    }
    inside += contact(target, mover).separation < 0;
  }
  // The draw covers both outcomes and movers starting inside their target.
  EXPECT_GT(stopped, 2000);
  EXPECT_GT(inside, 200);
}

TEST(MoverCast, RefusesBadInput) {
  const Shape floor = Rect{Vec2(0, -1), Vec2(10, 1), 0.0};
  const Shape ball = Circle{Vec2(0, 2), 0.5};
  expect_refused<InvalidShape>([&] { cast_mover(ball, Vec2(kNan, 0), floor, 0.01); }, "translation x must be finite");
  expect_refused<InvalidShape>([&] { cast_mover(ball, Vec2(0, INFINITY), floor, 0.01); },
                               "translation y must be finite");
  expect_refused<InvalidShape>([&] { cast_mover(ball, Vec2(0, 1), floor, -0.5); }, "skin");
  expect_refused<InvalidShape>([&] { cast_mover(ball, Vec2(0, 1), floor, INFINITY); }, "skin");
  expect_refused<InvalidShape>([&] { cast_mover(Circle{Vec2(0, 0), -1.0}, Vec2(0, 1), floor, 0.01); }, "radius");
}

}  // namespace
}  // namespace collide2d
