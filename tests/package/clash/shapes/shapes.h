// A game's own header, named as one of collide2d's private headers once was.
#pragma once
#define GAME_SHAPES_H 1
namespace game {
struct Aabb {
  int left, top, right, bottom;
};
}  // namespace game
