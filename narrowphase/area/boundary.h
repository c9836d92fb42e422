// Private: a convex solid's boundary as a closed loop of edges and arcs, for the area kernels.
//
// Every arc is the image of a unit-circle arc under an affine map, p = c + M u with |u| = 1 (M a
// rotation times diag(a, b): a circle's M is r I), run counter-clockwise from u0 to u1. Points are
// relative to an origin near the pair (the first shape's centre), so that far from the world's
// origin the geometry keeps the digits of its own size.
#pragma once

#include <collide2d/shapes.h>

#include <Eigen/Core>

#include <array>

namespace collide2d::detail::areas {

// The pieces and crossings below have no default member values, so that a boundary's room for a
// rounded octagon's 16 pieces is not written for a curve that uses one: each piece is set whole
// where it is made.
struct Arc {
  Vec2 c;
  Eigen::Matrix2d m;
  Eigen::Matrix2d inverse;  // of m
  double det;               // of m: a b, or r^2
  Vec2 u0;
  Vec2 u1;
  bool full;  // the whole ellipse, from u0 round to u0
  bool circular;

  Vec2 point(const Vec2& u) const { return c + m * u; }
  // The unit vector of a point on (or near) the curve.
  Vec2 unit(const Vec2& p) const;
  // The counter-clockwise tangent at u (not unit).
  Vec2 tangent(const Vec2& u) const { return m * Vec2(-u.y(), u.x()); }
};

// A point where a piece starts or ends, with its unit vector when the piece is an arc.
struct End {
  Vec2 p;
  Vec2 u;  // UnitX on an edge
};

// Piece k runs from start to the next piece's start, straight or along its arc.
struct Piece {
  End start;
  End end;
  bool curved;
  Arc arc;  // on an edge, unset
};

// At most a rounded octagon's 8 edges and 8 arcs.
inline constexpr int kMaxPieces = 2 * kMaxPolygonVertices;

struct Boundary {
  std::array<Piece, kMaxPieces> pieces;  // the first `count` set
  int count = 0;
  bool polygonal = true;  // edges only
};

// The boundary of a solid shape (not a segment), relative to `origin`.
Boundary boundary_of(const Shape& s, const Vec2& origin);

// A monotone stand-in for the counter-clockwise angle from u0 to u (both unit), in [0, 4): the
// position of a point along an arc, cheaper than the angle and ordered as it is.
double turn_key(const Vec2& u0, const Vec2& u);

}  // namespace collide2d::detail::areas
