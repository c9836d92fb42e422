// Private: the points where two convex boundaries cross, each with its place on both loops.
#pragma once

#include "narrowphase/area/boundary.h"
#include "shapes/internal.h"

#include <array>

namespace collide2d::detail::areas {

// A crossing's place on one loop: the piece, the position along it (the edge's parameter in
// [0, 1), or turn_key() from the arc's start), and the unit vector there when the piece is an arc.
struct Place {
  int piece;
  double key;
  Vec2 u;  // UnitX on an edge
};

// Set whole where it is found (no default member values: see boundary.h's Arc).
struct Crossing {
  Vec2 p;
  Place a;
  Place b;
  // The sine of the angle from B's tangent to A's: positive where A's boundary enters B.
  double entering;
};

// Two convex curves cross at most 4 times per pair of conics; the pieces of two rounded octagons
// cross at most 2 per edge pair, and in total as many times as the two loops have pieces.
inline constexpr int kMaxCrossings = 2 * kMaxPieces;

struct Crossings {
  std::array<Crossing, kMaxCrossings> list;  // the first `count` set
  int count = 0;
};

// Each crossing once: an edge owns its start and not its end, an arc its u0 and not its u1.
Crossings crossings_of(const Boundary& a, const Boundary& b);

// A crossing on the double-double boundaries of the same two shapes, as an end on each.
struct ExtendedCrossing {
  EndOf<DoubleDouble> a;
  EndOf<DoubleDouble> b;
};

// The crossing x, found in double on the same shapes' double boundaries, refined by Newton's method
// on the two pieces' curve equations, so that near-identical curves, which cross at a small angle
// and leave a double crossing far off along them, meet to double-double's digits; false where
// the iteration does not settle near x.
bool refined(const BoundaryOf<DoubleDouble>& a, const BoundaryOf<DoubleDouble>& b, const Crossing& x,
             ExtendedCrossing& out);

}  // namespace collide2d::detail::areas
