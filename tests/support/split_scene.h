// The scene the split-World tests share (test_partition, test_distributed): about 300 bodies of
// every kind over frames with churn, bodies crossing x = -10, -7, 0, 7 and 10 back and forth, an
// ellipse wider than a region drifting across them, bodies on those boundaries, filters, sensors,
// statics (a floor longer than every region, blocks, a segment) and continuous bullets that cross
// several regions in one step. The same seed makes the same scene in every process.
#pragma once

#include <collide2d/world.h>

#include "tools/random.h"

#include <cmath>
#include <iterator>
#include <map>
#include <random>
#include <vector>

namespace collide2d::testing {

using Rng = std::mt19937_64;

using tool::uniform;
inline int pick(Rng& rng, int n) { return static_cast<int>(tool::uniform_index(rng, static_cast<std::size_t>(n))); }

inline const WorldOptions kSplitOptions{
    .fat_margin = 0.2, .proximity_margin = 0.3, .contacts = true, .speculative_margin = 0.1};

inline Shape random_shape(Rng& rng, const Vec2& c) {
  const double size = uniform(rng, 0.2, 1.2), angle = uniform(rng, -3, 3);
  switch (pick(rng, 5)) {
    case 0:
      return Circle{c, size};
    case 1:
      return Ellipse{c, size, size * uniform(rng, 0.15, 1.0), angle};
    case 2:
      return Rect{c, Vec2(size, size * uniform(rng, 0.2, 1.0)), angle};
    case 3:
      return Capsule{c, size, size * uniform(rng, 0.2, 0.6), angle};
    default:
      return ConvexPolygon::of(std::vector<Vec2>{{-size, -0.5 * size}, {size, -0.2 * size}, {0.3 * size, size}})
          .at(c, angle);
  }
}

// The whole World and what each body does from frame to frame.
struct SplitScene {
  World world{kSplitOptions};
  Rng rng{7};
  std::map<std::uint64_t, BodyId> bodies;
  std::map<std::uint64_t, Vec2> velocity;
  std::map<std::uint64_t, Pose> start;  // continuous bodies: the pose at the last update
  std::uint64_t next_id = 1;
  std::vector<std::uint64_t> added, removed;  // by the last step (added: by the constructor too)
  // A chain of level geometry zigzagging across every boundary, held apart from `bodies`.
  std::vector<Vec2> chain;
  std::uint64_t chain_id = 0;
  std::uint64_t wide = 0;  // the ellipse wider than a region, removed at the tenth step while ghosted
  int steps = 0;

  std::uint64_t add(const Shape& shape, const BodyDef& def, const Vec2& v, bool continuous = false) {
    const std::uint64_t id = next_id++;
    BodyDef d = def;
    d.user_id = id;
    const BodyId body = world.add(shape, d);
    if (continuous) {
      world.set_continuous(body);
      start[id] = pose_of(shape);
    }
    bodies[id] = body;
    velocity[id] = v;
    added.push_back(id);
    return id;
  }
  void add_random() {
    const double y = uniform(rng, -12, 12);
    const double x = uniform(rng, -22, 22);
    const Vec2 c(x, y);
    const BodyDef def{.filter = {.category = std::uint64_t{1} << pick(rng, 3),
                                 .mask = 3 + 4 * std::uint64_t(pick(rng, 2)),
                                 .group = pick(rng, 9) == 0 ? -1 : 0},
                      .sensor = pick(rng, 25) == 0};
    const double vy = uniform(rng, -0.4, 0.4);
    const double vx = uniform(rng, -0.8, 0.8);
    add(random_shape(rng, c), def, Vec2(vx, vy));
  }

  SplitScene() {
    for (int k = 0; k < 260; ++k) add_random();
    // Level geometry: a floor longer than any region, blocks, a segment across a boundary.
    add(Rect{Vec2(0, -13), Vec2(40, 0.5), 0.0}, {.is_static = true}, Vec2::Zero());
    for (int k = 0; k < 8; ++k) add(random_shape(rng, Vec2(-20 + 5.5 * k, 6)), {.is_static = true}, Vec2::Zero());
    add(Segment::between(Vec2(-3, -5), Vec2(4, -4)), {.is_static = true}, Vec2::Zero());
    for (int k = 0; k <= 12; ++k) chain.emplace_back(24.0 - 4.0 * k, k % 2 == 0 ? -10.5 : -11.5);
    chain_id = next_id++;
    world.add_chain(chain, false, {.user_id = chain_id});
    // An ellipse wider than a region, drifting across the boundaries.
    wide = add(Ellipse{Vec2(-5, 2), 14.0, 1.0, 0.1}, {}, Vec2(0.9, 0.0));
    // Bodies on the boundaries used below, their centres or left ends there.
    for (const double x : {-10.0, 0.0, 10.0, -7.0, 7.0}) {
      add(Circle{Vec2(x, -8), 0.5}, {}, Vec2::Zero());
      add(Circle{Vec2(x + 0.5, -9.25), 0.5}, {}, Vec2::Zero());
    }
    // Bullets that cross several regions in one step.
    for (int k = 0; k < 6; ++k) {
      add(Circle{Vec2(-24, -10 + 4 * k), 0.15}, {}, Vec2(k % 2 == 0 ? 16.0 : 27.0, 0.0), true);
    }
  }

  // Every moving body moves on (turning back at the scene's edges), a few are removed and as many
  // added, each continuous one's step starting where the last update left it.
  void step() {
    added.clear();
    removed.clear();
    if (++steps == 10) {
      world.remove(bodies.at(wide));
      removed.push_back(wide);
      velocity.erase(wide);
      bodies.erase(wide);
    }
    for (auto& [id, body] : bodies) {
      if (world.is_static(body)) continue;
      if (world.is_continuous(body)) start[id] = world.pose(body);
      Vec2& v = velocity[id];
      const Pose p = world.pose(body);
      if (std::abs(p.position.x() + v.x()) > 25) v.x() = -v.x();
      if (std::abs(p.position.y() + v.y()) > 13) v.y() = -v.y();
      world.move_to(body, p.position + v, p.angle + 0.05);
    }
    for (int k = 0; k < 4; ++k) {
      auto it = std::next(bodies.begin(), pick(rng, static_cast<int>(bodies.size())));
      if (world.is_static(it->second) || world.is_continuous(it->second)) continue;
      world.remove(it->second);
      removed.push_back(it->first);
      velocity.erase(it->first);
      bodies.erase(it);
      add_random();
    }
  }

  BodyRecord record(std::uint64_t id) const {
    const BodyId b = bodies.at(id);
    const auto s = start.find(id);
    return {.id = id,
            .shape = world.shape(b),
            .start = s == start.end() ? Pose{} : s->second,
            .filter = world.filter(b),
            .is_static = world.is_static(b),
            .sensor = world.is_sensor(b),
            .continuous = world.is_continuous(b)};
  }
};

}  // namespace collide2d::testing
