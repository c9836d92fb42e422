// The World benchmarks' moving bodies (bench/bench_world.cpp, bench/box2d_v3/world.cpp): the same
// shapes, poses and motion for collide2d and each rival.
#pragma once

#include <collide2d/shapes.h>
#include "tools/random.h"

#include <cmath>
#include <cstddef>
#include <numbers>
#include <random>
#include <vector>

namespace collide2d::bench {

// A number in [0, 1), the same with every standard library (tools/random.h).
inline double unit(std::mt19937_64& rng) { return tool::uniform(rng, 0.0, 1.0); }

// A point of the square [0, side)^2 from `corner`, y drawn before x (one draw a statement: a call's
// arguments are evaluated in an order the compiler picks).
inline Vec2 point_in(std::mt19937_64& rng, const Vec2& corner, double side) {
  const double y = unit(rng) * side;
  const double x = unit(rng) * side;
  return corner + Vec2(x, y);
}

inline Shape random_shape(std::mt19937_64& rng, const Vec2& c) {
  const double half = 0.3 + 1.7 * unit(rng), angle = 2 * std::numbers::pi * unit(rng);
  switch (rng() % 3) {
    case 0:
      return Circle{c, half};
    case 1:
      return Ellipse{c, half, half * (0.2 + 0.8 * unit(rng)), angle};
    default:
      return Rect{c, Vec2(half, half * (0.2 + 0.8 * unit(rng))), angle};
  }
}

// The moving bodies: n shapes in a square of side sqrt(28 n) (8% covered) from `corner`, and each
// frame their poses, moved up to 0.1 and turned up to 0.025 rad either way, bouncing off the sides.
struct Movers {
  std::vector<Shape> shapes;
  std::vector<Vec2> centre;
  std::vector<double> angle;
  std::vector<Vec2> velocity;
  double side;
  Vec2 corner;

  Movers(int n, const Vec2& from, std::mt19937_64& rng) : side(std::sqrt(28.0 * n)), corner(from) {
    for (int k = 0; k < n; ++k) {
      shapes.push_back(random_shape(rng, point_in(rng, corner, side)));
      centre.push_back(center_of(shapes.back()));
      angle.push_back(angle_of(shapes.back()));
      velocity.push_back(0.2 * (point_in(rng, Vec2::Zero(), 1.0) - Vec2::Constant(0.5)));
    }
  }
  void step(std::mt19937_64& rng) {
    for (std::size_t k = 0; k < centre.size(); ++k) {
      const Vec2 at = centre[k] - corner;
      for (int a = 0; a < 2; ++a) {
        if ((at[a] < 0 && velocity[k][a] < 0) || (at[a] > side && velocity[k][a] > 0)) velocity[k][a] *= -1;
      }
      centre[k] += velocity[k];
      angle[k] += tool::uniform(rng, -0.025, 0.025);
    }
  }
  std::size_t heap() const {
    return shapes.capacity() * sizeof(Shape) + centre.capacity() * sizeof(Vec2) + angle.capacity() * sizeof(double) +
           velocity.capacity() * sizeof(Vec2);
  }
};

}  // namespace collide2d::bench
