// A game with headers of its own named shapes/shapes.h, engine/world.h and narrowphase/query.h,
// built against the installed collide2d: each name reaches the game's header, and collide2d's
// headers reach only their own.
#include "engine/world.h"
#include "narrowphase/query.h"
#include "shapes/shapes.h"

#include <collide2d/collide2d.h>

#include <cstdio>

static_assert(GAME_SHAPES_H && GAME_WORLD_H && GAME_QUERY_H, "the game's own headers");

int main() {
  const game::Aabb screen{0, 0, 640, 480};
  const game::World level;
  collide2d::World world;
  world.add(collide2d::Circle{collide2d::Vec2(0, 0), 1.0});
  world.add(collide2d::Circle{collide2d::Vec2(1.5, 0), 1.0});
  world.update();
  std::printf("%d %d %d %zu\n", screen.right, level.level, game::query(), world.overlapping().size());
  return world.overlapping().size() == 1 ? 0 : 1;
}
