// A game's own header, named as one of collide2d's private headers once was.
#pragma once
#define GAME_WORLD_H 1
namespace game {
struct World {
  int level = 1;
};
}  // namespace game
