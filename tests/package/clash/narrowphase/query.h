// A game's own header, named as one of collide2d's private headers once was.
#pragma once
#define GAME_QUERY_H 1
namespace game {
inline int query() { return 42; }
}  // namespace game
