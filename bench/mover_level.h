// The character movers' benchmark (bench/bench_movers.cpp, bench/box2d_v3/movers.cpp): a level of
// 10,000 static shapes both libraries have (a floor, and platforms, discs and capsules, one in each
// 4 m cell of a 400 m square) and 1,000 movers that walk left or right at 3 m/s under gravity of
// 20 m/s^2, turn about every two seconds and jump when on the ground about every three, each with
// inputs of its own drawn from a seed, the same for both libraries.
#pragma once

#include <collide2d/shapes.h>
#include "tools/random.h"

#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace collide2d::bench {

inline constexpr int kLevelSide = 100;  // cells on a side
inline constexpr double kCell = 4.0;
inline constexpr int kMovers = 1000;
inline constexpr double kFrame = 1.0 / 60, kGravity = 20.0, kWalk = 3.0, kJump = 7.0;
inline constexpr int kIterations = 5;  // of collide, solve and cast, as v3's sample

// A floor under the whole level and a shape in each cell but the last: a platform (a box 2 to 3.6 m
// wide, tilted up to 0.3 rad), a disc or a capsule.
inline std::vector<Shape> mover_level() {
  std::mt19937_64 rng(31);
  std::vector<Shape> level{Rect{Vec2(0.5 * kCell * kLevelSide, -1.0), Vec2(0.5 * kCell * kLevelSide + 10, 1.0), 0.0}};
  for (int i = 0; i < kLevelSide; ++i) {
    for (int j = 0; j < kLevelSide && level.size() < kLevelSide * kLevelSide; ++j) {
      const double y = tool::uniform(rng, 1.0, 3.0), x = tool::uniform(rng, 1.0, 3.0);
      const Vec2 c(kCell * i + x, kCell * j + y);
      const double size = tool::uniform(rng, 0.0, 1.0), angle = tool::uniform(rng, -0.3, 0.3);
      switch (rng() % 3) {
        case 0:
          level.push_back(Rect{c, Vec2(1.0 + 0.8 * size, 0.2), angle});
          break;
        case 1:
          level.push_back(Circle{c, 0.3 + 0.45 * size});
          break;
        default:
          level.push_back(Capsule{c, 0.6 + 0.9 * size, 0.2, 2 * angle});
      }
    }
  }
  return level;
}

// Where each mover starts: 1.5 m over a cell's shape, the cell drawn for each mover.
inline std::vector<Vec2> mover_starts(const std::vector<Shape>& level) {
  std::mt19937_64 rng(32);
  std::vector<Vec2> starts;
  for (int k = 0; k < kMovers; ++k) {
    const std::size_t cell = 1 + rng() % (level.size() - 1);
    starts.push_back(center_of(level[cell]) + Vec2(0.0, 1.5));
  }
  return starts;
}

// A mover's input: its walking direction and when it jumps, from its own generator.
struct MoverInput {
  std::mt19937_64 rng;
  double direction = 1.0;
  explicit MoverInput(int k) : rng(static_cast<std::uint64_t>(1000 + k)) {}
  // The velocity for this frame from the last one, and whether on the ground.
  Vec2 velocity(const Vec2& last, bool on_ground) {
    if (tool::uniform(rng, 0.0, 1.0) < kFrame / 2) direction = -direction;
    Vec2 v(kWalk * direction, last.y() - kGravity * kFrame);
    if (on_ground && tool::uniform(rng, 0.0, 1.0) < kFrame / 3) v.y() = kJump;
    return v;
  }
};

}  // namespace collide2d::bench
